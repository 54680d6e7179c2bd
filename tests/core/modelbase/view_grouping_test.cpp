// View grouping of the model base (§4.4.2): per part, complete-link clusters of the moment
// vectors cut at a level or to a count, with centroids (the first tier of Fig. 5.3).
#include "core/modelbase/view_grouping.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace cosmos {
namespace {

ModelBaseView view_with_mean(int part, double m1, double m2) {
  ModelBaseView view;
  view.part_index = part;
  view.moments.fill(0.0);
  view.moments[0] = m1;
  view.moments[1] = m2;
  view.moments[kSpectrumMoments] = 0.5;  // the planar fraction is averaged, not clustered on
  return view;
}

// Part 0: three tight groups of views (m1 near 0.2, 0.5, 0.8), interleaved in view order;
// part 1 (views in between): two groups. Within a group Eq. 4.3 is <= 2e-4, between groups
// >= 0.09.
ModelBase grouped_base() {
  ModelBase base;
  base.parts.resize(3);  // part 2 has no views
  const double part0[] = {0.2, 0.5, 0.8, 0.21, 0.51, 0.79, 0.205};
  for (double m1 : part0) base.views.push_back(view_with_mean(0, m1, 0.01));
  base.views.push_back(view_with_mean(1, 0.3, 0.02));
  base.views.push_back(view_with_mean(1, 0.6, 0.02));
  base.views.push_back(view_with_mean(1, 0.31, 0.03));
  return base;
}

TEST(ViewGrouping, CutAtALevelSeparatesTheGroupsOfEachPart) {
  const ModelBase base = grouped_base();
  const ViewGroupingResult result =
      group_model_views(base, {.cut_level = 0.01, .cluster_count = 0});
  ASSERT_EQ(result.status, ClusteringStatus::kOk);
  ASSERT_EQ(result.clusters.size(), 5u);
  // Part 0, clusters in order of their lowest view.
  EXPECT_EQ(result.clusters[0].part_index, 0);
  EXPECT_EQ(result.clusters[0].views, (std::vector<int>{0, 3, 6}));
  EXPECT_EQ(result.clusters[1].views, (std::vector<int>{1, 4}));
  EXPECT_EQ(result.clusters[2].views, (std::vector<int>{2, 5}));
  EXPECT_NEAR(result.clusters[0].centroid[0], (0.2 + 0.21 + 0.205) / 3, 1e-12);
  EXPECT_NEAR(result.clusters[2].centroid[0], (0.8 + 0.79) / 2, 1e-12);
  EXPECT_NEAR(result.clusters[1].centroid[kSpectrumMoments], 0.5, 1e-12);
  // Part 1: indices into ModelBase::views.
  EXPECT_EQ(result.clusters[3].part_index, 1);
  EXPECT_EQ(result.clusters[3].views, (std::vector<int>{7, 9}));
  EXPECT_EQ(result.clusters[4].views, (std::vector<int>{8}));
  EXPECT_NEAR(result.clusters[3].centroid[1], 0.025, 1e-12);
}

TEST(ViewGrouping, LevelBelowTheTightestPairKeepsEveryViewApart) {
  const ViewGroupingResult result =
      group_model_views(grouped_base(), {.cut_level = 1e-6, .cluster_count = 0});
  ASSERT_EQ(result.status, ClusteringStatus::kOk);
  EXPECT_EQ(result.clusters.size(), 10u);
}

TEST(ViewGrouping, RequestedCountOverridesTheLevel) {
  const ViewGroupingResult result =
      group_model_views(grouped_base(), {.cut_level = 0.01, .cluster_count = 2});
  ASSERT_EQ(result.status, ClusteringStatus::kOk);
  ASSERT_EQ(result.clusters.size(), 4u);
  // Complete link: the 0.5 and 0.8 groups are at most 0.30 apart in m1 (Eq. 4.3: 0.09), the
  // 0.2 and 0.5 groups 0.31 (0.0961), so the first two to merge are 0.5 and 0.8.
  EXPECT_EQ(result.clusters[0].views, (std::vector<int>{0, 3, 6}));
  EXPECT_EQ(result.clusters[1].views, (std::vector<int>{1, 2, 4, 5}));
  EXPECT_EQ(result.clusters[2].views, (std::vector<int>{7, 9}));
  EXPECT_EQ(result.clusters[3].views, (std::vector<int>{8}));
}

TEST(ViewGrouping, NonFiniteMomentsAreReportedWithThePart) {
  ModelBase base = grouped_base();
  base.views[8].moments[2] = std::numeric_limits<double>::quiet_NaN();
  const ViewGroupingResult result = group_model_views(base, {});
  EXPECT_EQ(result.status, ClusteringStatus::kInvalidValue);
  EXPECT_EQ(result.failed_part, 1);
  EXPECT_TRUE(result.clusters.empty());
}

}  // namespace
}  // namespace cosmos
