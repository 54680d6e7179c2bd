#pragma once
// The feasibility test of a correspondence (§5.3.1): a set of MappedPairs is a feasible
// correspondence when it covers both views, each patch in exactly one group, its groups are
// connected sets of patches, and the two patch-group graphs are isomorphic under it, i.e.
// every adjacency between two groups on one side exists between their partners on the
// other. Adjacencies below the strength limit of §5.4.3 (see patch_group.hpp) need not be
// matched. The matcher keeps its candidates feasible by construction; this independent
// check is for callers and tests.
#include <vector>

#include "core/matching/patch_group_matching.hpp"
#include "core/representation/cosmos_view.hpp"

namespace cosmos {

// The single all-inclusive pair (the trivial correspondence) is always feasible, also for
// empty views and disconnected ones. False for unknown or repeated patch ids, for patches
// left out, and for views over kMaxGraphPatches.
bool is_feasible_correspondence(const CosmosView& scene, const CosmosView& model,
                                const std::vector<MappedPair>& pairs,
                                double min_adjacency_strength);

}  // namespace cosmos
