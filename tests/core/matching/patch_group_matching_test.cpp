// COSMOS view verification (§5.3.2): patch-group graph matching of a scene view against a
// model view, on hand-made graphs, the analytic capsule and the free-form relief.
#include "core/matching/patch_group_matching.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <vector>

#include "core/matching/correspondence_feasibility.hpp"
#include "tests/core/matching/hand_made_patch_graphs.hpp"
#include "tests/core/matching_fixture.hpp"

namespace cosmos {
namespace {

using testing::analytic_view;
using testing::chain_view;
using testing::graph_patch;
using testing::LabelledView;
using testing::relief_view;

// A 3 x 5 grid of 15 patches with 4-neighbour adjacency and varied attributes; the patch at
// grid cell k gets id permutation[k], and jitter perturbs area and shape index a little.
CosmosView grid_view(const std::array<int, 15>& permutation, double jitter) {
  constexpr int kRows = 3;
  constexpr int kColumns = 5;
  CosmosView view;
  view.patches.resize(15);
  for (int row = 0; row < kRows; ++row) {
    for (int column = 0; column < kColumns; ++column) {
      const int k = row * kColumns + column;
      std::vector<PatchNeighbor> neighbors;
      if (row > 0) neighbors.push_back({permutation[k - kColumns], 20});
      if (row + 1 < kRows) neighbors.push_back({permutation[k + kColumns], 20});
      if (column > 0) neighbors.push_back({permutation[k - 1], 20});
      if (column + 1 < kColumns) neighbors.push_back({permutation[k + 1], 20});
      const double wiggle = jitter * std::sin(3.7 * k + 1.0);
      view.patches[permutation[k]] =
          graph_patch(permutation[k], 100 + 37 * ((k * 7) % 5) + 10 * wiggle,
                      0.1 + 0.1 * ((k * 5) % 9) + 0.01 * wiggle, std::move(neighbors));
    }
  }
  return view;
}

constexpr std::array<int, 15> kIdentity = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14};
constexpr std::array<int, 15> kShuffled = {9, 3, 14, 0, 7, 12, 5, 1, 10, 6, 13, 2, 8, 11, 4};

// The truth region covering most of a group's area.
int group_region(const LabelledView& labelled, const std::vector<int>& ids) {
  std::map<int, double> area_of_region;
  for (int id : ids) {
    for (const Csmp& patch : labelled.view.patches) {
      if (patch.id == id) area_of_region[labelled.region_of_patch.at(id)] += patch.area_mm2;
    }
  }
  return std::max_element(area_of_region.begin(), area_of_region.end(),
                          [](const auto& a, const auto& b) { return a.second < b.second; })
      ->first;
}

bool feasible(const CosmosView& scene, const CosmosView& model, const PatchGroupMatch& match) {
  return is_feasible_correspondence(scene, model, match.pairs,
                                    PatchGroupMatchParameters{}.min_adjacency_strength);
}

TEST(PatchGroupMatching, EmptyViewsGiveTheTrivialCorrespondence) {
  const CosmosView empty;
  for (const auto& [scene, model] : {std::pair{empty, empty}, std::pair{empty, chain_view()}}) {
    const PatchGroupMatch match = match_patch_groups(scene, model);
    EXPECT_EQ(match.status, PatchGroupMatchStatus::kEmptyView);
    ASSERT_EQ(match.pairs.size(), 1u);
    EXPECT_EQ(match.pairs[0].model_patches.size(), model.patches.size());
    EXPECT_EQ(match.score, 0.0);
    EXPECT_TRUE(feasible(scene, model, match));
  }
}

TEST(PatchGroupMatching, OnePatchViewsGiveOnePairScoredByItsGoodness) {
  CosmosView scene;
  CosmosView model;
  scene.patches = {graph_patch(4, 100, 0.80, {})};
  model.patches = {graph_patch(9, 250, 0.70, {})};
  const PatchGroupMatch match = match_patch_groups(scene, model);
  EXPECT_EQ(match.status, PatchGroupMatchStatus::kOk);
  ASSERT_EQ(match.pairs.size(), 1u);
  EXPECT_EQ(match.pairs[0].scene_patches, std::vector<int>{4});
  EXPECT_EQ(match.pairs[0].model_patches, std::vector<int>{9});
  EXPECT_NEAR(match.score, 1.0 - 0.1 / 0.25, 1e-12);  // both are 100% of their view
  EXPECT_EQ(match.operations, 0);
  EXPECT_TRUE(feasible(scene, model, match));
}

TEST(PatchGroupMatching, OnePatchAgainstAChainStaysTrivial) {
  CosmosView scene;
  scene.patches = {graph_patch(0, 100, 0.75, {})};
  const PatchGroupMatch match = match_patch_groups(scene, chain_view());
  ASSERT_EQ(match.pairs.size(), 1u);
  EXPECT_EQ(match.pairs[0].model_patches, (std::vector<int>{0, 1, 2, 3}));
  EXPECT_NEAR(match.fineness, std::sqrt(500.0 / 1400.0), 1e-12);
  EXPECT_TRUE(feasible(scene, chain_view(), match));
}

TEST(PatchGroupMatching, IdenticalViewsMatchPatchForPatchWithScoreOne) {
  const PatchGroupMatch match = match_patch_groups(chain_view(), chain_view());
  ASSERT_EQ(match.pairs.size(), 4u);
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(match.pairs[i].scene_patches, std::vector<int>{i});
    EXPECT_EQ(match.pairs[i].model_patches, std::vector<int>{i});
  }
  EXPECT_NEAR(match.score, 1.0, 1e-12);
  EXPECT_NEAR(match.fineness, 1.0, 1e-12);
}

