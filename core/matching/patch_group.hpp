#pragma once
// Patch groups and patch-group graphs (§5.3.1). The region adjacency graph of a view has one
// vertex per CSMP and one edge per pair of directly connected CSMPs (the connectivity list V,
// Eq. 3.10). A patch-group is a connected set of CSMPs; two groups are directly connected
// iff some patch of one is directly connected to some patch of the other.
//
// Views hold at most kMaxGraphPatches CSMPs here, so that a group is one 64-bit mask and
// splitting, connectivity and adjacency tests are a few bit operations: the adaptive
// segmentation of §5.4.3 yields at most 15 patches, far below the limit.
//
// Edge strength (§5.4.3, last paragraph: "allowing violations of the connectivity to a small
// degree depending on the strength of the adjacency as determined by the number of boundary
// pixels that are shared"): an adjacency is *strong* when the shared boundary is at least a
// given fraction of the perimeter of the smaller patch, estimated as that of a disc of the
// same pixel count (2 sqrt(pi N)). Weak adjacencies still connect patches into groups, but
// the isomorphism test does not require them to exist on the other side.
#include <Eigen/Core>
#include <array>
#include <bit>
#include <cstdint>
#include <vector>

#include "core/representation/cosmos_view.hpp"

namespace cosmos {

using PatchSet = std::uint64_t;  // bit i: the patch at index i of the view
inline constexpr int kMaxGraphPatches = 64;

inline int patch_count(PatchSet set) { return std::popcount(set); }
inline PatchSet patch_bit(int index) { return PatchSet{1} << index; }
inline int lowest_patch(PatchSet set) { return std::countr_zero(set); }

struct PatchNode {
  int id = 0;  // Csmp::id
  double area_mm2 = 0;
  // Share of the segmented area of the view (the "percentage area" of §5.3.3): the patches'
  // shares add up to exactly 1, so the weights of a complete correspondence do too.
  double area_fraction = 0;
  double shape_index = 0;
  double curvedness_per_mm = 0;
  bool planar = false;
  Eigen::Vector3d mean_normal = Eigen::Vector3d::UnitZ();
  Eigen::Vector3d centroid_mm = Eigen::Vector3d::Zero();
  PatchSet adjacent = 0;           // V(P) as indices, symmetric
  PatchSet strongly_adjacent = 0;  // the subset of strong adjacencies, symmetric
};

enum class PatchGraphStatus { kOk, kTooManyPatches };

struct PatchGraph {
  PatchGraphStatus status = PatchGraphStatus::kOk;
  std::vector<PatchNode> nodes;  // in the view's patch order
  PatchSet all = 0;
};

// Neighbour ids not present in the view are ignored; a one-sided entry in V counts for both
// patches. Views with more than kMaxGraphPatches patches give status too_many_patches and no
// nodes. min_adjacency_strength = 0 makes every adjacency strong (strict isomorphism).
PatchGraph build_patch_graph(const CosmosView& view, double min_adjacency_strength);

// The patches directly connected to the group and not in it.
PatchSet adjacent_patches(const PatchGraph& graph, PatchSet group);
bool groups_adjacent(const PatchGraph& graph, PatchSet a, PatchSet b);
bool groups_strongly_adjacent(const PatchGraph& graph, PatchSet a, PatchSet b);
bool is_connected(const PatchGraph& graph, PatchSet group);

// The attributes of a patch-group that §5.3.3 compares, all area-weighted.
struct GroupSummary {
  int patches = 0;
  double area_fraction = 0;
  double area_mm2 = 0;
  double largest_patch_fraction = 1;  // area share of the group's largest patch
  double planar_fraction = 0;         // area share of planar patches
  double shape_index = 0;             // mean over the curved patches only (planar S_I is symbolic)
  double curvedness_per_mm = 0;       // mean over all patches
};
GroupSummary summarize_group(const PatchGraph& graph, PatchSet group);

// §5.3.2 split: choosing a connected strict subset `selected` of `group` splits the group
// into `selected` and the connected components of the rest. components[0] = selected, the
// others ordered by their lowest patch index.
inline constexpr int kMaxSplitComponents = 8;
struct GroupSplit {
  int count = 0;  // 0 when the rest has more than kMaxSplitComponents - 1 components
  std::array<PatchSet, kMaxSplitComponents> components{};
};
GroupSplit split_group(const PatchGraph& graph, PatchSet group, PatchSet selected);

// Every connected subset of `within` with at most max_size patches that contains `seed`
// (or any seed when seed < 0) and is a strict subset of `within`, ordered by size, then by
// mask value: singletons first, as the loops of `refine` (§5.3.2) try them.
std::vector<PatchSet> connected_subsets(const PatchGraph& graph, PatchSet within, int seed,
                                        int max_size);

// The patch of the group with the largest area; ties go to the lowest index.
int largest_patch(const PatchGraph& graph, PatchSet group);

}  // namespace cosmos
