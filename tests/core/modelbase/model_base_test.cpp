// The in-memory model base (ch. 4, Fig. 5.3): the view-index convention of the view sphere
// (is_once_subdivided_view), and how views, parts and clusters index each other in the
// regression base (5 parts x 80 views, tests/regression_model_base.hpp).
#include "core/modelbase/model_base.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <set>
#include <vector>

#include "core/io/model_base_file.hpp"
#include "sim/view_sphere.hpp"
#include "tests/regression_model_base.hpp"

namespace cosmos {
namespace {

double angle_deg(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::acos(std::clamp(a.normalized().dot(b.normalized()), -1.0, 1.0)) * 180 /
         std::numbers::pi;
}

TEST(ModelBase, OnceSubdividedViewsAreTheMiddleChildrenOfThe80ViewSphere) {
  EXPECT_FALSE(is_once_subdivided_view(0));
  EXPECT_FALSE(is_once_subdivided_view(1));
  EXPECT_FALSE(is_once_subdivided_view(2));
  EXPECT_TRUE(is_once_subdivided_view(3));
  EXPECT_TRUE(is_once_subdivided_view(319));
  EXPECT_FALSE(is_once_subdivided_view(318));
  // View 4 f + 3 of the 320-view sphere lies at face centre f of the 80-view one; its corner
  // children 4 f .. 4 f + 2 do not.
  const std::vector<Eigen::Vector3d> fine = view_directions(2);
  const std::vector<Eigen::Vector3d> coarse = view_directions(1);
  ASSERT_EQ(fine.size(), 320u);
  ASSERT_EQ(coarse.size(), 80u);
  double worst_middle_deg = 0, nearest_corner_deg = 180;
  for (std::size_t face = 0; face < coarse.size(); ++face) {
    worst_middle_deg = std::max(worst_middle_deg, angle_deg(fine[4 * face + 3], coarse[face]));
    for (std::size_t child = 0; child < 3; ++child)
      nearest_corner_deg =
          std::min(nearest_corner_deg, angle_deg(fine[4 * face + child], coarse[face]));
  }
  EXPECT_LT(worst_middle_deg, 0.04);
  EXPECT_GT(nearest_corner_deg, 3.0);
}

class ModelBaseIndexing : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    base_ = std::make_unique<ModelBase>(read_model_base(testing::regression_model_base()));
  }
  static void TearDownTestSuite() { base_.reset(); }
  static inline std::unique_ptr<ModelBase> base_;
};

TEST_F(ModelBaseIndexing, EveryPartHasItsEightyOnceSubdividedViews) {
  const ModelBase& base = *base_;
  ASSERT_EQ(base.parts.size(), 5u);
  ASSERT_EQ(base.views.size(), 400u);
  const std::vector<Eigen::Vector3d> directions = view_directions(2);
  std::vector<std::set<int>> view_indices(base.parts.size());
  for (const ModelBaseView& view : base.views) {
    ASSERT_GE(view.part_index, 0);
    ASSERT_LT(view.part_index, 5);
    EXPECT_TRUE(is_once_subdivided_view(view.view_index)) << view.view_index;
    view_indices[static_cast<std::size_t>(view.part_index)].insert(view.view_index);
    // direction_part is the view sphere's direction of its index, and the pose the view was
    // scanned in turns it towards the scanner (+z).
    EXPECT_LT(angle_deg(view.direction_part, directions[static_cast<std::size_t>(view.view_index)]),
              1e-6);
    EXPECT_LT(
        angle_deg(view.T_scanner_part.rotation * view.direction_part, Eigen::Vector3d::UnitZ()),
        1e-6);
  }
  for (const std::set<int>& indices : view_indices) EXPECT_EQ(indices.size(), 80u);
}

TEST_F(ModelBaseIndexing, ClustersPartitionEachPartsViewsAndHoldTheirMeanMoments) {
  const ModelBase& base = *base_;
  ASSERT_FALSE(base.clusters.empty());
  std::vector<int> cluster_of_view(base.views.size(), -1);
  for (std::size_t c = 0; c < base.clusters.size(); ++c) {
    const ViewCluster& cluster = base.clusters[c];
    ASSERT_FALSE(cluster.views.empty()) << c;
    MomentVector mean{};
    for (int v : cluster.views) {
      ASSERT_GE(v, 0);
      ASSERT_LT(v, static_cast<int>(base.views.size()));
      EXPECT_EQ(cluster_of_view[static_cast<std::size_t>(v)], -1) << "view " << v << " twice";
      cluster_of_view[static_cast<std::size_t>(v)] = static_cast<int>(c);
      const ModelBaseView& view = base.views[static_cast<std::size_t>(v)];
      EXPECT_EQ(view.part_index, cluster.part_index) << "cluster " << c << ", view " << v;
      for (std::size_t f = 0; f < mean.size(); ++f) mean[f] += view.moments[f];
    }
    // §4.4.2: the centroid is the mean moment vector of the cluster's views.
    for (std::size_t f = 0; f < mean.size(); ++f)
      EXPECT_NEAR(cluster.centroid[f], mean[f] / static_cast<double>(cluster.views.size()),
                  1e-12 * (1 + std::abs(cluster.centroid[f])))
          << "cluster " << c << ", moment " << f;
  }
  EXPECT_EQ(std::count(cluster_of_view.begin(), cluster_of_view.end(), -1), 0)
      << "views in no cluster";
  // Each part has clusters of its own.
  std::set<int> parts_with_clusters;
  for (const ViewCluster& cluster : base.clusters) parts_with_clusters.insert(cluster.part_index);
  EXPECT_EQ(parts_with_clusters.size(), base.parts.size());
}

TEST_F(ModelBaseIndexing, ALoadedBaseKeepsOnlyThePackedRegistrationPoints) {
  for (const ModelBaseView& view : base_->views) {
    ASSERT_EQ(view.registration.size(), 0);
    ASSERT_GT(view.registration_packed.size(), 100);
    ASSERT_TRUE(packed_registration_points_consistent(view.registration_packed));
  }
}

}  // namespace
}  // namespace cosmos