TEST(PatchGroupMatching, FifteenPatchGridIsFollowedThroughShuffledIds) {
  const CosmosView scene = grid_view(kShuffled, 1.0);
  const CosmosView model = grid_view(kIdentity, -1.0);
  const PatchGroupMatch match = match_patch_groups(scene, model);
  EXPECT_EQ(match.status, PatchGroupMatchStatus::kOk);
  ASSERT_EQ(match.pairs.size(), 15u);
  int correct = 0;
  for (const MappedPair& pair : match.pairs) {
    ASSERT_EQ(pair.scene_patches.size(), 1u);
    ASSERT_EQ(pair.model_patches.size(), 1u);
    const int cell = static_cast<int>(
        std::find(kShuffled.begin(), kShuffled.end(), pair.scene_patches[0]) - kShuffled.begin());
    correct += pair.model_patches[0] == cell;
  }
  EXPECT_EQ(correct, 15);
  EXPECT_GT(match.score, 0.85);
  EXPECT_TRUE(feasible(scene, model, match));
}

TEST(PatchGroupMatching, PlanarPatchesPairOnlyWithPlanarOnes) {
  // Scene: a planar face between two caps; model: the same with the middle face curved.
  CosmosView scene;
  scene.patches = {graph_patch(0, 300, 0.95, {{1, 30}}),
                   graph_patch(1, 400, 0, {{0, 30}, {2, 30}}, true),
                   graph_patch(2, 300, 0.95, {{1, 30}})};
  CosmosView model = scene;
  model.patches[1] = graph_patch(1, 400, 0.75, {{0, 30}, {2, 30}});
  const PatchGroupMatch match = match_patch_groups(scene, model);
  for (const MappedPair& pair : match.pairs) {
    const bool scene_has_planar = std::find(pair.scene_patches.begin(), pair.scene_patches.end(),
                                            1) != pair.scene_patches.end();
    EXPECT_TRUE(!scene_has_planar || pair.scene_patches.size() > 1 || pair.model_patches.size() > 1)
        << "the planar patch alone was paired with a curved one";
  }
  EXPECT_LT(match.score, 0.5);
}

