#pragma once
// Folding of patches below the minimum area into their most similar neighbour (§5.4.3), part
// of CSMP segmentation: tiny patches join an adjacent significant patch of nearest mean shape
// index first (repeatedly, as folding makes more neighbours significant), so a ramp of thin
// strips between two patches splits between them instead of gluing itself into one more
// patch; then tiny clusters join among themselves; what is still tiny and alone is dropped.
#include <cstdint>
#include <utility>
#include <vector>

#include "core/segmentation/region_merge_queue.hpp"
#include "core/segmentation/shape_seeds.hpp"

namespace cosmos {

// Pairs of groups joined by a growing edge: at first the seeds' adjacency (seeds.adjacent).
// Each call rewrites them as pairs of the groups at its start, in the same order, without
// those inside one group, so later calls on coarser groups skip what no longer matters.
using GroupPairs = std::vector<std::pair<std::int32_t, std::int32_t>>;

// The queue's regions are the seeds, in order. Returns, per region index, whether that root
// was dropped as an island of noise.
std::vector<bool> fold_tiny_patches(const ShapeSeeds& seeds, GroupPairs& group_pairs,
                                    RegionMergeQueue& regions, double min_area_mm2);

}  // namespace cosmos
