#include "core/tiny_patch_folding.hpp"

#include <algorithm>
#include <cmath>

namespace cosmos {

std::vector<bool> fold_tiny_patches(const ShapeIndexField& field, const std::vector<int>& region_of_pixel,
                                    RegionMergeQueue& regions, double min_area_mm2) {
  const std::size_t n = regions.region_count();
  const std::size_t pixels = field.label.size();
  const int width = field.width();
  // The groups at the start, each with its pixels (a counting sort by root) and the sum of
  // S_I * area for its mean; groups that merge later chain their starting roots.
  std::vector<int> start_root(pixels, -1);
  std::vector<double> shape_area(n, 0.0);
  std::vector<int> offset(n + 1, 0);
  for (std::size_t i = 0; i < pixels; ++i) {
    if (region_of_pixel[i] < 0) continue;
    const int root = regions.find(region_of_pixel[i]);
    start_root[i] = root;
    shape_area[root] += static_cast<double>(field.shape_index[i]) * field.area_mm2[i];
    ++offset[root + 1];
  }
  for (std::size_t r = 0; r < n; ++r) offset[r + 1] += offset[r];
  std::vector<int> pixel_order(offset[n]);
  std::vector<int> fill(offset.begin(), offset.end() - 1);
  for (std::size_t i = 0; i < pixels; ++i)
    if (start_root[i] >= 0) pixel_order[fill[start_root[i]]++] = static_cast<int>(i);
  std::vector<int> next_member(n, -1), last_member(n);
  for (std::size_t r = 0; r < n; ++r) last_member[r] = static_cast<int>(r);

  std::vector<int> tiny;
  for (std::size_t r = 0; r < n; ++r)
    if (offset[r + 1] > offset[r] && regions.area_mm2(static_cast<int>(r)) < min_area_mm2)
      tiny.push_back(static_cast<int>(r));
  std::stable_sort(tiny.begin(), tiny.end(), [&](int a, int b) { return regions.area_mm2(a) < regions.area_mm2(b); });
  auto mean = [&](int root) { return shape_area[root] / std::max(1e-12, static_cast<double>(regions.area_mm2(root))); };

  auto fold_pass = [&](bool into_significant_only) {
    bool changed = false;
    for (int patch : tiny) {
      const int root = regions.find(patch);
      if (root != patch || regions.area_mm2(root) >= min_area_mm2) continue;  // handled via its root
      int best = -1;
      double best_difference = 0;
      for (int member = root; member >= 0; member = next_member[member]) {
        for (int k = offset[member]; k < offset[member + 1]; ++k) {
          const int i = pixel_order[k];
          const int column = i % width, row = i / width;
          for (int direction = 0; direction < 8; ++direction) {
            if (!((field.same_side[i] >> direction) & 1u)) continue;
            const std::size_t j = field.label.index(column + kNeighborOffsets[direction].column,
                                                    row + kNeighborOffsets[direction].row);
            if (start_root[j] < 0) continue;
            const int other = regions.find(start_root[j]);
            if (other == root || (into_significant_only && regions.area_mm2(other) < min_area_mm2)) continue;
            const double difference = std::abs(mean(other) - mean(root));
            if (best < 0 || difference < best_difference || (difference == best_difference && other < best)) {
              best = other;
              best_difference = difference;
            }
          }
        }
      }
      if (best < 0) continue;
      const double merged_shape_area = shape_area[root] + shape_area[best];
      regions.unite(root, best);
      const int merged = regions.find(root), absorbed = merged == root ? best : root;
      shape_area[merged] = merged_shape_area;
      next_member[last_member[merged]] = absorbed;
      last_member[merged] = last_member[absorbed];
      changed = true;
    }
    return changed;
  };
  while (fold_pass(true)) {
  }
  while (fold_pass(false)) {
  }
  std::vector<bool> dropped(n, false);
  for (int patch : tiny) {
    const int root = regions.find(patch);
    if (regions.area_mm2(root) < min_area_mm2) dropped[root] = true;  // an island of noise
  }
  return dropped;
}

}  // namespace cosmos