TEST(PatchGroupMatching, WeakAdjacenciesNeedNotMatchStrongOnesMust) {
  // The scene chain has an extra contact 0-3 of 2 boundary pixels (a noisy small patch
  // corner, §5.4.3); at 400 px a patch's perimeter is about 71 px, so 2 px is weak.
  CosmosView scene = chain_view();
  scene.patches[0].neighbors.push_back({3, 2});
  const PatchGroupMatch tolerant = match_patch_groups(scene, chain_view());
  EXPECT_EQ(tolerant.pairs.size(), 4u);
  EXPECT_NEAR(tolerant.fineness, 1.0, 1e-12);

  PatchGroupMatchParameters strict;
  strict.min_adjacency_strength = 0.0;
  const PatchGroupMatch strict_match = match_patch_groups(scene, chain_view(), strict);
  EXPECT_LT(strict_match.pairs.size(), 4u);
  EXPECT_TRUE(is_feasible_correspondence(scene, chain_view(), strict_match.pairs, 0.0));
  EXPECT_FALSE(is_feasible_correspondence(scene, chain_view(), tolerant.pairs, 0.0));
}

TEST(PatchGroupMatching, CapsuleViewsCorrespondCapToCapAndRidgeToRidge) {
  const LabelledView& scene = analytic_view(AnalyticShape::kCapsule, 35);
  const LabelledView& model = analytic_view(AnalyticShape::kCapsule, 0);
  const PatchGroupMatch match = match_patch_groups(scene.view, model.view);
  EXPECT_TRUE(feasible(scene.view, model.view, match));
  ASSERT_GE(match.pairs.size(), 3u);
  int caps = 0;
  for (const MappedPair& pair : match.pairs) {
    // The capsule is symmetric under a half turn, so either cap may take either cap.
    const bool scene_ridge = group_region(scene, pair.scene_patches) == 1;
    const bool model_ridge = group_region(model, pair.model_patches) == 1;
    EXPECT_EQ(scene_ridge, model_ridge);
    caps += !scene_ridge;
  }
  EXPECT_EQ(caps, 2);
  EXPECT_GT(match.score, 0.75);
  EXPECT_GT(match.fineness, 0.9);
}

TEST(PatchGroupMatching, FreeFormReliefViewsCorrespondRegionToRegion) {
  const LabelledView& scene = relief_view(40);
  const LabelledView& model = relief_view(0);
  const PatchGroupMatch match = match_patch_groups(scene.view, model.view);
  EXPECT_TRUE(feasible(scene.view, model.view, match));
  double correct_weight = 0;
  std::map<int, bool> region_matched;
  for (const MappedPair& pair : match.pairs) {
    const int scene_region = group_region(scene, pair.scene_patches);
    const int model_region = group_region(model, pair.model_patches);
    if (pair.goodness.weight >= 0.02) {
      EXPECT_EQ(scene_region, model_region) << "pair weight " << pair.goodness.weight;
    }
    if (scene_region == model_region) {
      correct_weight += pair.goodness.weight;
      region_matched[scene_region] = true;
    }
  }
  EXPECT_GT(correct_weight, 0.95);
  EXPECT_EQ(region_matched.size(), 6u) << "flanks, ridge, both bumps and the dent";
  EXPECT_GT(match.score, 0.7);
}

