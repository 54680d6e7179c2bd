// The region-growing queue of §3.5.2 (core/segmentation/region_merge_queue.hpp) on hand-made
// region graphs: least merged shape diameter first, up to and including the limit; resumed
// with a larger limit (the adaptive mode of §5.4.3); union by area; the count of regions of
// at least a given area kept through every merge.
#include "core/segmentation/region_merge_queue.hpp"

#include <gtest/gtest.h>

namespace cosmos {
namespace {

TEST(RegionMergeQueue, RegionsAreNumberedInOrderAndStartAlone) {
  RegionMergeQueue queue;
  EXPECT_EQ(queue.add_region(0.1f, 0.2f, 3.0f), 0);
  EXPECT_EQ(queue.add_region(0.5f, 0.5f, 1.0f), 1);
  EXPECT_EQ(queue.region_count(), 2u);
  EXPECT_TRUE(queue.is_root(0));
  EXPECT_TRUE(queue.is_root(1));
  EXPECT_EQ(queue.find(1), 1);
  EXPECT_EQ(queue.shape_index_min(0), 0.1f);
  EXPECT_EQ(queue.shape_index_max(0), 0.2f);
  EXPECT_EQ(queue.area_mm2(0), 3.0f);
}

TEST(RegionMergeQueue, GrowsLeastMergedDiameterFirst) {
  // A (0.10) - B (0.20) - C (0.26). Least diameter first merges B and C (0.06); A would then
  // make a region 0.16 wide, above the limit 0.1. Merging A and B first (0.10, within the
  // limit) would instead have kept C apart.
  RegionMergeQueue queue;
  const int a = queue.add_region(0.10f, 0.10f, 1.0f);
  const int b = queue.add_region(0.20f, 0.20f, 1.0f);
  const int c = queue.add_region(0.26f, 0.26f, 1.0f);
  queue.add_edge(a, b);
  queue.add_edge(b, c);
  EXPECT_NE(queue.find(b), queue.find(c));  // nothing merges before grow()
  queue.grow(0.1);
  EXPECT_EQ(queue.find(b), queue.find(c));
  EXPECT_NE(queue.find(a), queue.find(b));
  const int bc = queue.find(b);
  EXPECT_EQ(queue.shape_index_min(bc), 0.20f);
  EXPECT_EQ(queue.shape_index_max(bc), 0.26f);
  EXPECT_EQ(queue.area_mm2(bc), 2.0f);
  // Resumed with a larger limit, the edge held back above the old one merges.
  queue.grow(0.2);
  const int abc = queue.find(a);
  EXPECT_EQ(queue.find(c), abc);
  EXPECT_EQ(queue.shape_index_min(abc), 0.10f);
  EXPECT_EQ(queue.shape_index_max(abc), 0.26f);
  EXPECT_EQ(queue.area_mm2(abc), 3.0f);
}

TEST(RegionMergeQueue, TheLimitItselfStillMerges) {
  // 0.25 and 0.5 are exact in float: their diameter is the limit 0.25, not above it. A limit
  // a little below falls in the same bucket of the queue and must still hold them apart.
  for (const auto& [limit, merged] : {std::pair{0.25, true}, std::pair{0.2499, false}}) {
    RegionMergeQueue queue;
    queue.add_region(0.25f, 0.25f, 1.0f);
    queue.add_region(0.5f, 0.5f, 1.0f);
    queue.add_edge(0, 1);
    queue.grow(limit);
    EXPECT_EQ(queue.find(0) == queue.find(1), merged) << limit;
  }
}

TEST(RegionMergeQueue, EqualShapeIndicesMergeAsTheirEdgeIsAdded) {
  RegionMergeQueue queue;
  queue.add_region(0.4f, 0.4f, 1.0f);
  queue.add_region(0.4f, 0.4f, 1.0f);
  queue.add_region(0.401f, 0.401f, 1.0f);
  queue.add_edge(0, 1);  // merged diameter 0: the first bucket, merged at once
  queue.add_edge(1, 2);  // 0.001: filed for grow()
  EXPECT_EQ(queue.find(0), queue.find(1));
  EXPECT_NE(queue.find(1), queue.find(2));
  queue.grow(0.0);
  EXPECT_NE(queue.find(1), queue.find(2));
  queue.grow(0.002);
  EXPECT_EQ(queue.find(1), queue.find(2));
}

TEST(RegionMergeQueue, TheLargerRegionBecomesTheRootTiesToTheLowerIndex) {
  RegionMergeQueue queue;
  queue.add_region(0.1f, 0.1f, 1.0f);
  queue.add_region(0.9f, 0.9f, 3.0f);
  queue.add_region(0.5f, 0.5f, 2.0f);
  queue.add_region(0.6f, 0.6f, 2.0f);
  queue.unite(0, 1);  // unconditional: a diameter of 0.8
  EXPECT_EQ(queue.find(0), 1);
  EXPECT_FALSE(queue.is_root(0));
  EXPECT_EQ(queue.shape_index_min(1), 0.1f);
  EXPECT_EQ(queue.shape_index_max(1), 0.9f);
  EXPECT_EQ(queue.area_mm2(1), 4.0f);
  queue.unite(3, 2);
  EXPECT_EQ(queue.find(3), 2);
  queue.unite(2, 2);  // a region with itself: nothing happens
  EXPECT_EQ(queue.area_mm2(2), 4.0f);
  queue.unite(3, 0);  // roots 2 and 1 of equal area 4: root 1
  EXPECT_EQ(queue.find(2), 1);
  EXPECT_EQ(queue.area_mm2(1), 8.0f);
}

TEST(RegionMergeQueue, CountsRegionsOfAtLeastTheAreaThroughEveryMerge) {
  RegionMergeQueue queue;
  for (float area : {1.0f, 1.0f, 2.0f, 5.0f, 0.5f}) queue.add_region(0.5f, 0.5f, area);
  queue.count_regions_of_area_at_least(2.0f);
  EXPECT_EQ(queue.significant_region_count(), 2);  // 2 and 5
  queue.unite(0, 1);                               // 1 + 1: a new one
  EXPECT_EQ(queue.significant_region_count(), 3);
  queue.unite(2, 3);  // two significant ones become one
  EXPECT_EQ(queue.significant_region_count(), 2);
  queue.unite(4, 2);  // a tiny one into a significant one
  EXPECT_EQ(queue.significant_region_count(), 2);
  queue.add_edge(0, 3);  // equal shape indices: merged as filed
  EXPECT_EQ(queue.significant_region_count(), 1);
}

}  // namespace
}  // namespace cosmos
