// Patch groups and the patch-group graph (§5.3.1): the graph built from a view's connectivity
// list V (Eq. 3.10), the strength of an adjacency (§5.4.3), and the group operations the
// matcher uses (adjacency, connectivity, summaries, splits, connected subsets), on hand-made
// views whose answers are counted by hand.
#include "core/matching/patch_group.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "tests/core/matching/hand_made_patch_graphs.hpp"

namespace cosmos {
namespace {

using testing::chain_view;
using testing::graph_patch;

PatchSet bits(std::initializer_list<int> indices) {
  PatchSet set = 0;
  for (int i : indices) set |= patch_bit(i);
  return set;
}

TEST(PatchGroup, GraphFollowsTheConnectivityListWithAreaShares) {
  const PatchGraph graph = build_patch_graph(chain_view(), 0.05);
  ASSERT_EQ(graph.status, PatchGraphStatus::kOk);
  ASSERT_EQ(graph.nodes.size(), 4u);
  EXPECT_EQ(graph.all, bits({0, 1, 2, 3}));
  EXPECT_EQ(graph.nodes[0].adjacent, bits({1}));
  EXPECT_EQ(graph.nodes[1].adjacent, bits({0, 2}));
  EXPECT_EQ(graph.nodes[2].adjacent, bits({1, 3}));
  EXPECT_EQ(graph.nodes[3].adjacent, bits({2}));
  // 30 shared pixels against 0.05 x 2 sqrt(pi 400) = 3.5: all strong.
  for (const PatchNode& node : graph.nodes) EXPECT_EQ(node.strongly_adjacent, node.adjacent);
  // Percentage areas (§5.3.3) of 300, 500, 200, 400 out of 1400 mm^2.
  EXPECT_DOUBLE_EQ(graph.nodes[0].area_fraction, 300.0 / 1400);
  EXPECT_DOUBLE_EQ(graph.nodes[1].area_fraction, 500.0 / 1400);
  EXPECT_DOUBLE_EQ(graph.nodes[3].area_fraction, 400.0 / 1400);
  EXPECT_EQ(graph.nodes[2].shape_index, 0.50);
  EXPECT_EQ(graph.nodes[2].curvedness_per_mm, 0.05);
}

TEST(PatchGroup, IdsAreMappedToIndicesAndOneSidedOrUnknownEntriesHandled) {
  CosmosView view;
  // Ids 10, 20, 30 at indices 0, 1, 2. V lists 10-20 on one side only, 20-30 on both, a
  // neighbour 99 that is not in the view, and 30 as its own neighbour.
  view.patches = {graph_patch(10, 100, 0.9, {{20, 30}, {99, 30}}),
                  graph_patch(20, 100, 0.5, {{30, 30}}),
                  graph_patch(30, 100, 0.1, {{20, 30}, {30, 30}})};
  const PatchGraph graph = build_patch_graph(view, 0.05);
  ASSERT_EQ(graph.nodes.size(), 3u);
  EXPECT_EQ(graph.nodes[0].id, 10);
  EXPECT_EQ(graph.nodes[2].id, 30);
  EXPECT_EQ(graph.nodes[0].adjacent, bits({1}));
  EXPECT_EQ(graph.nodes[1].adjacent, bits({0, 2}));
  EXPECT_EQ(graph.nodes[2].adjacent, bits({1}));
}

// §5.4.3: an adjacency is strong when the shared boundary reaches min_adjacency_strength of the
// smaller patch's disc perimeter 2 sqrt(pi N): for N = 400 that is 70.9 px, so at 0.05 the
// limit is 3.54 px.
TEST(PatchGroup, AdjacencyStrengthComparesTheSharedBoundaryWithThePerimeter) {
  CosmosView view;
  view.patches = {graph_patch(0, 100, 0.9, {{1, 3}, {2, 4}}, false, 400),
                  graph_patch(1, 100, 0.5, {}, false, 900),
                  graph_patch(2, 100, 0.1, {}, false, 400)};
  const PatchGraph graph = build_patch_graph(view, 0.05);
  EXPECT_EQ(graph.nodes[0].adjacent, bits({1, 2}));
  EXPECT_EQ(graph.nodes[0].strongly_adjacent, bits({2}));  // 3 px weak, 4 px strong
  EXPECT_EQ(graph.nodes[1].strongly_adjacent, 0u);
  EXPECT_EQ(graph.nodes[2].strongly_adjacent, bits({0}));
  EXPECT_TRUE(groups_adjacent(graph, bits({0}), bits({1})));
  EXPECT_FALSE(groups_strongly_adjacent(graph, bits({0}), bits({1})));
  EXPECT_TRUE(groups_strongly_adjacent(graph, bits({0, 1}), bits({2})));
  // Strength 0: every adjacency is strong (strict isomorphism).
  EXPECT_EQ(build_patch_graph(view, 0.0).nodes[0].strongly_adjacent, bits({1, 2}));
  // At 0.06 the limit is 4.25 px: both weak.
  EXPECT_EQ(build_patch_graph(view, 0.06).nodes[0].strongly_adjacent, 0u);
  // Patches without pixel counts cannot rate an edge: strong.
  view.patches[1].pixels = 0;
  EXPECT_EQ(build_patch_graph(view, 0.05).nodes[0].strongly_adjacent, bits({1, 2}));
}

TEST(PatchGroup, ViewsWithoutAreaShareItEquallyAndTooLargeViewsAreRefused) {
  CosmosView view = chain_view();
  for (Csmp& patch : view.patches) patch.area_mm2 = 0;
  const PatchGraph graph = build_patch_graph(view, 0.05);
  for (const PatchNode& node : graph.nodes) EXPECT_DOUBLE_EQ(node.area_fraction, 0.25);
  EXPECT_DOUBLE_EQ(summarize_group(graph, bits({0, 1})).largest_patch_fraction, 0.5);

  CosmosView large;
  for (int id = 0; id <= kMaxGraphPatches; ++id)
    large.patches.push_back(graph_patch(id, 1, 0.5, {}));
  const PatchGraph refused = build_patch_graph(large, 0.05);
  EXPECT_EQ(refused.status, PatchGraphStatus::kTooManyPatches);
  EXPECT_TRUE(refused.nodes.empty());
  large.patches.pop_back();
  EXPECT_EQ(build_patch_graph(large, 0.05).status, PatchGraphStatus::kOk);
}

TEST(PatchGroup, AdjacencyAndConnectivityOfGroups) {
  const PatchGraph graph = build_patch_graph(chain_view(), 0.05);
  EXPECT_EQ(adjacent_patches(graph, bits({1})), bits({0, 2}));
  EXPECT_EQ(adjacent_patches(graph, bits({1, 2})), bits({0, 3}));
  EXPECT_EQ(adjacent_patches(graph, graph.all), 0u);
  EXPECT_FALSE(groups_adjacent(graph, bits({0}), bits({2})));
  EXPECT_TRUE(groups_adjacent(graph, bits({0, 1}), bits({2})));
  EXPECT_TRUE(groups_adjacent(graph, bits({2}), bits({0, 1})));
  EXPECT_TRUE(is_connected(graph, bits({1, 2, 3})));
  EXPECT_FALSE(is_connected(graph, bits({0, 2})));
  EXPECT_FALSE(is_connected(graph, bits({0, 1, 3})));
  EXPECT_FALSE(is_connected(graph, 0));
  EXPECT_EQ(largest_patch(graph, graph.all), 1);
  EXPECT_EQ(largest_patch(graph, bits({0, 2, 3})), 3);
}

// The area-weighted attributes §5.3.3 compares, for the ridge (500 mm^2, S_I 0.75) and the
// saddle (200 mm^2, S_I 0.5) together; and a group with a planar patch, whose symbolic S_I
// stays out of the mean.
TEST(PatchGroup, SummaryIsAreaWeightedAndLeavesPlanarShapeIndexOut) {
  const PatchGraph graph = build_patch_graph(chain_view(), 0.05);
  const GroupSummary middle = summarize_group(graph, bits({1, 2}));
  EXPECT_EQ(middle.patches, 2);
  EXPECT_DOUBLE_EQ(middle.area_fraction, 700.0 / 1400);
  EXPECT_DOUBLE_EQ(middle.area_mm2, 700.0);
  EXPECT_DOUBLE_EQ(middle.largest_patch_fraction, 500.0 / 700);
  EXPECT_DOUBLE_EQ(middle.planar_fraction, 0.0);
  EXPECT_NEAR(middle.shape_index, (500 * 0.75 + 200 * 0.50) / 700, 1e-12);
  EXPECT_NEAR(middle.curvedness_per_mm, 0.05, 1e-12);

  CosmosView view = chain_view();
  view.patches[1] = graph_patch(1, 500, 0, {{0, 30}, {2, 30}}, true);
  const GroupSummary with_plane = summarize_group(build_patch_graph(view, 0.05), bits({0, 1, 2}));
  EXPECT_DOUBLE_EQ(with_plane.planar_fraction, 500.0 / 1000);
  EXPECT_NEAR(with_plane.shape_index, (300 * 0.95 + 200 * 0.50) / 500, 1e-12);
  EXPECT_NEAR(with_plane.curvedness_per_mm, 0.05 * 500 / 1000, 1e-12);
}

TEST(PatchGroup, SplitGivesTheSelectedGroupThenTheComponentsOfTheRest) {
  const PatchGraph graph = build_patch_graph(chain_view(), 0.05);
  const GroupSplit split = split_group(graph, graph.all, patch_bit(1));
  ASSERT_EQ(split.count, 3);
  EXPECT_EQ(split.components[0], patch_bit(1));
  EXPECT_EQ(split.components[1], patch_bit(0));
  EXPECT_EQ(split.components[2], patch_bit(2) | patch_bit(3));
  // Connected strict subsets around patch 1 of at most 2 patches: {1}, {0,1}, {1,2}.
  const std::vector<PatchSet> subsets = connected_subsets(graph, graph.all, 1, 2);
  EXPECT_EQ(subsets, (std::vector<PatchSet>{patch_bit(1), patch_bit(0) | patch_bit(1),
                                            patch_bit(1) | patch_bit(2)}));
}

TEST(PatchGroup, ConnectedSubsetsComeSmallestFirstThenByMask) {
  const PatchGraph graph = build_patch_graph(chain_view(), 0.05);
  // Any seed, up to 2 patches: the four singletons, then the three links of the chain.
  EXPECT_EQ(connected_subsets(graph, graph.all, -1, 2),
            (std::vector<PatchSet>{bits({0}), bits({1}), bits({2}), bits({3}), bits({0, 1}),
                                   bits({1, 2}), bits({2, 3})}));
  // The whole group is not a strict subset of itself; the two triples are.
  const std::vector<PatchSet> up_to_four = connected_subsets(graph, graph.all, -1, 4);
  EXPECT_EQ(up_to_four.size(), 4u + 3u + 2u);
  EXPECT_EQ(up_to_four.back(), bits({1, 2, 3}));
  // Within {0, 1, 3} patch 3 is cut off from 0: only {0}, {1}, {3}, {0, 1}.
  EXPECT_EQ(connected_subsets(graph, bits({0, 1, 3}), -1, 3),
            (std::vector<PatchSet>{bits({0}), bits({1}), bits({3}), bits({0, 1})}));
  EXPECT_TRUE(connected_subsets(graph, graph.all, 1, 0).empty());
}

// A star of 8 leaves: taking its centre leaves 8 components, more than a split holds.
TEST(PatchGroup, SplitIntoTooManyComponentsIsRefused) {
  CosmosView star;
  std::vector<PatchNeighbor> leaves;
  for (int id = 1; id <= 8; ++id) leaves.push_back({id, 30});
  star.patches.push_back(graph_patch(0, 100, 0.5, leaves));
  for (int id = 1; id <= 8; ++id) star.patches.push_back(graph_patch(id, 10, 0.9, {{0, 30}}));
  const PatchGraph graph = build_patch_graph(star, 0.05);
  EXPECT_EQ(split_group(graph, graph.all, patch_bit(0)).count, 0);
  // Without leaf 8, the 7 remaining ones still fit.
  const GroupSplit seven = split_group(graph, graph.all & ~patch_bit(8), patch_bit(0));
  ASSERT_EQ(seven.count, 8);
  EXPECT_EQ(seven.components[7], patch_bit(7));
}

}  // namespace
}  // namespace cosmos
