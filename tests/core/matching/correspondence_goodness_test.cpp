// The goodness of a correspondence (§5.3.3): each MappedPair's area, shape-index, curvedness and
// neighbour similarities, its fineness, and the area-weighted quality, all computed by hand
// from the formulas of correspondence_goodness.hpp.
#include "core/matching/correspondence_goodness.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/matching/patch_group.hpp"
#include "tests/core/matching/hand_made_patch_graphs.hpp"

namespace cosmos {
namespace {

using testing::chain_view;
using testing::graph_patch;

TEST(CorrespondenceGoodness, AreaGoodnessIsTheThesisRatioOfPercentageAreas) {
  GroupDescriptor scene;
  GroupDescriptor model;
  scene.group.area_fraction = 0.3;
  model.group.area_fraction = 0.1;
  const PairGoodness g = evaluate_pair(scene, model, GoodnessParameters{});
  EXPECT_NEAR(g.area, 1.0 - 0.2 / 0.4, 1e-12);  // §5.3.3: 1 - |a1 - a2| / (a1 + a2)
  EXPECT_NEAR(g.weight, 0.2, 1e-12);
  model.group.shape_index = 0.125;  // half the default scale away
  EXPECT_NEAR(evaluate_pair(scene, model, GoodnessParameters{}).shape_index, 0.5, 1e-12);
}

// Every factor of one pair, by hand:
//   area        0.3 vs 0.2:                     1 - 0.1 / 0.5                = 0.8
//   shape index S_I 0.60 vs 0.65, planar 0.2 vs 0.5: (1 - 0.05 / 0.25) (1 - 0.3) = 0.56
//   curvedness  0.05 vs 0.03 (floor 0.01):      1 - 0.02 / 0.09
//   neighbour   2 vs 3 patches: 1 - 1/5 = 0.8; their S_I 0.40 vs 0.45 (no planar): 0.8
//   fineness    sqrt(0.5 * 0.8)
TEST(CorrespondenceGoodness, EveryFactorOfAPairByHand) {
  GroupDescriptor scene, model;
  scene.group = {.patches = 2,
                 .area_fraction = 0.3,
                 .largest_patch_fraction = 0.5,
                 .planar_fraction = 0.2,
                 .shape_index = 0.60,
                 .curvedness_per_mm = 0.05};
  model.group = {.patches = 3,
                 .area_fraction = 0.2,
                 .largest_patch_fraction = 0.8,
                 .planar_fraction = 0.5,
                 .shape_index = 0.65,
                 .curvedness_per_mm = 0.03};
  scene.neighbors.shape_index = 0.40;
  model.neighbors.shape_index = 0.45;
  scene.neighbor_patches = 2;
  model.neighbor_patches = 3;
  const PairGoodness g = evaluate_pair(scene, model, GoodnessParameters{});
  EXPECT_NEAR(g.area, 0.8, 1e-12);
  EXPECT_NEAR(g.shape_index, 0.8 * 0.7, 1e-12);
  EXPECT_NEAR(g.curvedness, 1.0 - 0.02 / 0.09, 1e-12);
  EXPECT_NEAR(g.neighbor, 0.8 * 0.8, 1e-12);
  EXPECT_NEAR(g.goodness, g.area * g.shape_index * g.curvedness * g.neighbor, 1e-15);
  EXPECT_NEAR(g.goodness, 0.8 * 0.56 * (1.0 - 0.02 / 0.09) * 0.64, 1e-12);
  EXPECT_NEAR(g.fineness, std::sqrt(0.4), 1e-12);
  EXPECT_NEAR(g.weight, 0.25, 1e-12);
  EXPECT_NEAR(g.score, g.goodness * std::sqrt(0.4), 1e-12);
  // The coarseness exponent raises the fineness: 2 gives 0.5 * 0.8.
  GoodnessParameters squared;
  squared.coarseness_exponent = 2.0;
  EXPECT_NEAR(evaluate_pair(scene, model, squared).score, g.goodness * 0.4, 1e-12);
  EXPECT_NEAR(coarseness_factor(scene.group, model.group, squared), 0.4, 1e-12);
  // A wider S_I scale forgives more: 1 - 0.05 / 0.5.
  GoodnessParameters wide;
  wide.shape_index_scale = 0.5;
  EXPECT_NEAR(evaluate_pair(scene, model, wide).shape_index, 0.9 * 0.7, 1e-12);
}

TEST(CorrespondenceGoodness, PlanarAndMissingNeighboursScoreByTheirShares) {
  GroupDescriptor planar, curved;
  planar.group.planar_fraction = 1.0;  // symbolic S_I: no S_I closeness, only the shares
  planar.group.shape_index = 0.0;
  curved.group.planar_fraction = 0.25;
  curved.group.shape_index = 0.9;
  EXPECT_NEAR(evaluate_pair(planar, curved, GoodnessParameters{}).shape_index, 0.25, 1e-12);
  // S_I more than the scale apart: no similarity at all.
  GroupDescriptor cap, cup;
  cap.group.shape_index = 0.95;
  cup.group.shape_index = 0.05;
  EXPECT_EQ(evaluate_pair(cap, cup, GoodnessParameters{}).shape_index, 0.0);
  // A group with neighbours against one without: the count term is 1 - 2 / 2 = 0.
  cap.neighbor_patches = 2;
  cap.neighbors.shape_index = 0.5;
  const PairGoodness lonely = evaluate_pair(cap, cap, GoodnessParameters{});
  EXPECT_NEAR(lonely.neighbor, 1.0, 1e-12);
  GroupDescriptor alone = cap;
  alone.neighbor_patches = 0;
  EXPECT_EQ(evaluate_pair(cap, alone, GoodnessParameters{}).neighbor, 0.0);
  // Two flat groups (curvedness 0 on both sides) are alike, not 0/0.
  EXPECT_EQ(evaluate_pair(GroupDescriptor{}, GroupDescriptor{}, GoodnessParameters{}).curvedness,
            1.0);
}

TEST(CorrespondenceGoodness, PlanarPatchesMatchOnlyGroupsWithSomePlanarArea) {
  EXPECT_TRUE(planar_compatible(GroupSummary{.planar_fraction = 1.0},
                                GroupSummary{.planar_fraction = 0.4}));
  EXPECT_FALSE(planar_compatible(GroupSummary{.planar_fraction = 1.0},
                                 GroupSummary{.planar_fraction = 0.0}));
  EXPECT_FALSE(planar_compatible(GroupSummary{.planar_fraction = 0.0},
                                 GroupSummary{.planar_fraction = 1.0}));
  EXPECT_TRUE(planar_compatible(GroupSummary{.planar_fraction = 0.0},
                                GroupSummary{.planar_fraction = 0.3}));
}

// describe_group on the chain 0-1-2-3: the ridge's neighbours are the cap (300 mm^2, S_I 0.95)
// and the saddle (200 mm^2, S_I 0.50).
TEST(CorrespondenceGoodness, DescriptorHoldsTheGroupAndTheRingAroundIt) {
  const PatchGraph graph = build_patch_graph(chain_view(), 0.05);
  const GroupDescriptor ridge = describe_group(graph, patch_bit(1));
  EXPECT_EQ(ridge.group.patches, 1);
  EXPECT_DOUBLE_EQ(ridge.group.shape_index, 0.75);
  EXPECT_EQ(ridge.neighbor_patches, 2);
  EXPECT_NEAR(ridge.neighbors.shape_index, (300 * 0.95 + 200 * 0.50) / 500, 1e-12);
  const GroupDescriptor end = describe_group(graph, patch_bit(3));
  EXPECT_EQ(end.neighbor_patches, 1);
  EXPECT_DOUBLE_EQ(end.neighbors.shape_index, 0.50);
}

TEST(CorrespondenceGoodness, TheTrivialCorrespondenceOfIdenticalViewsScoresBelowTheFineOne) {
  const PatchGraph graph = build_patch_graph(chain_view(), 0.05);
  const std::vector<GroupPair> trivial = {{graph.all, graph.all}};
  std::vector<GroupPair> fine;
  for (int i = 0; i < 4; ++i) fine.push_back({patch_bit(i), patch_bit(i)});
  const double trivial_quality =
      correspondence_quality(graph, graph, trivial, GoodnessParameters{});
  const double fine_quality = correspondence_quality(graph, graph, fine, GoodnessParameters{});
  EXPECT_NEAR(fine_quality, 1.0, 1e-12);
  // Equally good, but the trivial pair lumps four patches: fineness = largest share 500/1400.
  EXPECT_NEAR(trivial_quality, 500.0 / 1400.0, 1e-12);
}

// Two pairs of identical groups, {0, 1} and {2, 3}: goodness 1 each, so the quality is the
// weighted fineness (800 / 1400) (500 / 800) + (600 / 1400) (400 / 600) = 900 / 1400.
TEST(CorrespondenceGoodness, QualityIsTheAreaWeightedSumOfThePairScores) {
  const PatchGraph graph = build_patch_graph(chain_view(), 0.05);
  const std::vector<GroupPair> halves = {
      {patch_bit(0) | patch_bit(1), patch_bit(0) | patch_bit(1)},
      {patch_bit(2) | patch_bit(3), patch_bit(2) | patch_bit(3)}};
  EXPECT_NEAR(correspondence_quality(graph, graph, halves, GoodnessParameters{}), 900.0 / 1400,
              1e-12);
  // Against a chain whose ridge shrank to 100 mm^2 the first pair loses area similarity.
  CosmosView shrunk = chain_view();
  shrunk.patches[1] = graph_patch(1, 100, 0.75, {{0, 30}, {2, 30}});
  const PatchGraph other = build_patch_graph(shrunk, 0.05);
  EXPECT_LT(correspondence_quality(graph, other, halves, GoodnessParameters{}), 900.0 / 1400);
}

}  // namespace
}  // namespace cosmos
