#include "core/segmentation/shape_seeds.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <memory>
#include <numbers>
#include <span>

#include "core/segmentation/neighbor_equality.hpp"

namespace cosmos {
namespace {

constexpr std::int32_t kNotRegion = -1;
// Directions 0-3 of kNeighborOffsets (up-left, up, up-right, left) are the half of the
// 8-neighbourhood already visited in raster order: every adjacency is seen once, from its
// later pixel.
constexpr int kBackwardNeighbors = 4;
constexpr int kLeft = 3;

// A pixel's union-find node; at a root, the S_I range of its set.
struct PixelNode {
  std::int32_t parent;
  float low;
  float high;
};

std::int32_t find_root(std::span<PixelNode> nodes, std::int32_t x) {
  while (nodes[x].parent != x) {
    nodes[x].parent = nodes[nodes[x].parent].parent;  // path halving
    x = nodes[x].parent;
  }
  return x;
}

// The table of recently listed seed pairs: 4096 entries, indexed by the top bits of a hash.
constexpr int kRecentShift = 20;
constexpr std::size_t kRecentPairs = std::size_t{1} << (32 - kRecentShift);

// The growing-edge masks of one row: bit k set when backward neighbour k is inside the image,
// on the same side of any depth jump and has the same label; planar pixels also need normals
// within the crease angle.
void backward_edges_of_row(const DarbouxFrameField& frames, const ShapeIndexField& field, int row,
                           double crease_cos, std::uint8_t* edges) {
  const int width = field.width();
  const std::uint8_t* side = field.same_side.row(row);
  equal_neighbors_of_row<kBackwardNeighbors>(field.label.data(), width, field.height(), row, edges);
  for (int column = 0; column < width; ++column)
    edges[column] = static_cast<std::uint8_t>(edges[column] & side[column] & 0x0Fu);
  for (int column = 0; column < width; ++column) {
    if (field.label.row(row)[column] != SurfaceLabel::kPlanar || edges[column] == 0) continue;
    const std::size_t i = field.label.index(column, row);
    for (int k = 0; k < kBackwardNeighbors; ++k) {
      if (!((edges[column] >> k) & 1u)) continue;
      const std::size_t j =
          field.label.index(column + kNeighborOffsets[k].column, row + kNeighborOffsets[k].row);
      double cosine = 0;
      for (int axis = kNx; axis <= kNz; ++axis)
        cosine += frames.frame[axis][i] * frames.frame[axis][j];
      if (cosine < crease_cos) edges[column] &= static_cast<std::uint8_t>(~(1u << k));
    }
  }
}

}  // namespace

ShapeSeeds find_shape_seeds(const DarbouxFrameField& frames, const ShapeIndexField& field,
                            const SegmentationParameters& parameters) {
  const std::size_t pixels = field.label.size();
  const std::ptrdiff_t width = field.width();
  const double crease_cos = std::cos(parameters.planar_crease_deg * std::numbers::pi / 180.0);
  std::ptrdiff_t step[8];
  for (int k = 0; k < 8; ++k)
    step[k] = kNeighborOffsets[k].row * width + kNeighborOffsets[k].column;

  // Pass 1: union-find over pixels in raster order, every root the first pixel of its set, so
  // a parent always precedes its child. Every node is written in raster order before it is
  // read: no fill beforehand. Where a pixel does not join a neighbour's set, the two sets'
  // roots make a crossing: the sets may still join later through other pixels, so a crossing
  // names pixels, resolved to seeds once seeds are numbered. A crossing repeating the one
  // before it (the same two sets along a boundary) is listed once.
  const std::unique_ptr<PixelNode[]> node_storage(new PixelNode[pixels]);
  const std::span<PixelNode> nodes(node_storage.get(), pixels);
  std::vector<std::uint8_t> row_edges(width);
  std::vector<std::pair<std::int32_t, std::int32_t>> crossings;
  crossings.reserve(pixels / 4);
  auto add_crossing = [&](std::int32_t root, std::int32_t other) {
    const std::pair<std::int32_t, std::int32_t> crossing{root, other};
    if (crossings.empty() || crossings.back() != crossing) crossings.push_back(crossing);
  };
  const auto quantum = static_cast<float>(parameters.seed_shape_index_quantum);
  for (int row = 0; row < field.height(); ++row) {
    const std::size_t row_start = static_cast<std::size_t>(row) * width;
    backward_edges_of_row(frames, field, row, crease_cos, row_edges.data());
    std::int32_t left_root = kNotRegion;
    for (std::size_t i = row_start; i < row_start + width; ++i) {
      if (field.label[i] == SurfaceLabel::kInvalid) {
        nodes[i].parent = kNotRegion;
        continue;
      }
      const std::uint8_t joined = row_edges[i - row_start];
      auto root = static_cast<std::int32_t>(i);
      const float shape_index = field.shape_index[i];
      nodes[i] = {root, shape_index, shape_index};
      // Inside a seed, the pixels above point straight at the left pixel's root (the previous
      // pixel's, a root still): then it is the only seed to join, without a search, and the
      // pixel joins it when the joined range stays within one quantum (the loop below would
      // do the same, more slowly; half the pixels of a smooth view are inside).
      bool inside = (joined >> kLeft) & 1u;
      for (int k = 0; k < kLeft; ++k)
        inside &= !((joined >> k) & 1u) || nodes[i + step[k]].parent == left_root;
      if (inside) {
        PixelNode& left = nodes[left_root];
        if (std::max(shape_index, left.high) - std::min(shape_index, left.low) <= quantum) {
          left.low = std::min(left.low, shape_index);
          left.high = std::max(left.high, shape_index);
          nodes[i].parent = left_root;
        } else {
          add_crossing(root, left_root);
          left_root = root;
        }
        continue;
      }
      // Join the neighbours' seeds, the one whose joined S_I range is least first (the growing
      // order of §3.5.2), while the joined seed's range stays within one quantum.
      std::int32_t roots[kBackwardNeighbors], root_in_direction[kBackwardNeighbors];
      int count = 0;
      for (int k = 0; k < kBackwardNeighbors; ++k) {
        if (!((joined >> k) & 1u)) continue;
        const std::int32_t other =
            k == kLeft ? left_root : find_root(nodes, static_cast<std::int32_t>(i + step[k]));
        root_in_direction[k] = other;
        bool listed = false;
        for (int n = 0; n < count; ++n) listed |= roots[n] == other;
        if (!listed) roots[count++] = other;
      }
      while (count > 0) {
        int best = -1;
        float best_range = quantum;
        for (int n = 0; n < count; ++n) {
          const PixelNode& other = nodes[roots[n]];
          const float range =
              std::max(nodes[root].high, other.high) - std::min(nodes[root].low, other.low);
          if (range <= best_range) best_range = range, best = n;
        }
        if (best < 0) break;
        const std::int32_t other = roots[best];
        roots[best] = roots[--count];
        // The joined set keeps the older root; the roots left in the list are untouched.
        const std::int32_t kept = std::min(root, other), joined_root = std::max(root, other);
        nodes[kept].low = std::min(nodes[kept].low, nodes[joined_root].low);
        nodes[kept].high = std::max(nodes[kept].high, nodes[joined_root].high);
        nodes[joined_root].parent = kept;
        root = kept;
      }
      if (count == 1) {
        add_crossing(root, roots[0]);
      } else if (count > 1) {
        // Edge by edge, in direction order, into the sets left unjoined (roots still, and not
        // this pixel's): the seed pairs then keep the order a scan of every growing edge gives
        // them, which orders ties in the growing queue.
        for (int k = 0; k < kBackwardNeighbors; ++k) {
          const std::int32_t other = root_in_direction[k];
          if (((joined >> k) & 1u) && other != root && nodes[other].parent == other)
            add_crossing(root, other);
        }
      }
      left_root = root;
    }
  }

  // Pass 2: a root opens the next seed, with the S_I range pass 1 kept at it; any other pixel
  // takes its parent's seed (the parent precedes it, so it is already numbered). Areas are
  // summed pixel by pixel.
  ShapeSeeds seeds;
  std::vector<std::int32_t>& seed_of_pixel = seeds.seed_of_pixel;
  seed_of_pixel.assign(pixels, kNotRegion);
  for (std::size_t i = 0; i < pixels; ++i) {
    const std::int32_t p = nodes[i].parent;
    if (p == kNotRegion) continue;
    const float shape_index = field.shape_index[i], area_mm2 = field.area_mm2[i];
    if (p == static_cast<std::int32_t>(i)) {
      seed_of_pixel[i] = seeds.seed_count();
      seeds.shape_index_min.push_back(nodes[i].low);
      seeds.shape_index_max.push_back(nodes[i].high);
      seeds.area_mm2.push_back(area_mm2);
      seeds.shape_area.push_back(static_cast<double>(shape_index) * area_mm2);
    } else {
      const std::int32_t seed = seed_of_pixel[p];
      seed_of_pixel[i] = seed;
      seeds.area_mm2[seed] += area_mm2;
      seeds.shape_area[seed] += static_cast<double>(shape_index) * area_mm2;
    }
  }

  // Pass 3: the crossings between different seeds. Along a boundary the same pair recurs from
  // pixel to pixel and row to row: a small table of recently listed pairs, indexed by a hash
  // of the pair, keeps nearly all repeats out of the list. The scan runs backwards so that a
  // pair keeps the place of its last crossing, as the unfiltered list's last copy would have
  // in the growing queue (keeping first copies changed the relief views' segmentations).
  seeds.adjacent.reserve(crossings.size() / 2);
  std::vector<std::uint64_t> recent(kRecentPairs, ~std::uint64_t{0});
  for (auto crossing = crossings.rbegin(); crossing != crossings.rend(); ++crossing) {
    const std::int32_t a = seed_of_pixel[crossing->first], b = seed_of_pixel[crossing->second];
    if (a == b) continue;
    const auto low = static_cast<std::uint32_t>(std::min(a, b));
    const auto high = static_cast<std::uint32_t>(std::max(a, b));
    const std::uint64_t key = std::uint64_t{low} << 32 | high;
    std::uint64_t& slot = recent[(low * 0x9E3779B1u ^ high * 0x85EBCA77u) >> kRecentShift];
    if (slot == key) continue;
    slot = key;
    seeds.adjacent.emplace_back(b, a);
  }
  std::reverse(seeds.adjacent.begin(), seeds.adjacent.end());
  return seeds;
}

}  // namespace cosmos
