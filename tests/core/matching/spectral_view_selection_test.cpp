// Two-tier spectral model-view selection (§5.2) on a hand-made model base.
#include "core/matching/spectral_view_selection.hpp"

#include <gtest/gtest.h>

namespace cosmos {
namespace {

MomentVector moments(double m1, double m2) {
  MomentVector m{};
  m[0] = m1;
  m[1] = m2;
  return m;
}

// Part 0 has two clusters (views near m1 = 0.2 and 0.5), part 1 one cluster (near 0.8).
ModelBase hand_made_base() {
  ModelBase base;
  base.parts.resize(2);
  const double view_m1[] = {0.20, 0.21, 0.50, 0.52, 0.80, 0.79, 0.81};
  const int part_of[] = {0, 0, 0, 0, 1, 1, 1};
  for (int v = 0; v < 7; ++v) {
    ModelBaseView view;
    view.part_index = part_of[v];
    view.view_index = v;
    view.moments = moments(view_m1[v], 0.01 * v);
    base.views.push_back(view);
  }
  auto cluster = [&](int part, std::vector<int> views) {
    ViewCluster c;
    c.part_index = part;
    for (int v : views)
      for (int k = 0; k <= kSpectrumMoments; ++k)
        c.centroid[k] += base.views[v].moments[k] / views.size();
    c.views = std::move(views);
    base.clusters.push_back(c);
  };
  cluster(0, {0, 1});
  cluster(0, {2, 3});
  cluster(1, {4, 5, 6});
  return base;
}

TEST(SpectralViewSelection, BestClustersThenBestViews) {
  const ModelBase base = hand_made_base();
  SpectralSelectionParameters parameters;
  parameters.best_clusters = 1;
  parameters.best_views = 2;
  const SpectralViewSelector selector(base, parameters);
  const auto candidates = selector.select(moments(0.515, 0.03));
  ASSERT_EQ(candidates.size(), 2u);
  EXPECT_EQ(candidates[0].cluster, 1);
  EXPECT_EQ(candidates[0].view, 3);  // m = (0.52, 0.03): distance 2.5e-5
  EXPECT_EQ(candidates[1].view, 2);  // m = (0.50, 0.02): distance 3.25e-4
  EXPECT_NEAR(candidates[0].distance, 0.005 * 0.005, 1e-12);
  EXPECT_EQ(selector.rank_clusters(moments(0.78, 0.0)), (std::vector<int>{2, 1, 0}));
}

TEST(SpectralViewSelection, MoreClustersWidenTheSearch) {
  const ModelBase base = hand_made_base();
  SpectralSelectionParameters parameters;
  parameters.best_clusters = 3;
  parameters.best_views = 7;
  const auto candidates = SpectralViewSelector(base, parameters).select(moments(0.2, 0.0));
  ASSERT_EQ(candidates.size(), 7u);
  EXPECT_EQ(candidates.front().view, 0);
  for (std::size_t k = 1; k < candidates.size(); ++k)
    EXPECT_LE(candidates[k - 1].distance, candidates[k].distance);
}

TEST(SpectralViewSelection, MahalanobisWeighsMomentsByTheirSpread) {
  // Within each cluster m1 spreads by 0.02 while m2 barely moves (0.001), so under the
  // Mahalanobis distance the same step counts far more along m2 than along m1.
  ModelBase base = hand_made_base();
  for (ModelBaseView& view : base.views)
    view.moments[1] = 0.1 * view.part_index + 0.001 * (view.view_index % 2);
  for (ViewCluster& cluster : base.clusters) {
    cluster.centroid = MomentVector{};
    for (int v : cluster.views)
      for (int k = 0; k <= kSpectrumMoments; ++k)
        cluster.centroid[k] += base.views[v].moments[k] / cluster.views.size();
  }
  SpectralSelectionParameters parameters;
  parameters.distance = SpectralDistance::kMahalanobis;
  const SpectralViewSelector mahalanobis(base, parameters);
  const SpectralViewSelector euclidean(base, SpectralSelectionParameters{});
  const MomentVector origin = moments(0.5, 0.0);
  const double along_m1 = mahalanobis.distance(origin, moments(0.51, 0.0));
  const double along_m2 = mahalanobis.distance(origin, moments(0.5, 0.01));
  EXPECT_GT(along_m2, 10 * along_m1);
  EXPECT_NEAR(euclidean.distance(origin, moments(0.51, 0.0)),
              euclidean.distance(origin, moments(0.5, 0.01)), 1e-15);
  EXPECT_NEAR(mahalanobis.distance(origin, origin), 0.0, 1e-12);
}

}  // namespace
}  // namespace cosmos
