// Folding of patches below the minimum area (§5.4.3, core/segmentation/tiny_patch_folding.hpp)
// on hand-made seed graphs, each seed one region of the queue: a tiny patch joins its
// significant neighbour of nearest mean shape index, a ramp of tiny strips splits between the
// patches at its ends, tiny islands join among themselves, and what stays tiny alone is
// dropped.
#include "core/segmentation/tiny_patch_folding.hpp"

#include <gtest/gtest.h>

#include <utility>
#include <vector>

namespace cosmos {
namespace {

struct Seed {
  float shape_index;
  float area_mm2;
};

// Seeds of one shape index each, their queue regions, and the adjacent pairs.
struct SeedGraph {
  ShapeSeeds seeds;
  RegionMergeQueue regions;
  GroupPairs pairs;

  SeedGraph(const std::vector<Seed>& list, const GroupPairs& adjacent) : pairs(adjacent) {
    for (const Seed& seed : list) {
      seeds.shape_index_min.push_back(seed.shape_index);
      seeds.shape_index_max.push_back(seed.shape_index);
      seeds.area_mm2.push_back(seed.area_mm2);
      seeds.shape_area.push_back(double{seed.shape_index} * seed.area_mm2);
      regions.add_region(seed.shape_index, seed.shape_index, seed.area_mm2);
    }
    seeds.adjacent = adjacent;
  }
  std::vector<bool> fold(double min_area_mm2) {
    return fold_tiny_patches(seeds, pairs, regions, min_area_mm2);
  }
  bool together(int a, int b) { return regions.find(a) == regions.find(b); }
};

TEST(TinyPatchFolding, TinyPatchesFoldIntoTheMostSimilarNeighbour) {
  // 0.2 (4 mm^2) - 0.6 (1 mm^2) - 0.9 (5 mm^2), minimum 1.5 mm^2: 0.6 is nearer 0.9.
  SeedGraph graph({{0.2f, 4}, {0.6f, 1}, {0.9f, 5}}, {{0, 1}, {1, 2}});
  const std::vector<bool> dropped = graph.fold(1.5);
  EXPECT_TRUE(graph.together(1, 2));
  EXPECT_FALSE(graph.together(0, 1));
  EXPECT_EQ(dropped, std::vector<bool>(3, false));
  EXPECT_EQ(graph.regions.area_mm2(graph.regions.find(2)), 6.0f);
}

TEST(TinyPatchFolding, ASignificantNeighbourWinsOverANearerTinyOne) {
  // 0.51 (tiny) - 0.50 (tiny) - 0.90 (significant): the 0.50 strip goes to 0.90 although the
  // other tiny one is 0.01 away; then the 0.51 one follows into the patch it now touches.
  SeedGraph graph({{0.51f, 1}, {0.50f, 1}, {0.90f, 10}}, {{0, 1}, {1, 2}});
  const std::vector<bool> dropped = graph.fold(3.0);
  EXPECT_TRUE(graph.together(1, 2));
  EXPECT_TRUE(graph.together(0, 2));
  EXPECT_EQ(dropped, std::vector<bool>(3, false));
}

TEST(TinyPatchFolding, ARampOfTinyStripsSplitsBetweenThePatchesAtItsEnds) {
  // P (0.2, 10 mm^2) - 0.3 - 0.4 - 0.5 - 0.6 - Q (0.7, 10 mm^2), strips of 1 mm^2, minimum
  // 3 mm^2. Smallest (then lowest index) first, each strip joins its significant neighbour of
  // nearest mean: 0.3, 0.4 and 0.5 reach only P (mean then 0.2 -> 0.209 -> 0.225), 0.6 is
  // nearer Q (0.1) than P (0.246). No strip becomes a patch of its own.
  SeedGraph graph({{0.2f, 10}, {0.3f, 1}, {0.4f, 1}, {0.5f, 1}, {0.6f, 1}, {0.7f, 10}},
                  {{0, 1}, {1, 2}, {2, 3}, {3, 4}, {4, 5}});
  graph.fold(3.0);
  for (int strip : {1, 2, 3}) EXPECT_TRUE(graph.together(strip, 0)) << strip;
  EXPECT_TRUE(graph.together(4, 5));
  EXPECT_FALSE(graph.together(0, 5));
  EXPECT_EQ(graph.regions.area_mm2(graph.regions.find(0)), 13.0f);
  EXPECT_EQ(graph.regions.area_mm2(graph.regions.find(5)), 11.0f);
}

TEST(TinyPatchFolding, TinyIslandsFoldAmongThemselvesUntilSignificant) {
  // Three pairs, each a third of the area, none of the half that makes a patch significant:
  // the first (smallest index on equal area) folds into its only neighbour, which makes that
  // cluster significant, and the last pair then folds into it.
  SeedGraph graph({{0.11f, 2}, {0.51f, 2}, {0.91f, 2}}, {{0, 1}, {1, 2}});
  const std::vector<bool> dropped = graph.fold(3.0);
  EXPECT_TRUE(graph.together(0, 1));
  EXPECT_TRUE(graph.together(1, 2));
  EXPECT_EQ(dropped, std::vector<bool>(3, false));
}

TEST(TinyPatchFolding, WhatStaysTinyAndAloneIsDropped) {
  // A significant patch 0, a tiny seed 1 with no neighbour, and two tiny seeds 2-3 that join
  // but stay below the minimum together.
  SeedGraph graph({{0.5f, 10}, {0.3f, 1}, {0.7f, 1}, {0.8f, 1}}, {{2, 3}});
  const std::vector<bool> dropped = graph.fold(3.0);
  ASSERT_EQ(dropped.size(), 4u);
  EXPECT_FALSE(dropped[0]);
  EXPECT_TRUE(dropped[1]);
  EXPECT_TRUE(graph.together(2, 3));
  const int island = graph.regions.find(2);
  EXPECT_TRUE(dropped[static_cast<std::size_t>(island)]);
  EXPECT_FALSE(dropped[static_cast<std::size_t>(5 - island)]);  // the other of 2, 3: no root
}

TEST(TinyPatchFolding, GroupPairsBecomePairsOfTheStartingGroupsInOrder) {
  // Seeds 0 and 1 grew into one group before folding (root 1, the larger); every pair is
  // rewritten to the groups' roots, pairs inside a group are left out, the order is kept.
  SeedGraph graph({{0.5f, 1}, {0.5f, 4}, {0.55f, 6}, {0.6f, 8}}, {{0, 1}, {1, 2}, {2, 0}, {3, 2}});
  graph.regions.unite(0, 1);
  ASSERT_EQ(graph.regions.find(0), 1);
  graph.fold(0.5);  // nothing is tiny
  EXPECT_EQ(graph.pairs, (GroupPairs{{1, 2}, {2, 1}, {3, 2}}));
  EXPECT_FALSE(graph.together(1, 2));
  EXPECT_FALSE(graph.together(2, 3));
}

}  // namespace
}  // namespace cosmos
