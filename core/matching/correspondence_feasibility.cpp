#include "core/matching/correspondence_feasibility.hpp"

#include <algorithm>

#include "core/matching/correspondence_goodness.hpp"
#include "core/matching/patch_group.hpp"

namespace cosmos {
namespace {

// The ids of a group as a mask; false when an id is unknown or repeated.
bool mask_of(const PatchGraph& graph, const std::vector<int>& ids, PatchSet& mask) {
  mask = 0;
  for (int id : ids) {
    const auto node = std::find_if(graph.nodes.begin(), graph.nodes.end(),
                                   [id](const PatchNode& n) { return n.id == id; });
    if (node == graph.nodes.end()) return false;
    const PatchSet bit = patch_bit(static_cast<int>(node - graph.nodes.begin()));
    if ((mask & bit) != 0) return false;
    mask |= bit;
  }
  return true;
}

}  // namespace

bool is_feasible_correspondence(const CosmosView& scene, const CosmosView& model,
                                const std::vector<MappedPair>& pairs,
                                double min_adjacency_strength) {
  const PatchGraph scene_graph = build_patch_graph(scene, min_adjacency_strength);
  const PatchGraph model_graph = build_patch_graph(model, min_adjacency_strength);
  if (scene_graph.status != PatchGraphStatus::kOk || model_graph.status != PatchGraphStatus::kOk)
    return false;
  if (pairs.empty()) return false;

  std::vector<GroupPair> groups(pairs.size());
  PatchSet scene_covered = 0;
  PatchSet model_covered = 0;
  for (std::size_t p = 0; p < pairs.size(); ++p) {
    if (!mask_of(scene_graph, pairs[p].scene_patches, groups[p].scene)) return false;
    if (!mask_of(model_graph, pairs[p].model_patches, groups[p].model)) return false;
    if ((scene_covered & groups[p].scene) != 0 || (model_covered & groups[p].model) != 0)
      return false;
    scene_covered |= groups[p].scene;
    model_covered |= groups[p].model;
  }
  if (scene_covered != scene_graph.all || model_covered != model_graph.all) return false;
  if (pairs.size() == 1) return true;  // the trivial correspondence (§5.3.1)

  for (const GroupPair& g : groups) {
    if (!is_connected(scene_graph, g.scene) || !is_connected(model_graph, g.model)) return false;
  }
  for (std::size_t p = 0; p < groups.size(); ++p) {
    for (std::size_t q = p + 1; q < groups.size(); ++q) {
      const bool scene_strong =
          groups_strongly_adjacent(scene_graph, groups[p].scene, groups[q].scene);
      const bool model_strong =
          groups_strongly_adjacent(model_graph, groups[p].model, groups[q].model);
      const bool scene_any = groups_adjacent(scene_graph, groups[p].scene, groups[q].scene);
      const bool model_any = groups_adjacent(model_graph, groups[p].model, groups[q].model);
      if ((scene_strong && !model_any) || (model_strong && !scene_any)) return false;
    }
  }
  return true;
}

}  // namespace cosmos
