#include "core/tiny_patch_folding.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

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

  // Scans the pixels of group `root` for its most similar neighbour (significant ones only,
  // if asked) and, optionally, collects its tiny neighbours.
  std::vector<int> tiny_neighbors;
  auto best_neighbor = [&](int root, bool significant_only, bool collect) {
    int best = -1;
    double best_difference = 0;
    if (collect) tiny_neighbors.clear();
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
          if (other == root) continue;
          const bool significant = regions.area_mm2(other) >= min_area_mm2;
          if (collect && !significant) tiny_neighbors.push_back(other);
          if (significant_only && !significant) continue;
          const double difference = std::abs(mean(other) - mean(root));
          if (best < 0 || difference < best_difference || (difference == best_difference && other < best)) {
            best = other;
            best_difference = difference;
          }
        }
      }
    }
    return best;
  };
  auto fold = [&](int root, int into) {
    const double merged_shape_area = shape_area[root] + shape_area[into];
    regions.unite(root, into);
    const int merged = regions.find(root), absorbed = merged == root ? into : root;
    shape_area[merged] = merged_shape_area;
    next_member[last_member[merged]] = absorbed;
    last_member[merged] = last_member[absorbed];
  };
  // Into significant neighbours: smallest first, then, as folding makes a significant patch
  // the neighbour of more tiny ones, those (a worklist, so each is rescanned only when a
  // neighbour of it has folded).
  std::vector<int> worklist(tiny.begin(), tiny.end());
  std::vector<std::uint8_t> queued(n, 0);
  for (int patch : tiny) queued[patch] = 1;
  for (std::size_t next = 0; next < worklist.size(); ++next) {
    const int patch = worklist[next];
    queued[patch] = 0;
    const int root = regions.find(patch);
    if (root != patch || regions.area_mm2(root) >= min_area_mm2) continue;
    const int best = best_neighbor(root, true, true);
    if (best < 0) continue;
    fold(root, best);
    for (int neighbor : tiny_neighbors) {
      const int other = regions.find(neighbor);
      if (!queued[other] && regions.area_mm2(other) < min_area_mm2) {
        queued[other] = 1;
        worklist.push_back(other);
      }
    }
  }
  // Then tiny clusters among themselves (islands away from any significant patch).
  for (bool changed = true; changed;) {
    changed = false;
    for (int patch : tiny) {
      const int root = regions.find(patch);
      if (root != patch || regions.area_mm2(root) >= min_area_mm2) continue;
      const int best = best_neighbor(root, false, false);
      if (best < 0) continue;
      fold(root, best);
      changed = true;
    }
  }
  std::vector<bool> dropped(n, false);
  for (int patch : tiny) {
    const int root = regions.find(patch);
    if (regions.area_mm2(root) < min_area_mm2) dropped[root] = true;  // an island of noise
  }
  return dropped;
}

}  // namespace cosmos
