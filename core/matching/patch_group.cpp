#include "core/matching/patch_group.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace cosmos {
namespace {

int index_of_id(const CosmosView& view, int id) {
  for (std::size_t i = 0; i < view.patches.size(); ++i) {
    if (view.patches[i].id == id) return static_cast<int>(i);
  }
  return -1;
}

// Perimeter (pixels) of a disc of the patch's pixel count: the boundary a compact patch has.
double perimeter_estimate_px(int pixels) {
  return 2.0 * std::sqrt(std::numbers::pi * std::max(pixels, 0));
}

// The connected component of `within` that contains `seed` (breadth-first on bit masks).
PatchSet component_of(const PatchGraph& graph, PatchSet within, int seed) {
  PatchSet reached = patch_bit(seed);
  PatchSet frontier = reached;
  while (frontier != 0) {
    PatchSet next = 0;
    for (PatchSet f = frontier; f != 0; f &= f - 1) next |= graph.nodes[lowest_patch(f)].adjacent;
    next &= within & ~reached;
    reached |= next;
    frontier = next;
  }
  return reached;
}

void grow_subsets(const PatchGraph& graph, PatchSet within, PatchSet current, int max_size,
                  std::vector<PatchSet>& out) {
  if (current != within) out.push_back(current);
  if (patch_count(current) >= max_size) return;
  const PatchSet candidates = adjacent_patches(graph, current) & within;
  for (PatchSet c = candidates; c != 0; c &= c - 1) {
    grow_subsets(graph, within, current | patch_bit(lowest_patch(c)), max_size, out);
  }
}

}  // namespace

PatchGraph build_patch_graph(const CosmosView& view, double min_adjacency_strength) {
  PatchGraph graph;
  const int n = static_cast<int>(view.patches.size());
  if (n > kMaxGraphPatches) {
    graph.status = PatchGraphStatus::kTooManyPatches;
    return graph;
  }
  double total_area_mm2 = 0;
  for (const Csmp& patch : view.patches) total_area_mm2 += std::max(patch.area_mm2, 0.0);

  graph.nodes.resize(n);
  for (int i = 0; i < n; ++i) {
    const Csmp& patch = view.patches[i];
    PatchNode& node = graph.nodes[i];
    node.id = patch.id;
    node.area_mm2 = std::max(patch.area_mm2, 0.0);
    // Patches without area (hand-made views) share the view equally.
    node.area_fraction = total_area_mm2 > 0 ? node.area_mm2 / total_area_mm2 : 1.0 / n;
    node.shape_index = patch.shape_index;
    node.curvedness_per_mm = patch.mean_curvedness_per_mm;
    node.planar = patch.planar;
    node.mean_normal = patch.mean_normal;
    node.centroid_mm = patch.centroid_mm;
    graph.all |= patch_bit(i);
  }
  for (int i = 0; i < n; ++i) {
    const Csmp& patch = view.patches[i];
    for (const PatchNeighbor& neighbor : patch.neighbors) {
      const int j = index_of_id(view, neighbor.patch);
      if (j < 0 || j == i) continue;
      graph.nodes[i].adjacent |= patch_bit(j);
      graph.nodes[j].adjacent |= patch_bit(i);
      const int smaller_pixels = std::min(patch.pixels, view.patches[j].pixels);
      // Views without pixel counts (hand-made) cannot rate an edge: every edge is strong.
      const bool strong =
          smaller_pixels <= 0 || neighbor.shared_boundary_pixels >=
                                     min_adjacency_strength * perimeter_estimate_px(smaller_pixels);
      if (strong) {
        graph.nodes[i].strongly_adjacent |= patch_bit(j);
        graph.nodes[j].strongly_adjacent |= patch_bit(i);
      }
    }
  }
  return graph;
}

PatchSet adjacent_patches(const PatchGraph& graph, PatchSet group) {
  PatchSet neighbors = 0;
  for (PatchSet g = group; g != 0; g &= g - 1) neighbors |= graph.nodes[lowest_patch(g)].adjacent;
  return neighbors & ~group;
}

bool groups_adjacent(const PatchGraph& graph, PatchSet a, PatchSet b) {
  return (adjacent_patches(graph, a) & b) != 0;
}

bool groups_strongly_adjacent(const PatchGraph& graph, PatchSet a, PatchSet b) {
  for (PatchSet g = a; g != 0; g &= g - 1) {
    if ((graph.nodes[lowest_patch(g)].strongly_adjacent & b) != 0) return true;
  }
  return false;
}

bool is_connected(const PatchGraph& graph, PatchSet group) {
  return group != 0 && component_of(graph, group, lowest_patch(group)) == group;
}

GroupSummary summarize_group(const PatchGraph& graph, PatchSet group) {
  GroupSummary summary;
  double curved_fraction = 0;
  double shape_index_sum = 0;
  double curvedness_sum = 0;
  double largest = 0;
  double planar = 0;
  for (PatchSet g = group; g != 0; g &= g - 1) {
    const PatchNode& node = graph.nodes[lowest_patch(g)];
    ++summary.patches;
    summary.area_fraction += node.area_fraction;
    summary.area_mm2 += node.area_mm2;
    largest = std::max(largest, node.area_fraction);
    curvedness_sum += node.area_fraction * node.curvedness_per_mm;
    if (node.planar) {
      planar += node.area_fraction;
    } else {
      curved_fraction += node.area_fraction;
      shape_index_sum += node.area_fraction * node.shape_index;
    }
  }
  if (summary.area_fraction > 0) {
    summary.largest_patch_fraction = largest / summary.area_fraction;
    summary.planar_fraction = planar / summary.area_fraction;
    summary.curvedness_per_mm = curvedness_sum / summary.area_fraction;
  } else if (summary.patches > 0) {
    // Zero-area patches: count them instead of weighing them.
    summary.largest_patch_fraction = 1.0 / summary.patches;
  }
  if (curved_fraction > 0) summary.shape_index = shape_index_sum / curved_fraction;
  return summary;
}

GroupSplit split_group(const PatchGraph& graph, PatchSet group, PatchSet selected) {
  GroupSplit split;
  split.components[0] = selected;
  split.count = 1;
  PatchSet rest = group & ~selected;
  while (rest != 0) {
    if (split.count == kMaxSplitComponents) return GroupSplit{};
    const PatchSet component = component_of(graph, rest, lowest_patch(rest));
    split.components[split.count++] = component;
    rest &= ~component;
  }
  return split;
}

std::vector<PatchSet> connected_subsets(const PatchGraph& graph, PatchSet within, int seed,
                                        int max_size) {
  std::vector<PatchSet> subsets;
  if (max_size < 1) return subsets;
  for (PatchSet s = within; s != 0; s &= s - 1) {
    const int start = lowest_patch(s);
    if (seed >= 0 && start != seed) continue;
    grow_subsets(graph, within, patch_bit(start), max_size, subsets);
  }
  std::sort(subsets.begin(), subsets.end(), [](PatchSet a, PatchSet b) {
    const int size_a = patch_count(a);
    const int size_b = patch_count(b);
    return size_a != size_b ? size_a < size_b : a < b;
  });
  subsets.erase(std::unique(subsets.begin(), subsets.end()), subsets.end());
  return subsets;
}

int largest_patch(const PatchGraph& graph, PatchSet group) {
  int best = -1;
  for (PatchSet g = group; g != 0; g &= g - 1) {
    const int i = lowest_patch(g);
    if (best < 0 || graph.nodes[i].area_mm2 > graph.nodes[best].area_mm2) best = i;
  }
  return best;
}

}  // namespace cosmos
