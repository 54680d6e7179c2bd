// Part support (the recognizer's decision): the fraction of scene control points within the
// inlier distance of the part's surface, and their RMS distance, with the part's surface the
// matched view together with its neighbouring views. A hand-made base of planar views whose
// coverage and placement are known, so every fraction is counted by hand.
#include "core/recognition/part_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "core/modelbase/model_surface.hpp"
#include "core/registration/registration_points.hpp"
#include "tests/common/plane_view_points.hpp"
#include "tests/core/backwards_task_runner.hpp"

namespace cosmos {
namespace {

using testing::kPlaneHeightMm;
using testing::plane_view_points;

constexpr double kDeg = std::numbers::pi / 180.0;

Eigen::Vector3d direction_at_deg(double angle_deg) {
  return {std::sin(angle_deg * kDeg), 0.0, std::cos(angle_deg * kDeg)};
}

// Part 0 seen by view 0 over part x in [-12, 1] (its scanner frame is the part frame) and by
// view 1 over part x in [-1, 12], 30 degrees away, whose scanner frame is the part shifted by
// 20 mm in x; part 1 holds a view like view 1 that must never be asked.
const std::vector<int> kPartZeroViews = {0, 1};
ModelBase two_view_base(double second_view_angle_deg) {
  ModelBase base;
  base.parts = {{"plate", "plate.off", 24, 24, false, {}, {}, {}, {}, {}},
                {"other", "other.off", 24, 24, false, {}, {}, {}, {}, {}}};
  ModelBaseView matched;
  matched.part_index = 0;
  matched.direction_part = direction_at_deg(0.0);
  matched.registration = plane_view_points(-12.0);
  ModelBaseView neighbour;
  neighbour.part_index = 0;
  neighbour.view_index = 1;
  neighbour.direction_part = direction_at_deg(second_view_angle_deg);
  neighbour.T_scanner_part = {Eigen::Matrix3d::Identity(), {20.0, 0.0, 0.0}};
  neighbour.registration = plane_view_points(-1.0 + 20.0);
  ModelBaseView elsewhere = neighbour;
  elsewhere.part_index = 1;
  elsewhere.T_scanner_part = RigidTransform::identity();
  elsewhere.registration = plane_view_points(-1.0);
  base.views = {matched, neighbour, elsewhere};
  return base;
}

// Scene points over x = -8.75, -8.25, ..., 8.75 (half of them at x < 0) and `rows` rows of y
// over [-6, 6] mm, each `offset_mm(index)` above the plane, normals +z.
template <class Offset>
RegistrationPoints scene_points(Offset offset_mm, int rows = 5) {
  std::vector<Eigen::Vector3d> positions;
  for (int row = 0; row < rows; ++row)
    for (int k = 0; k < 36; ++k) {
      const int index = static_cast<int>(positions.size());
      positions.emplace_back(-8.75 + 0.5 * k, -6.0 + 12.0 * row / (rows - 1),
                             kPlaneHeightMm + offset_mm(index));
    }
  RegistrationPoints scene;
  const auto n = static_cast<Eigen::Index>(positions.size());
  scene.position_mm.resize(3, n);
  for (Eigen::Index i = 0; i < n; ++i)
    scene.position_mm.col(i) = positions[static_cast<std::size_t>(i)];
  scene.normal = Eigen::Matrix3Xd::Zero(3, n);
  scene.normal.row(2).setOnes();
  scene.surface =
      Eigen::Matrix<double, kSurfaceCoefficients, Eigen::Dynamic>::Zero(kSurfaceCoefficients, n);
  scene.residual_rms_mm = Eigen::VectorXd::Zero(n);
  scene.z_noise_sigma_mm = 0.02;
  return scene;
}

PartSupport support_of(const RegistrationPoints& scene, const ModelBase& base,
                       const PartSupportParameters& parameters = {},
                       const TaskRunner& tasks = one_after_another()) {
  ModelSurfaces surfaces(base, ModelSurfaceCacheParameters{});
  return measure_part_support(scene, base, kPartZeroViews, 0, RigidTransform::identity(),
                              RegistrationParameters{}, parameters, surfaces, tasks);
}

TEST(PartSupport, CountsThePointsWithinTheInlierDistanceAndTheirRms) {
  const ModelBase base = two_view_base(30.0);
  // Every third point 0.05 mm below the surface, every third 0.15 mm above, the others 0.6 mm
  // above: two thirds within the default 0.2 mm.
  const auto offset = [](int i) { return i % 3 == 0 ? -0.05 : i % 3 == 1 ? 0.15 : 0.6; };
  const RegistrationPoints scene = scene_points(offset);
  ASSERT_EQ(scene.size() % 3, 0);
  const PartSupport support = support_of(scene, base);
  EXPECT_NEAR(support.inlier_fraction, 2.0 / 3, 1e-12);
  EXPECT_NEAR(support.rms_mm, std::sqrt((0.05 * 0.05 + 0.15 * 0.15) / 2), 1e-5);
  // A tighter inlier distance leaves only the points 0.05 mm away.
  const PartSupport tight = support_of(scene, base, {.inlier_distance_mm = 0.1});
  EXPECT_NEAR(tight.inlier_fraction, 1.0 / 3, 1e-12);
  EXPECT_NEAR(tight.rms_mm, 0.05, 1e-5);
}

// The matched view sees x < 0 of the scene; its neighbour, 30 degrees away and placed 20 mm off
// in its own scanner frame, the rest, once brought there through the part frame.
TEST(PartSupport, NeighbouringViewsOfThePartExplainWhatTheMatchedViewMisses) {
  const RegistrationPoints scene = scene_points([](int) { return 0.05; });
  const PartSupport both = support_of(scene, two_view_base(30.0));
  EXPECT_NEAR(both.inlier_fraction, 1.0, 1e-12);
  EXPECT_NEAR(both.rms_mm, 0.05, 1e-5);
  EXPECT_EQ(both.views_used, 2);

  const PartSupport alone = support_of(scene, two_view_base(30.0), {.max_neighbour_views = 0});
  EXPECT_NEAR(alone.inlier_fraction, 0.5, 1e-12);
  EXPECT_EQ(alone.views_used, 1);

  // 50 degrees away the second view is no neighbour; the other part's view never counts.
  const PartSupport far = support_of(scene, two_view_base(50.0));
  EXPECT_NEAR(far.inlier_fraction, 0.5, 1e-12);
  EXPECT_EQ(far.views_used, 1);
  const PartSupport wider =
      support_of(scene, two_view_base(50.0), {.neighbour_view_angle_deg = 60.0});
  EXPECT_NEAR(wider.inlier_fraction, 1.0, 1e-12);
}

// Each view's points asked in shares that end in any order (a backwards runner): the same
// support to the bit, on the matched view and on the neighbour asked about what it missed.
TEST(PartSupport, PointsAskedInSharesGiveTheSameSupport) {
  const ModelBase base = two_view_base(30.0);
  const auto offset = [](int i) { return i % 3 == 0 ? -0.05 : i % 3 == 1 ? 0.15 : 0.6; };
  const RegistrationPoints scene = scene_points(offset, 30);
  const PartSupport alone = support_of(scene, base);
  const BackwardsTaskRunner backwards;
  const PartSupport shared = support_of(scene, base, {}, backwards);
  EXPECT_EQ(shared.inlier_fraction, alone.inlier_fraction);
  EXPECT_EQ(shared.rms_mm, alone.rms_mm);
  EXPECT_EQ(shared.views_used, 2);
  EXPECT_EQ(alone.views_used, 2);
  EXPECT_NEAR(alone.inlier_fraction, 2.0 / 3, 1e-12);
  // 1,080 points on the matched view, the 720 it did not explain on its neighbour: two
  // batches of two shares.
  EXPECT_EQ(backwards.batches, 2);
  EXPECT_EQ(backwards.tasks, 4);
}

// The scene registered 3 mm too high: nothing within 0.2 mm (the lines meet the plane 3 mm away).
TEST(PartSupport, AWrongPoseOrAnEmptySceneIsSupportedByNothing) {
  const ModelBase base = two_view_base(30.0);
  const RegistrationPoints scene = scene_points([](int) { return 0.0; });
  ModelSurfaces surfaces(base, ModelSurfaceCacheParameters{});
  const PartSupport lifted = measure_part_support(
      scene, base, kPartZeroViews, 0, {Eigen::Matrix3d::Identity(), {0.0, 0.0, 3.0}},
      RegistrationParameters{}, PartSupportParameters{}, surfaces);
  EXPECT_EQ(lifted.inlier_fraction, 0.0);
  EXPECT_EQ(lifted.rms_mm, 0.0);
  EXPECT_EQ(lifted.views_used, 2);  // the neighbour was asked, in vain
  const PartSupport empty = measure_part_support(
      RegistrationPoints{}, base, kPartZeroViews, 0, RigidTransform::identity(),
      RegistrationParameters{}, PartSupportParameters{}, surfaces);
  EXPECT_EQ(empty.inlier_fraction, 0.0);
  EXPECT_EQ(empty.views_used, 0);
}

}  // namespace
}  // namespace cosmos
