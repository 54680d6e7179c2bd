// View grouping (§4.4.2): complete-link clustering of a hand-made dissimilarity matrix with a
// known dendrogram, its cuts by level and by count, centroids of moment vectors (Eq. 4.3).
#include "core/modelbase/view_clustering.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

namespace cosmos::testing {
namespace {

// Worked by hand (complete link: the distance to a union is the larger of the two):
//   1. {0,1} at 0.10 -> 6            2. {3,4} at 0.20 -> 7
//   3. {2} + 6 at max(0.40, 0.30) = 0.40 -> 8   (single link would say 0.30)
//   4. {5} + 7 at max(0.55, 0.35) = 0.55 -> 9   (single link: 0.35)
//   5. 8 + 9 at 0.90 -> 10
Eigen::MatrixXd hand_made_dissimilarities() {
  Eigen::MatrixXd d(6, 6);
  d << 0.00, 0.10, 0.40, 0.90, 0.80, 0.70,  //
      0.10, 0.00, 0.30, 0.85, 0.75, 0.60,   //
      0.40, 0.30, 0.00, 0.50, 0.45, 0.65,   //
      0.90, 0.85, 0.50, 0.00, 0.20, 0.55,   //
      0.80, 0.75, 0.45, 0.20, 0.00, 0.35,   //
      0.70, 0.60, 0.65, 0.55, 0.35, 0.00;
  return d;
}

void expect_merge(const DendrogramMerge& m, int a, int b, double height, int size) {
  EXPECT_EQ(m.cluster_a, a);
  EXPECT_EQ(m.cluster_b, b);
  EXPECT_DOUBLE_EQ(m.height, height);
  EXPECT_EQ(m.size, size);
}

TEST(ViewClustering, CompleteLinkBuildsTheHandComputedDendrogram) {
  const Dendrogram dendrogram = complete_link_clustering(hand_made_dissimilarities());
  ASSERT_EQ(dendrogram.status, ClusteringStatus::kOk);
  ASSERT_EQ(dendrogram.leaves, 6);
  ASSERT_EQ(dendrogram.merges.size(), 5u);
  expect_merge(dendrogram.merges[0], 0, 1, 0.10, 2);
  expect_merge(dendrogram.merges[1], 3, 4, 0.20, 2);
  expect_merge(dendrogram.merges[2], 2, 6, 0.40, 3);
  expect_merge(dendrogram.merges[3], 5, 7, 0.55, 3);
  expect_merge(dendrogram.merges[4], 8, 9, 0.90, 6);
}

TEST(ViewClustering, CutsByLevelAndByCount) {
  const Dendrogram dendrogram = complete_link_clustering(hand_made_dissimilarities());
  using Labels = std::vector<int>;
  EXPECT_EQ(cut_at_level(dendrogram, 0.05).label, (Labels{0, 1, 2, 3, 4, 5}));
  EXPECT_EQ(cut_at_level(dendrogram, 0.10).label, (Labels{0, 0, 1, 2, 3, 4}));  // <= level merges
  EXPECT_EQ(cut_at_level(dendrogram, 0.45).label, (Labels{0, 0, 0, 1, 1, 2}));
  EXPECT_EQ(cut_at_level(dendrogram, 0.45).clusters, 3);
  EXPECT_EQ(cut_at_level(dendrogram, 0.60).label, (Labels{0, 0, 0, 1, 1, 1}));
  EXPECT_EQ(cut_at_level(dendrogram, 1.00).label, (Labels{0, 0, 0, 0, 0, 0}));
  EXPECT_EQ(cut_to_count(dendrogram, 2).label, (Labels{0, 0, 0, 1, 1, 1}));
  EXPECT_EQ(cut_to_count(dendrogram, 3).label, (Labels{0, 0, 0, 1, 1, 2}));
  EXPECT_EQ(cut_to_count(dendrogram, 4).label, (Labels{0, 0, 1, 2, 2, 3}));
  EXPECT_EQ(cut_to_count(dendrogram, 6).clusters, 6);
  EXPECT_EQ(cut_to_count(dendrogram, 0).clusters, 1);   // clamped
  EXPECT_EQ(cut_to_count(dendrogram, 99).clusters, 6);  // clamped
}

TEST(ViewClustering, LabelsFollowTheLowestViewOfEachCluster) {
  // Views 0 and 3 close, 1 and 2 close: clusters are numbered by their lowest view.
  Eigen::MatrixXd d(4, 4);
  d << 0, 1, 1, 0.1,  //
      1, 0, 0.2, 1,   //
      1, 0.2, 0, 1,   //
      0.1, 1, 1, 0;
  const Dendrogram dendrogram = complete_link_clustering(d);
  EXPECT_EQ(cut_to_count(dendrogram, 2).label, (std::vector<int>{0, 1, 1, 0}));
}

TEST(ViewClustering, TiesBreakByTheLowestClusterIds) {
  const Eigen::MatrixXd d = Eigen::MatrixXd::Constant(4, 4, 1.0);
  const Dendrogram dendrogram = complete_link_clustering(d);
  ASSERT_EQ(dendrogram.merges.size(), 3u);
  expect_merge(dendrogram.merges[0], 0, 1, 1.0, 2);
  expect_merge(dendrogram.merges[1], 2, 3, 1.0, 2);
  expect_merge(dendrogram.merges[2], 4, 5, 1.0, 4);
}

TEST(ViewClustering, RejectsBadMatrices) {
  EXPECT_EQ(complete_link_clustering(Eigen::MatrixXd(2, 3)).status, ClusteringStatus::kNotSquare);
  EXPECT_EQ(complete_link_clustering(Eigen::MatrixXd(0, 0)).status, ClusteringStatus::kEmpty);
  Eigen::MatrixXd d = hand_made_dissimilarities();
  d(0, 1) = 0.2;
  EXPECT_EQ(complete_link_clustering(d).status, ClusteringStatus::kNotSymmetric);
  d = hand_made_dissimilarities();
  d(0, 1) = d(1, 0) = -0.1;
  EXPECT_EQ(complete_link_clustering(d).status, ClusteringStatus::kInvalidValue);
  const Dendrogram one = complete_link_clustering(Eigen::MatrixXd::Zero(1, 1));
  EXPECT_EQ(one.status, ClusteringStatus::kOk);
  EXPECT_EQ(cut_at_level(one, 0.1).clusters, 1);
}

// 320 views (§4.5's view sphere) with random dissimilarities: every merge height is the
// largest original dissimilarity between the two clusters' members, heights never decrease.
TEST(ViewClustering, EveryMergeHeightIsTheLargestMemberDissimilarity) {
  constexpr int n = 320;
  std::mt19937_64 generator(4);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  Eigen::MatrixXd d = Eigen::MatrixXd::Zero(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) d(i, j) = d(j, i) = uniform(generator);
  const Dendrogram dendrogram = complete_link_clustering(d);
  ASSERT_EQ(dendrogram.merges.size(), static_cast<std::size_t>(n - 1));
  std::vector<std::vector<int>> members(2 * n - 1);
  for (int v = 0; v < n; ++v) members[v] = {v};
  double previous = 0.0;
  for (int k = 0; k < n - 1; ++k) {
    const DendrogramMerge& m = dendrogram.merges[k];
    double largest = 0.0;
    for (int a : members[m.cluster_a])
      for (int b : members[m.cluster_b]) largest = std::max(largest, d(a, b));
    ASSERT_EQ(m.height, largest) << k;
    ASSERT_GE(m.height, previous) << k;
    previous = m.height;
    members[n + k] = members[m.cluster_a];
    members[n + k].insert(members[n + k].end(), members[m.cluster_b].begin(),
                          members[m.cluster_b].end());
    ASSERT_EQ(static_cast<int>(members[n + k].size()), m.size);
  }
  EXPECT_EQ(dendrogram.merges.back().size, n);
}

// Two groups of views with nearby moment vectors (Eq. 4.3 distances ~1e-3 within, ~0.5
// between): the thesis's cut at 0.1 gives the two groups, and their centroids are the means.
TEST(ViewClustering, MomentVectorsGroupAtTheThesisLevelAndGiveCentroids) {
  std::vector<MomentVector> moments;
  for (int v = 0; v < 6; ++v) {
    MomentVector m{};
    const bool second_group = v % 2 == 1;
    m[0] = second_group ? 0.8 : 0.3;
    m[1] = 0.05 + 0.01 * v;
    m[2] = second_group ? -0.2 : 0.1;
    m[10] = 0.1 * v;  // the planar fraction does not enter Eq. 4.3
    moments.push_back(m);
  }
  const Eigen::MatrixXd d = spectral_dissimilarity_matrix(moments);
  EXPECT_DOUBLE_EQ(d(0, 1), spectral_dissimilarity(moments[0], moments[1]));
  EXPECT_NEAR(d(0, 2), 0.02 * 0.02, 1e-15);
  const ViewPartition partition = cut_at_level(complete_link_clustering(d), 0.1);
  EXPECT_EQ(partition.label, (std::vector<int>{0, 1, 0, 1, 0, 1}));
  const std::vector<MomentVector> centroids = cluster_centroids(partition, moments);
  ASSERT_EQ(centroids.size(), 2u);
  EXPECT_DOUBLE_EQ(centroids[0][0], 0.3);
  EXPECT_NEAR(centroids[0][1], 0.05 + 0.01 * (0 + 2 + 4) / 3.0, 1e-15);
  EXPECT_NEAR(centroids[1][1], 0.05 + 0.01 * (1 + 3 + 5) / 3.0, 1e-15);
  EXPECT_DOUBLE_EQ(centroids[1][2], -0.2);
  EXPECT_NEAR(centroids[1][10], 0.3, 1e-15);
}

}  // namespace
}  // namespace cosmos::testing