TEST(PatchGroupMatching, DifferentPartsGiveCoarserLowerScoringCorrespondences) {
  const LabelledView& capsule35 = analytic_view(AnalyticShape::kCapsule, 35);
  const LabelledView& capsule0 = analytic_view(AnalyticShape::kCapsule, 0);
  const PatchGroupMatch same_capsule = match_patch_groups(capsule35.view, capsule0.view);
  const PatchGroupMatch same_relief = match_patch_groups(relief_view(40).view, relief_view(0).view);
  const double same_score = std::min(same_capsule.score, same_relief.score);
  const double same_fineness = std::min(same_capsule.fineness, same_relief.fineness);

  const std::vector<std::pair<const CosmosView*, const CosmosView*>> different = {
      {&capsule35.view, &analytic_view(AnalyticShape::kTorus, 0).view},
      {&capsule35.view, &analytic_view(AnalyticShape::kBoxCorner, 0).view},
      {&relief_view(40).view, &capsule0.view},
      {&relief_view(40).view, &analytic_view(AnalyticShape::kTorus, 0).view},
      {&relief_view(40).view, &analytic_view(AnalyticShape::kBoxCorner, 0).view}};
  for (const auto& [scene, model] : different) {
    const PatchGroupMatch match = match_patch_groups(*scene, *model);
    EXPECT_TRUE(feasible(*scene, *model, match));
    EXPECT_LT(match.score, 0.4);
    EXPECT_LT(match.score, same_score - 0.3);
    EXPECT_LT(match.fineness, same_fineness - 0.1);
  }
  // Planar faces against curved patches: nothing refines, and nothing resembles.
  const PatchGroupMatch box =
      match_patch_groups(capsule35.view, analytic_view(AnalyticShape::kBoxCorner, 0).view);
  EXPECT_EQ(box.pairs.size(), 1u);
  EXPECT_LT(box.score, 0.05);
}

TEST(PatchGroupMatching, WithoutABudgetTheTrivialCorrespondenceStays) {
  PatchGroupMatchParameters no_budget;
  no_budget.max_operations = 0;
  const PatchGroupMatch match =
      match_patch_groups(relief_view(40).view, relief_view(0).view, no_budget);
  EXPECT_EQ(match.pairs.size(), 1u);
  EXPECT_EQ(match.operations, 0);
  EXPECT_EQ(match.status, PatchGroupMatchStatus::kBudgetExhausted);
  EXPECT_TRUE(feasible(relief_view(40).view, relief_view(0).view, match));
}

TEST(PatchGroupMatching, TheOperationBudgetIsRespected) {
  const CosmosView& scene = relief_view(40).view;
  const CosmosView& model = relief_view(0).view;
  const PatchGroupMatch unlimited = match_patch_groups(scene, model);
  EXPECT_EQ(unlimited.status, PatchGroupMatchStatus::kOk);
  ASSERT_GT(unlimited.operations, 50);
  for (std::int64_t budget : {std::int64_t{1}, std::int64_t{10}, std::int64_t{50},
                              unlimited.operations / 2, unlimited.operations - 1}) {
    PatchGroupMatchParameters parameters;
    parameters.max_operations = budget;
    const PatchGroupMatch match = match_patch_groups(scene, model, parameters);
    EXPECT_LE(match.operations, budget);
    EXPECT_EQ(match.status, PatchGroupMatchStatus::kBudgetExhausted);
    EXPECT_TRUE(feasible(scene, model, match));
    EXPECT_LE(match.pairs.size(), unlimited.pairs.size());
  }
  PatchGroupMatchParameters per_refine;
  per_refine.max_operations_per_refine = 5;
  const PatchGroupMatch small = match_patch_groups(scene, model, per_refine);
  EXPECT_LE(small.operations,
            5 * (small.refinements + static_cast<std::int64_t>(small.pairs.size())));
  EXPECT_TRUE(feasible(scene, model, small));
}

TEST(PatchGroupMatching, RepeatedRunsGiveIdenticalResults) {
  const CosmosView scene = relief_view(40).view;  // copies: nothing may depend on addresses
  const CosmosView model = relief_view(0).view;
  const PatchGroupMatch first = match_patch_groups(scene, model);
  for (int run = 0; run < 3; ++run) {
    const PatchGroupMatch again = match_patch_groups(relief_view(40).view, relief_view(0).view);
    EXPECT_EQ(again.score, first.score);
    EXPECT_EQ(again.operations, first.operations);
    ASSERT_EQ(again.pairs.size(), first.pairs.size());
    for (std::size_t p = 0; p < first.pairs.size(); ++p) {
      EXPECT_EQ(again.pairs[p].scene_patches, first.pairs[p].scene_patches);
      EXPECT_EQ(again.pairs[p].model_patches, first.pairs[p].model_patches);
    }
  }
}

}  // namespace
}  // namespace cosmos
