#include "core/segmentation/csmp_segmentation.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

#include "core/segmentation/neighbor_equality.hpp"
#include "core/segmentation/region_merge_queue.hpp"
#include "core/segmentation/tiny_patch_folding.hpp"

namespace cosmos {
namespace {

// The post-processing of §3.5.2: a curved boundary pixel moves to the adjacent curved patch
// whose mean shape index is nearer its own, so boundaries settle where the shape index is
// halfway between the patches instead of where growing happened to stop. Each pass reads the
// labels of the previous one only (the result does not depend on the scan order) and looks
// only at pixels next to the previous pass's moves.
// `area` and `shape_area` are per patch, over its curved pixels.
void refine_boundaries(const ShapeIndexField& field, const std::vector<double>& area,
                       const std::vector<double>& shape_area, CsmpSegmentation& segmentation,
                       int passes) {
  auto& patch = segmentation.patch_of_pixel;
  // Mean S_I per patch, shifted by one: entry 0 stands for "not a curved patch", a neighbour
  // no pixel moves to, so the neighbour loop below needs no branch.
  std::vector<double> mean_of(segmentation.patch_count + 1, kPlanarShapeIndex);
  mean_of[0] = std::numeric_limits<double>::infinity();
  for (int p = 0; p < segmentation.patch_count; ++p)
    if (area[p] > 0) mean_of[p + 1] = shape_area[p] / area[p];
  // The patch of each curved pixel, kNoPatch elsewhere: only curved pixels move, and only
  // into curved patches.
  std::vector<std::int32_t> curved_patch(patch.size());
  for (std::size_t i = 0; i < patch.size(); ++i)
    curved_patch[i] = field.label[i] == SurfaceLabel::kCurved ? patch[i] : kNoPatch;
  const int width = patch.width();
  std::ptrdiff_t step[8];
  for (int k = 0; k < 8; ++k)
    step[k] = kNeighborOffsets[k].row * width + kNeighborOffsets[k].column;
  std::vector<std::pair<std::size_t, std::int32_t>> moves;
  auto consider = [&](std::size_t i) {
    const std::int32_t own = curved_patch[i];
    if (own == kNoPatch) return;
    const double s = field.shape_index[i];
    double best_distance = std::abs(s - mean_of[own + 1]);
    std::int32_t best = own;
    const std::uint8_t side = field.same_side[i];
    for (int k = 0; k < 8; ++k) {
      // Same-side bits are only set for neighbours inside the image; a neighbour without one
      // reads the pixel itself, which is never nearer than itself.
      const std::size_t j = ((side >> k) & 1u) ? i + step[k] : i;
      const std::int32_t other = curved_patch[j];
      const double distance = std::abs(s - mean_of[other + 1]);
      const bool nearer = distance < best_distance;
      best_distance = nearer ? distance : best_distance;
      best = nearer ? other : best;
    }
    if (best != own) moves.emplace_back(i, best);
  };
  // A pixel whose eight neighbours all share its patch cannot move: the first pass finds the
  // others row by row (a pixel on the image border always counts as a boundary pixel).
  std::vector<std::uint8_t> equal(width);
  std::vector<std::int32_t> boundary_columns(width);
  std::vector<std::size_t> candidates;
  std::vector<int> stamp;
  stamp.assign(patch.size(), -1);
  // Moves are decided on the previous pass's labels, so the order of the candidates is free.
  for (int pass = 0; pass < passes; ++pass) {
    moves.clear();
    if (pass == 0) {
      for (int row = 0; row < patch.height(); ++row) {
        equal_neighbors_of_row<8>(patch.data(), width, patch.height(), row, equal.data());
        const int listed =
            columns_with_mask_other_than(equal.data(), width, 0xFFu, boundary_columns.data());
        for (int n = 0; n < listed; ++n) consider(patch.index(boundary_columns[n], row));
      }
    } else {
      if (candidates.empty()) break;
      for (std::size_t i : candidates) consider(i);
    }
    for (const auto& [i, to] : moves) patch[i] = curved_patch[i] = to;
    // A pixel that did not move had its own patch nearest among its neighbours' (or had all
    // neighbours in its patch); it can move next pass only if a neighbour moved into a patch
    // nearer than its own. Others need no second look. Listed without branches: whether a
    // neighbour is listed is as unpredictable as the noise.
    candidates.resize(moves.size() * 8);
    std::size_t listed = 0;
    for (const auto& [i, to] : moves) {
      // Links between two labelled pixels are symmetric (a depth-jump test of the pair), and
      // only set towards neighbours inside the image; a neighbour without one reads the pixel
      // itself, now in `to`.
      const std::uint8_t side = field.same_side[i];
      const double mean_to = mean_of[to + 1];
      for (int k = 0; k < 8; ++k) {
        const std::size_t j = ((side >> k) & 1u) ? i + step[k] : i;
        const std::int32_t own = curved_patch[j];
        const double s = field.shape_index[j];
        const bool nearer = std::abs(s - mean_to) < std::abs(s - mean_of[own + 1]);
        const bool listing = own != kNoPatch && own != to && stamp[j] != pass && nearer;
        stamp[j] = listing ? pass : stamp[j];
        candidates[listed] = j;
        listed += listing;
      }
    }
    candidates.resize(listed);
  }
}

}  // namespace

void drop_emptied_patches(CsmpSegmentation& result) {
  std::vector<std::int32_t> renumbered(static_cast<std::size_t>(result.patch_count), kNoPatch);
  for (std::size_t i = 0; i < result.patch_of_pixel.size(); ++i)
    if (const std::int32_t patch = result.patch_of_pixel[i]; patch >= 0) renumbered[patch] = 0;
  int patches = 0;
  for (std::int32_t& id : renumbered)
    if (id == 0) id = patches++;
  if (patches == result.patch_count) return;
  for (std::size_t i = 0; i < result.patch_of_pixel.size(); ++i)
    if (std::int32_t& patch = result.patch_of_pixel[i]; patch >= 0) patch = renumbered[patch];
  result.patch_count = patches;
}

CsmpSegmentation segment_csmps(const DarbouxFrameField& frames, const ShapeIndexField& field,
                               const SegmentationParameters& parameters) {
  return segment_csmps_from_seeds(field, find_shape_seeds(frames, field, parameters), parameters);
}

CsmpSegmentation segment_csmps_from_seeds(const ShapeIndexField& field, const ShapeSeeds& seeds,
                                          const SegmentationParameters& parameters) {
  const std::size_t pixels = field.label.size();
  RegionMergeQueue regions;
  regions.reserve(seeds.seed_count());
  double visible_area_mm2 = 0;
  for (int seed = 0; seed < seeds.seed_count(); ++seed) {
    regions.add_region(seeds.shape_index_min[seed], seeds.shape_index_max[seed],
                       seeds.area_mm2[seed]);
    visible_area_mm2 += seeds.area_mm2[seed];
  }
  for (const auto& [a, b] : seeds.adjacent) regions.add_edge(a, b);

  const double min_area_mm2 = parameters.min_patch_area_fraction * visible_area_mm2;
  regions.count_regions_of_area_at_least(static_cast<float>(min_area_mm2));
  const bool adaptive = parameters.max_patches > 0;
  double limit = adaptive ? parameters.adaptive_start_limit : parameters.shape_diameter_limit;
  regions.grow(limit);
  std::vector<bool> dropped;
  GroupPairs group_pairs = seeds.adjacent;
  for (;;) {
    while (adaptive && limit < parameters.adaptive_max_limit &&
           regions.significant_region_count() > parameters.max_patches) {
      limit = std::min(parameters.adaptive_max_limit, limit + parameters.adaptive_limit_step);
      regions.grow(limit);
    }
    // Folding can join tiny patches into new significant ones: grow on if that overshoots.
    dropped = fold_tiny_patches(seeds, group_pairs, regions, min_area_mm2);
    if (!adaptive || limit >= parameters.adaptive_max_limit ||
        regions.significant_region_count() <= parameters.max_patches)
      break;
  }

  CsmpSegmentation result;
  result.shape_diameter_limit = limit;
  result.patch_of_pixel = PixelGrid<std::int32_t>(field.width(), field.height(), kNoPatch);
  // Patches are numbered in raster order of their first pixel: the order of their first
  // seeds, since seeds are numbered so.
  constexpr std::int32_t kUnnumbered = -2;
  std::vector<std::int32_t> patch_of_root(regions.region_count(), kUnnumbered);
  std::vector<std::int32_t> patch_of_seed(seeds.seed_count());
  for (int seed = 0; seed < seeds.seed_count(); ++seed) {
    const int root = regions.find(seed);
    std::int32_t& patch = patch_of_root[root];
    if (patch == kUnnumbered) patch = dropped[root] ? kNoPatch : result.patch_count++;
    patch_of_seed[seed] = patch;
  }
  for (std::size_t i = 0; i < pixels; ++i) {
    const std::int32_t seed = seeds.seed_of_pixel[i];
    if (seed >= 0) result.patch_of_pixel[i] = patch_of_seed[seed];
  }
  // The patches' curved area and S_I moments, from their seeds (a seed has one label).
  std::vector<double> area(result.patch_count, 0), shape_area(result.patch_count, 0);
  for (int seed = 0; seed < seeds.seed_count(); ++seed) {
    const std::int32_t patch = patch_of_seed[seed];
    if (patch == kNoPatch || seeds.shape_index_max[seed] > 1.0f) continue;
    area[patch] += seeds.area_mm2[seed];
    shape_area[patch] += seeds.shape_area[seed];
  }
  refine_boundaries(field, area, shape_area, result, parameters.boundary_refinement_passes);
  drop_emptied_patches(result);
  return result;
}

}  // namespace cosmos
