// The feasibility test of a correspondence (§5.3.1): the pairs cover both views, each patch in
// exactly one group, every group is connected, and the patch-group graphs are isomorphic under
// the pairing (weak adjacencies, §5.4.3, need not be matched). Hand-made chains with one
// feasible correspondence after another made infeasible in each way the test looks at.
#include "core/matching/correspondence_feasibility.hpp"

#include <gtest/gtest.h>

#include <utility>
#include <vector>

#include "core/matching/patch_group.hpp"
#include "tests/core/matching/hand_made_patch_graphs.hpp"
#include "tests/core/matching_fixture.hpp"

namespace cosmos {
namespace {

using testing::analytic_view;
using testing::chain_view;
using testing::graph_patch;
using testing::relief_view;

constexpr double kStrength = 0.05;

MappedPair pair_of(std::vector<int> scene, std::vector<int> model) {
  return {std::move(scene), std::move(model), {}};
}

std::vector<int> all_ids(const CosmosView& view) {
  std::vector<int> ids;
  for (const Csmp& patch : view.patches) ids.push_back(patch.id);
  return ids;
}

TEST(CorrespondenceFeasibility, IsomorphicGroupingsOfTwoChainsAreFeasible) {
  const CosmosView chain = chain_view();
  // Patch for patch.
  EXPECT_TRUE(is_feasible_correspondence(
      chain, chain, {pair_of({0}, {0}), pair_of({1}, {1}), pair_of({2}, {2}), pair_of({3}, {3})},
      kStrength));
  // Groups of different sizes on the two sides: {0, 1} - {2, 3} against {0} - {1, 2, 3}; both
  // graphs are one edge.
  EXPECT_TRUE(is_feasible_correspondence(
      chain, chain, {pair_of({0, 1}, {0}), pair_of({2, 3}, {1, 2, 3})}, kStrength));
  // The chain reversed: 0-1-2-3 onto 3-2-1-0.
  EXPECT_TRUE(is_feasible_correspondence(
      chain, chain, {pair_of({0}, {3}), pair_of({1}, {2}), pair_of({2}, {1}), pair_of({3}, {0})},
      kStrength));
}

TEST(CorrespondenceFeasibility, EachWayOfBreakingTheCorrespondenceIsInfeasible) {
  const CosmosView chain = chain_view();
  const auto feasible = [&](const std::vector<MappedPair>& pairs) {
    return is_feasible_correspondence(chain, chain, pairs, kStrength);
  };
  // Scene patch 3 left out.
  EXPECT_FALSE(feasible({pair_of({0}, {0}), pair_of({1}, {1}), pair_of({2}, {2, 3})}));
  // Model patch 3 in two groups.
  EXPECT_FALSE(feasible({pair_of({0, 1}, {0, 1, 3}), pair_of({2, 3}, {2, 3})}));
  // A patch repeated within a group, and an id the view does not have.
  EXPECT_FALSE(feasible({pair_of({0, 1, 1}, {0, 1}), pair_of({2, 3}, {2, 3})}));
  EXPECT_FALSE(feasible({pair_of({0, 1}, {0, 1}), pair_of({2, 3, 7}, {2, 3})}));
  // A group that is not connected: {0, 2} on both sides.
  EXPECT_FALSE(feasible({pair_of({0, 2}, {0, 2}), pair_of({1}, {1}), pair_of({3}, {3})}));
  // Not isomorphic: scene 0-1 adjacent, their partners model 0 and 2 are not.
  EXPECT_FALSE(
      feasible({pair_of({0}, {0}), pair_of({1}, {2}), pair_of({2}, {1}), pair_of({3}, {3})}));
  // No pairs at all.
  EXPECT_FALSE(feasible({}));
}

// The scene chain has an extra contact 0-3 of 2 boundary pixels: at 400 px a patch's perimeter
// is about 71 px, so 2 px is weak at strength 0.05 and need not exist in the model.
TEST(CorrespondenceFeasibility, WeakAdjacenciesNeedNotBeMatchedStrongOnesMust) {
  CosmosView scene = chain_view();
  scene.patches[0].neighbors.push_back({3, 2});
  const CosmosView model = chain_view();
  const std::vector<MappedPair> patch_for_patch = {pair_of({0}, {0}), pair_of({1}, {1}),
                                                   pair_of({2}, {2}), pair_of({3}, {3})};
  EXPECT_TRUE(is_feasible_correspondence(scene, model, patch_for_patch, 0.05));
  EXPECT_FALSE(is_feasible_correspondence(scene, model, patch_for_patch, 0.0));
  // The same contact of 30 pixels is strong: now it must be matched.
  scene.patches[0].neighbors.back().shared_boundary_pixels = 30;
  EXPECT_FALSE(is_feasible_correspondence(scene, model, patch_for_patch, 0.05));
  // ... unless the model side has it as well.
  CosmosView ring = model;
  ring.patches[3].neighbors.push_back({0, 30});
  EXPECT_TRUE(is_feasible_correspondence(scene, ring, patch_for_patch, 0.05));
}

TEST(CorrespondenceFeasibility, TheTrivialCorrespondenceIsAlwaysFeasible) {
  // Also for two patches that touch nowhere, and for empty views.
  CosmosView apart;
  apart.patches = {graph_patch(4, 100, 0.9, {}), graph_patch(8, 100, 0.1, {})};
  EXPECT_TRUE(
      is_feasible_correspondence(apart, chain_view(), {pair_of({4, 8}, {0, 1, 2, 3})}, 0.0));
  EXPECT_FALSE(is_feasible_correspondence(apart, chain_view(),
                                          {pair_of({4}, {0, 1}), pair_of({8}, {2, 3})}, 0.0))
      << "split into two groups, the scene's are not adjacent but the model's are";
  EXPECT_TRUE(is_feasible_correspondence(CosmosView{}, CosmosView{}, {pair_of({}, {})}, 0.0));

  const CosmosView& relief = relief_view(0).view;
  for (AnalyticShape shape :
       {AnalyticShape::kCapsule, AnalyticShape::kTorus, AnalyticShape::kBoxCorner}) {
    const CosmosView& view = analytic_view(shape, 0).view;
    EXPECT_TRUE(
        is_feasible_correspondence(view, relief, {pair_of(all_ids(view), all_ids(relief))}, 0.0));
    EXPECT_FALSE(is_feasible_correspondence(view, relief, {pair_of(all_ids(view), {})}, 0.0))
        << "model not covered";
  }
}

TEST(CorrespondenceFeasibility, ViewsBeyondTheGraphLimitAreNeverFeasible) {
  CosmosView large;
  for (int id = 0; id <= kMaxGraphPatches; ++id)
    large.patches.push_back(graph_patch(id, 1, 0.5, {}));
  EXPECT_FALSE(is_feasible_correspondence(large, large, {pair_of(all_ids(large), all_ids(large))},
                                          kStrength));
}

}  // namespace
}  // namespace cosmos
