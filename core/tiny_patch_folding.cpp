#include "core/tiny_patch_folding.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>

namespace cosmos {
namespace {

// The groups at the start of folding (the roots after growing) and, for every tiny one, the
// groups its pixels touch. Only tiny groups are ever searched for a neighbour, so only they
// get a list. A list holds each neighbouring group once, in the order a scan of the group's
// pixels (increasing index, neighbours in direction order) first meets it: the order in which
// folding a tiny patch queues its tiny neighbours again. Building it once replaces rescanning
// the pixels of every group at every search (and of every cluster at every round).
struct StartingGroups {
  std::vector<int> root_of_pixel;    // -1: not a region pixel
  std::vector<double> shape_area;    // per root: sum of S_I * area, for the mean S_I
  std::vector<int> tiny;             // tiny roots, by area (ties by index)
  std::vector<int> slot_of_root;     // index into `tiny` (-1: not tiny)
  std::vector<int> neighbor_offset;  // per slot, into `neighbors`
  std::vector<int> neighbors;        // starting roots
};

StartingGroups starting_groups(const ShapeIndexField& field,
                               const std::vector<int>& region_of_pixel, RegionMergeQueue& regions,
                               double min_area_mm2) {
  const std::size_t n = regions.region_count();
  const std::size_t pixels = field.label.size();
  StartingGroups groups;
  groups.root_of_pixel.assign(pixels, -1);
  groups.shape_area.assign(n, 0.0);
  groups.slot_of_root.assign(n, -1);
  for (std::size_t i = 0; i < pixels; ++i) {
    if (region_of_pixel[i] < 0) continue;
    const int root = regions.find(region_of_pixel[i]);
    groups.root_of_pixel[i] = root;
    groups.shape_area[root] += static_cast<double>(field.shape_index[i]) * field.area_mm2[i];
  }
  for (int region = 0; region < static_cast<int>(n); ++region)
    if (regions.is_root(region) && regions.area_mm2(region) < min_area_mm2)
      groups.tiny.push_back(region);
  std::stable_sort(groups.tiny.begin(), groups.tiny.end(),
                   [&](int a, int b) { return regions.area_mm2(a) < regions.area_mm2(b); });
  const int slots = static_cast<int>(groups.tiny.size());
  for (int slot = 0; slot < slots; ++slot) groups.slot_of_root[groups.tiny[slot]] = slot;

  // The pixels of the tiny groups, by slot and then by index (a counting sort).
  std::vector<int> first_pixel(slots + 1, 0);
  for (std::size_t i = 0; i < pixels; ++i) {
    const int root = groups.root_of_pixel[i];
    if (root >= 0 && groups.slot_of_root[root] >= 0) ++first_pixel[groups.slot_of_root[root] + 1];
  }
  for (int slot = 0; slot < slots; ++slot) first_pixel[slot + 1] += first_pixel[slot];
  std::vector<int> pixel_order(first_pixel[slots]);
  std::vector<int> fill(first_pixel.begin(), first_pixel.end() - 1);
  for (std::size_t i = 0; i < pixels; ++i) {
    const int root = groups.root_of_pixel[i];
    if (root >= 0 && groups.slot_of_root[root] >= 0)
      pixel_order[fill[groups.slot_of_root[root]]++] = static_cast<int>(i);
  }

  // Same-side bits are only set for neighbours inside the image, so plain index offsets do.
  const std::ptrdiff_t width = field.width();
  std::ptrdiff_t step[8];
  for (int k = 0; k < 8; ++k)
    step[k] = kNeighborOffsets[k].row * width + kNeighborOffsets[k].column;
  std::vector<int> seen_by(n, -1);
  groups.neighbor_offset.assign(slots + 1, 0);
  for (int slot = 0; slot < slots; ++slot) {
    const int root = groups.tiny[slot];
    for (int k = first_pixel[slot]; k < first_pixel[slot + 1]; ++k) {
      const int i = pixel_order[k];
      for (int direction = 0; direction < 8; ++direction) {
        if (!((field.same_side[i] >> direction) & 1u)) continue;
        const int other = groups.root_of_pixel[i + step[direction]];
        if (other < 0 || other == root || seen_by[other] == slot) continue;
        seen_by[other] = slot;
        groups.neighbors.push_back(other);
      }
    }
    groups.neighbor_offset[slot + 1] = static_cast<int>(groups.neighbors.size());
  }
  return groups;
}

}  // namespace

std::vector<bool> fold_tiny_patches(const ShapeIndexField& field,
                                    const std::vector<int>& region_of_pixel,
                                    RegionMergeQueue& regions, double min_area_mm2) {
  StartingGroups groups = starting_groups(field, region_of_pixel, regions, min_area_mm2);
  const std::vector<int>& tiny = groups.tiny;
  std::vector<double>& shape_area = groups.shape_area;
  const int slots = static_cast<int>(tiny.size());
  // Groups that fold together chain their slots (only clusters of tiny groups are searched).
  std::vector<int> next_member(slots, -1), last_member(slots);
  for (int slot = 0; slot < slots; ++slot) last_member[slot] = slot;
  auto mean = [&](int root) {
    return shape_area[root] / std::max(1e-12, static_cast<double>(regions.area_mm2(root)));
  };

  // The most similar neighbour of group `root` (significant ones only, if asked), ties to the
  // lowest index; optionally collects its tiny neighbours, in the order the pixels meet them.
  std::vector<int> tiny_neighbors;
  auto best_neighbor = [&](int root, bool significant_only, bool collect) {
    int best = -1;
    double best_difference = 0;
    if (collect) tiny_neighbors.clear();
    for (int member = groups.slot_of_root[root]; member >= 0; member = next_member[member]) {
      for (int k = groups.neighbor_offset[member]; k < groups.neighbor_offset[member + 1]; ++k) {
        const int other = regions.find(groups.neighbors[k]);
        if (other == root) continue;
        const bool significant = regions.area_mm2(other) >= min_area_mm2;
        if (collect && !significant) tiny_neighbors.push_back(other);
        if (significant_only && !significant) continue;
        const double difference = std::abs(mean(other) - mean(root));
        if (best < 0 || difference < best_difference ||
            (difference == best_difference && other < best)) {
          best = other;
          best_difference = difference;
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
    const int merged_slot = groups.slot_of_root[merged];
    const int absorbed_slot = groups.slot_of_root[absorbed];
    // A group that absorbs a significant one is significant: it is never searched again.
    if (merged_slot < 0 || absorbed_slot < 0) return;
    next_member[last_member[merged_slot]] = absorbed_slot;
    last_member[merged_slot] = last_member[absorbed_slot];
  };
  // Into significant neighbours: smallest first, then, as folding makes a significant patch
  // the neighbour of more tiny ones, those (a worklist, so each is searched again only when a
  // neighbour of it has folded).
  std::vector<int> worklist(tiny.begin(), tiny.end());
  std::vector<std::uint8_t> queued(slots, 1);
  for (std::size_t next = 0; next < worklist.size(); ++next) {
    const int patch = worklist[next];
    queued[groups.slot_of_root[patch]] = 0;
    const int root = regions.find(patch);
    if (root != patch || regions.area_mm2(root) >= min_area_mm2) continue;
    const int best = best_neighbor(root, true, true);
    if (best < 0) continue;
    fold(root, best);
    for (int neighbor : tiny_neighbors) {
      // Still a tiny root: folding into a significant patch only absorbs the tiny one.
      const int slot = groups.slot_of_root[neighbor];
      if (!queued[slot]) {
        queued[slot] = 1;
        worklist.push_back(neighbor);
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
  std::vector<bool> dropped(regions.region_count(), false);
  for (int patch : tiny) {
    const int root = regions.find(patch);
    if (regions.area_mm2(root) < min_area_mm2) dropped[root] = true;  // an island of noise
  }
  return dropped;
}

}  // namespace cosmos
