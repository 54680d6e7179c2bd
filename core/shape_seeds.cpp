#include "core/shape_seeds.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>

namespace cosmos {
namespace {

constexpr std::int32_t kNotRegion = -1;
// Directions 0-3 of kNeighborOffsets (up-left, up, up-right, left) are the half of the
// 8-neighbourhood already visited in raster order: every adjacency is seen once, from its
// later pixel.
constexpr int kBackwardNeighbors = 4;

// A pixel's union-find node; at a root, the S_I range of its set.
struct PixelNode {
  std::int32_t parent;
  float low;
  float high;
};

std::int32_t find_root(std::vector<PixelNode>& nodes, std::int32_t x) {
  while (nodes[x].parent != x) {
    nodes[x].parent = nodes[nodes[x].parent].parent;  // path halving
    x = nodes[x].parent;
  }
  return x;
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
  // a parent always precedes its child. `edges` keeps each pixel's backward growing edges.
  std::vector<PixelNode> nodes(pixels, PixelNode{kNotRegion, 0.0f, 0.0f});
  std::vector<std::uint8_t> edges(pixels, 0);
  const auto quantum = static_cast<float>(parameters.seed_shape_index_quantum);
  for (std::size_t i = 0; i < pixels; ++i) {
    const SurfaceLabel own_label = field.label[i];
    if (own_label == SurfaceLabel::kInvalid) continue;
    // Neighbours outside the image have no same-side bit, so their indices are never read.
    const std::uint8_t side = field.same_side[i] & 0x0Fu;
    std::uint8_t joined = 0;
    for (int k = 0; k < kBackwardNeighbors; ++k) {
      const bool inside = (side >> k) & 1u;
      const bool same_label = inside && field.label[i + step[k]] == own_label;
      joined |= static_cast<std::uint8_t>(same_label << k);
    }
    if (own_label == SurfaceLabel::kPlanar) {
      for (int k = 0; k < kBackwardNeighbors; ++k) {
        if (!((joined >> k) & 1u)) continue;
        const std::size_t j = i + step[k];
        double cosine = 0;
        for (int axis = kNx; axis <= kNz; ++axis)
          cosine += frames.frame[axis][i] * frames.frame[axis][j];
        if (cosine < crease_cos) joined &= static_cast<std::uint8_t>(~(1u << k));
      }
    }
    edges[i] = joined;
    // Join the neighbours' seeds, the one whose joined S_I range is least first (the growing
    // order of §3.5.2), while the joined seed's range stays within one quantum.
    auto root = static_cast<std::int32_t>(i);
    nodes[i] = {root, field.shape_index[i], field.shape_index[i]};
    std::int32_t roots[kBackwardNeighbors];
    int count = 0;
    for (int k = 0; k < kBackwardNeighbors; ++k) {
      if (!((joined >> k) & 1u)) continue;
      const std::int32_t other = find_root(nodes, static_cast<std::int32_t>(i + step[k]));
      if (std::find(roots, roots + count, other) == roots + count) roots[count++] = other;
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
  }

  // Pass 2: a root opens the next seed, any other pixel takes its parent's seed (the parent
  // precedes it, so it is already numbered).
  ShapeSeeds seeds;
  std::vector<std::int32_t>& seed_of_pixel = seeds.seed_of_pixel;
  seed_of_pixel.assign(pixels, kNotRegion);
  for (std::size_t i = 0; i < pixels; ++i) {
    const std::int32_t p = nodes[i].parent;
    if (p == kNotRegion) continue;
    const float shape_index = field.shape_index[i], area_mm2 = field.area_mm2[i];
    if (p == static_cast<std::int32_t>(i)) {
      seed_of_pixel[i] = seeds.seed_count();
      seeds.shape_index_min.push_back(shape_index);
      seeds.shape_index_max.push_back(shape_index);
      seeds.area_mm2.push_back(area_mm2);
      seeds.shape_area.push_back(static_cast<double>(shape_index) * area_mm2);
    } else {
      const std::int32_t seed = seed_of_pixel[p];
      seed_of_pixel[i] = seed;
      seeds.shape_index_min[seed] = std::min(seeds.shape_index_min[seed], shape_index);
      seeds.shape_index_max[seed] = std::max(seeds.shape_index_max[seed], shape_index);
      seeds.area_mm2[seed] += area_mm2;
      seeds.shape_area[seed] += static_cast<double>(shape_index) * area_mm2;
    }
  }

  // Pass 3: growing edges between different seeds. Along a boundary the same pair recurs from
  // pixel to pixel and from direction to direction: a pair is listed unless the previous pixel
  // listed it in the same direction or this pixel already did in another.
  seeds.adjacent.reserve(pixels / 4);
  std::int32_t last_neighbor[kBackwardNeighbors];
  std::fill(std::begin(last_neighbor), std::end(last_neighbor), kNotRegion);
  std::int32_t last_seed = kNotRegion;
  for (std::size_t i = 0; i < pixels; ++i) {
    const std::uint8_t mask = edges[i];
    if (mask == 0) continue;
    const std::int32_t a = seed_of_pixel[i];
    if (a != last_seed) {
      std::fill(std::begin(last_neighbor), std::end(last_neighbor), kNotRegion);
      last_seed = a;
    }
    std::int32_t listed = a;
    for (int k = 0; k < kBackwardNeighbors; ++k) {
      if (!((mask >> k) & 1u)) continue;
      const std::int32_t b = seed_of_pixel[i + step[k]];
      if (b == a || b == listed || b == last_neighbor[k]) continue;
      last_neighbor[k] = b;
      listed = b;
      seeds.adjacent.emplace_back(b, a);
    }
  }
  return seeds;
}

}  // namespace cosmos
