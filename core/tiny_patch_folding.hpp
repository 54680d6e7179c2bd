#pragma once
// Folding of patches below the minimum area into their most similar neighbour (§5.4.3), part
// of CSMP segmentation: tiny patches join an adjacent significant patch of nearest mean shape
// index first (repeatedly, as folding makes more neighbours significant), so a ramp of thin
// strips between two patches splits between them instead of gluing itself into one more
// patch; then tiny clusters join among themselves; what is still tiny and alone is dropped.
#include <vector>

#include "core/region_merge_queue.hpp"
#include "core/shape_seeds.hpp"

namespace cosmos {

// The queue's regions are the seeds, in order. Returns, per region index, whether that root
// was dropped as an island of noise.
std::vector<bool> fold_tiny_patches(const ShapeSeeds& seeds, RegionMergeQueue& regions,
                                    double min_area_mm2);

}  // namespace cosmos
