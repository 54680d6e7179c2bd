#include "core/segmentation/tiny_patch_folding.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <utility>

namespace cosmos {
namespace {

// The groups at the start of folding (the roots after growing) and, for every tiny one, the
// groups it touches. Only tiny groups are ever searched for a neighbour, so only they get a
// list. A list holds each neighbouring group once, in the order of the seed adjacency list:
// the order in which folding a tiny patch queues its tiny neighbours again. Building it once
// replaces rescanning the adjacency of every group at every search.
struct StartingGroups {
  std::vector<double> shape_area;    // per root: sum of S_I * area, for the mean S_I
  std::vector<int> tiny;             // tiny roots, by area (ties by index)
  std::vector<int> slot_of_root;     // index into `tiny` (-1: not tiny)
  std::vector<int> neighbor_offset;  // per slot, into `neighbors`
  std::vector<int> neighbors;        // starting roots
  int significant = 0;               // starting roots of at least the minimum area
};

// Stable sort of `roots` (in index order) by area: a radix sort on the bits of the areas,
// which order as unsigned integers since areas are positive floats.
void sort_by_area(const RegionMergeQueue& regions, std::vector<int>& roots) {
  constexpr int kDigitBits = 11;
  constexpr std::uint32_t kDigits = 1u << kDigitBits;
  std::vector<std::pair<std::uint32_t, int>> keyed(roots.size()), sorted(roots.size());
  for (std::size_t k = 0; k < roots.size(); ++k)
    keyed[k] = {std::bit_cast<std::uint32_t>(regions.area_mm2(roots[k])), roots[k]};
  std::vector<std::uint32_t> start(kDigits);
  for (int shift = 0; shift < 32; shift += kDigitBits) {
    std::fill(start.begin(), start.end(), 0u);
    for (const auto& entry : keyed) ++start[(entry.first >> shift) & (kDigits - 1)];
    std::uint32_t offset = 0;
    for (std::uint32_t& count : start) offset += std::exchange(count, offset);
    for (const auto& entry : keyed) sorted[start[(entry.first >> shift) & (kDigits - 1)]++] = entry;
    keyed.swap(sorted);
  }
  for (std::size_t k = 0; k < roots.size(); ++k) roots[k] = keyed[k].second;
}

StartingGroups starting_groups(const ShapeSeeds& seeds, GroupPairs& group_pairs,
                               RegionMergeQueue& regions, double min_area_mm2) {
  const std::size_t n = regions.region_count();
  StartingGroups groups;
  groups.shape_area.assign(n, 0.0);
  groups.slot_of_root.assign(n, -1);
  std::vector<int> root_of(n);
  for (std::size_t seed = 0; seed < n; ++seed) {
    root_of[seed] = regions.find(static_cast<int>(seed));
    groups.shape_area[root_of[seed]] += seeds.shape_area[seed];
  }
  for (int region = 0; region < static_cast<int>(n); ++region) {
    if (!regions.is_root(region)) continue;
    if (regions.area_mm2(region) < min_area_mm2) {
      groups.tiny.push_back(region);
    } else {
      ++groups.significant;
    }
  }
  sort_by_area(regions, groups.tiny);
  const int slots = static_cast<int>(groups.tiny.size());
  for (int slot = 0; slot < slots; ++slot) groups.slot_of_root[groups.tiny[slot]] = slot;

  // The pairs, now of groups: those inside one group are dropped for good (groups only grow),
  // the order is kept.
  std::size_t kept = 0;
  for (const auto& [a, b] : group_pairs) {
    const int root_a = root_of[a], root_b = root_of[b];
    if (root_a != root_b) group_pairs[kept++] = {root_a, root_b};
  }
  group_pairs.resize(kept);

  // Each adjacent pair of different groups, seen from each tiny side: counted, then filed.
  std::vector<int> fill(slots + 1, 0);
  auto for_each_side = [&](auto&& visit) {
    for (const auto& [root_a, root_b] : group_pairs) {
      if (groups.slot_of_root[root_a] >= 0) visit(groups.slot_of_root[root_a], root_b);
      if (groups.slot_of_root[root_b] >= 0) visit(groups.slot_of_root[root_b], root_a);
    }
  };
  for_each_side([&](int slot, int) { ++fill[slot + 1]; });
  for (int slot = 0; slot < slots; ++slot) fill[slot + 1] += fill[slot];
  std::vector<int> sides(fill[slots]);
  std::vector<int> side_offset(fill.begin(), fill.end());
  for_each_side([&](int slot, int other) { sides[fill[slot]++] = other; });

  std::vector<int> seen_by(n, -1);
  groups.neighbor_offset.assign(slots + 1, 0);
  groups.neighbors.reserve(sides.size());
  for (int slot = 0; slot < slots; ++slot) {
    for (int k = side_offset[slot]; k < side_offset[slot + 1]; ++k) {
      const int other = sides[k];
      if (seen_by[other] == slot) continue;
      seen_by[other] = slot;
      groups.neighbors.push_back(other);
    }
    groups.neighbor_offset[slot + 1] = static_cast<int>(groups.neighbors.size());
  }
  return groups;
}

}  // namespace

std::vector<bool> fold_tiny_patches(const ShapeSeeds& seeds, GroupPairs& group_pairs,
                                    RegionMergeQueue& regions, double min_area_mm2) {
  StartingGroups groups = starting_groups(seeds, group_pairs, regions, min_area_mm2);
  const std::vector<int>& tiny = groups.tiny;
  std::vector<double>& shape_area = groups.shape_area;
  const int slots = static_cast<int>(tiny.size());
  // Groups that fold together chain their slots (only clusters of tiny groups are searched).
  std::vector<int> next_member(slots, -1), last_member(slots);
  for (int slot = 0; slot < slots; ++slot) last_member[slot] = slot;
  auto mean = [&](int root) {
    return shape_area[root] / std::max(1e-12, static_cast<double>(regions.area_mm2(root)));
  };
  // Each slot's neighbour list, lists[list_begin[slot], list_end[slot]): at first the starting
  // groups'; the search of a cluster among tiny ones rewrites it (see below).
  std::vector<int>& lists = groups.neighbors;
  std::vector<int> list_begin(groups.neighbor_offset.begin(), groups.neighbor_offset.end() - 1);
  std::vector<int> list_end(groups.neighbor_offset.begin() + 1, groups.neighbor_offset.end());
  // Every root's mean S_I, kept up to date by fold().
  std::vector<double> mean_of(regions.region_count());
  for (int region = 0; region < static_cast<int>(regions.region_count()); ++region)
    if (regions.is_root(region)) mean_of[region] = mean(region);

  // The most similar of the offered groups: least difference of mean S_I, ties to the lowest
  // index.
  struct Nearest {
    int group = -1;
    double difference = 0;
    void offer(int other, double other_difference) {
      if (group < 0 || other_difference < difference ||
          (other_difference == difference && other < group)) {
        group = other;
        difference = other_difference;
      }
    }
  };
  // The most similar significant neighbour of group `root`; collects its tiny neighbours too,
  // in the order of its neighbour list.
  std::vector<int> tiny_neighbors;
  auto nearest_significant_neighbor = [&](int root) {
    Nearest nearest;
    tiny_neighbors.clear();
    const double own_mean = mean_of[root];
    for (int member = groups.slot_of_root[root]; member >= 0; member = next_member[member]) {
      for (int k = list_begin[member]; k < list_end[member]; ++k) {
        const int other = regions.find(lists[k]);
        if (other == root) continue;
        if (regions.area_mm2(other) < min_area_mm2) {
          tiny_neighbors.push_back(other);
        } else {
          nearest.offer(other, std::abs(mean_of[other] - own_mean));
        }
      }
    }
    return nearest.group;
  };
  auto fold = [&](int root, int into) {
    const double merged_shape_area = shape_area[root] + shape_area[into];
    regions.unite(root, into);
    const int merged = regions.find(root), absorbed = merged == root ? into : root;
    shape_area[merged] = merged_shape_area;
    mean_of[merged] = mean(merged);
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
  // With no significant group yet, no tiny one has a neighbour to fold into.
  std::vector<int> worklist;
  if (groups.significant > 0) worklist.assign(tiny.begin(), tiny.end());
  std::vector<std::uint8_t> queued(slots, 1);
  for (std::size_t next = 0; next < worklist.size(); ++next) {
    const int patch = worklist[next];
    queued[groups.slot_of_root[patch]] = 0;
    const int root = regions.find(patch);
    if (root != patch || regions.area_mm2(root) >= min_area_mm2) continue;
    const int best = nearest_significant_neighbor(root);
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
  // Then tiny clusters among themselves (islands away from any significant patch), in rounds
  // over the tiny roots that are left. The nearest neighbour does not depend on the order of
  // the list, so each search leaves its cluster one list of its current outside neighbours:
  // a cluster formed in one round is not searched through all its members' lists, mostly
  // about each other, in the next.
  std::vector<int> seen_by(regions.region_count(), -1);
  int search = 0;
  auto nearest_neighbor_compacting = [&](int root) {
    const int head = groups.slot_of_root[root];
    const int begin = static_cast<int>(lists.size());
    Nearest nearest;
    const double own_mean = mean_of[root];
    for (int member = head; member >= 0; member = next_member[member]) {
      for (int k = list_begin[member]; k < list_end[member]; ++k) {
        const int other = regions.find(lists[k]);
        if (other == root || seen_by[other] == search) continue;
        seen_by[other] = search;
        lists.push_back(other);
        nearest.offer(other, std::abs(mean_of[other] - own_mean));
      }
    }
    ++search;
    list_begin[head] = begin;
    list_end[head] = static_cast<int>(lists.size());
    next_member[head] = -1;
    last_member[head] = head;
    return nearest.group;
  };
  std::vector<int> left(tiny.begin(), tiny.end());
  for (bool changed = true; changed;) {
    changed = false;
    std::size_t kept = 0;
    for (int patch : left) {
      const int root = regions.find(patch);
      // A group that stops being a tiny root never becomes one again.
      if (root != patch || regions.area_mm2(root) >= min_area_mm2) continue;
      left[kept++] = patch;
      const int best = nearest_neighbor_compacting(root);
      if (best < 0) continue;
      fold(root, best);
      changed = true;
    }
    left.resize(kept);
  }
  std::vector<bool> dropped(regions.region_count(), false);
  for (int patch : tiny) {
    const int root = regions.find(patch);
    if (regions.area_mm2(root) < min_area_mm2) dropped[root] = true;  // an island of noise
  }
  return dropped;
}

}  // namespace cosmos
