// The motion registration leaves free (§6.8), searched: a barrel (a surface of revolution about
// x whose radius grows away from its middle, so that it cannot slide) seen from above with one
// narrow ridge along it, the scene the same surface turned about the axis. From the unturned
// pose registration fits the barrel and rejects the ridge's points: the turn is its least
// constrained motion, and the search along it finds the turn back.
#include "core/registration/free_motion_search.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <optional>

#include "core/range_image.hpp"
#include "core/registration/registration_points.hpp"
#include "core/registration/view_registration.hpp"
#include "tests/core/backwards_task_runner.hpp"

namespace cosmos::testing {
namespace {

constexpr double kRadiusMm = 20.0;
constexpr double kDeg = std::numbers::pi / 180.0;

// The top of a barrel along x, of radius 20 mm at its middle, with a ridge 1.5 mm high and
// about 6 degrees wide at `ridge_deg` from the top, seen from above (orthographic), 0.5 mm
// pixels.
RangeImage ridged_cylinder(double ridge_deg) {
  constexpr int kWidth = 60, kHeight = 60;
  RangeImage image(kWidth, kHeight, 0.5, 0.5);
  image.origin_x_mm = -0.5 * (kWidth - 1) * 0.5;
  image.origin_y_mm = -0.5 * (kHeight - 1) * 0.5;
  for (int row = 0; row < kHeight; ++row)
    for (int column = 0; column < kWidth; ++column) {
      const double x = image.x_mm(column), y = image.y_mm(row);
      const double barrel_mm = kRadiusMm + 0.05 * x * x;
      const double angle = std::asin(y / barrel_mm);
      const double from_ridge = (angle - ridge_deg * kDeg) / (3 * kDeg);
      const double radius = barrel_mm + 1.5 * std::exp(-from_ridge * from_ridge);
      image.z_mm(column, row) = static_cast<float>(std::sqrt(radius * radius - y * y));
    }
  return image;
}

RegistrationPoints points_of(const RangeImage& image, int stride_px) {
  RegistrationPointParameters parameters;
  parameters.stride_px = stride_px;
  parameters.z_noise_sigma_mm = 0.01;
  parameters.max_residual_noise_ratio = 1e3;
  return build_registration_points(image, parameters).points;
}

TEST(FreeMotionSearch, FindsTheTurnAboutABarrelsAxisThatRegistrationLeftFree) {
  const RegistrationPoints model = points_of(ridged_cylinder(0), 1);
  const RegistrationPoints scene = points_of(ridged_cylinder(12), 2);
  RegistrationParameters registration;
  registration.max_iterations = 30;
  const RegistrationResult registered =
      register_views(scene, model, RigidTransform{}, registration);
  ASSERT_NE(registered.status, RegistrationStatus::kInvalidInput);
  // The barrel holds the pose; the ridge, off by 12 degrees, is left out.
  const double turned_deg =
      std::acos(std::clamp((registered.T_model_scene.rotation.trace() - 1) / 2, -1.0, 1.0)) / kDeg;
  EXPECT_LT(turned_deg, 6.0);
  EXPECT_LT(registered.weakest_constraint, 0.02);
  // A turn about x, the axis: about the inliers' centre, 20 mm above the axis, with the
  // centre's slide across it.
  const Eigen::Vector3d turn_part = registered.weakest_motion.head<3>();
  EXPECT_GT(turn_part.norm(), 0.3);
  EXPECT_GT(std::abs(turn_part.x()) / turn_part.norm(), 0.95);

  // The barrel's curvature along its axis constrains this small patch's turn a little more
  // than the default bound (set for whole parts' views) lets through.
  FreeMotionSearchParameters search;
  search.max_constraint = 0.02;
  const std::optional<RigidTransform> found =
      search_free_motion(scene, model, registered, registration, 0.2, search);
  ASSERT_TRUE(found.has_value());
  const RegistrationResult again = register_views(scene, model, *found, registration);
  // The scene turned by +12 degrees about x: registered onto the model it turns back.
  const Eigen::AngleAxisd turn(again.T_model_scene.rotation);
  EXPECT_NEAR(turn.angle() / kDeg, 12.0, 1.5);
  EXPECT_GT(std::abs(turn.axis().x()), 0.95);
  // Scored in shares that end in any order, the positions give the same pose to the bit.
  const BackwardsTaskRunner backwards;
  const std::optional<RigidTransform> in_shares =
      search_free_motion(scene, model, registered, registration, 0.2, search, backwards);
  ASSERT_TRUE(in_shares.has_value());
  EXPECT_EQ(in_shares->rotation, found->rotation);
  EXPECT_EQ(in_shares->translation_mm, found->translation_mm);
  EXPECT_EQ(backwards.tasks, 2);
  RegistrationParameters strict = registration;
  strict.max_correspondence_distance_mm = 0.2;
  EXPECT_GT(
      score_alignment(scene, model, again.T_model_scene, strict).matched_fraction,
      score_alignment(scene, model, registered.T_model_scene, strict).matched_fraction + 0.02);
}

TEST(FreeMotionSearch, LeavesAConstrainedPoseOrADisabledSearchAlone) {
  const RegistrationPoints model = points_of(ridged_cylinder(0), 1);
  const RegistrationPoints scene = points_of(ridged_cylinder(0), 2);
  const RegistrationResult registered =
      register_views(scene, model, RigidTransform{}, RegistrationParameters{});
  FreeMotionSearchParameters constrained_only;
  constrained_only.max_constraint = 0;  // nothing is free enough to search
  EXPECT_FALSE(
      search_free_motion(scene, model, registered, RegistrationParameters{}, 0.2, constrained_only)
          .has_value());
  // Already at the truth: no position explains more.
  EXPECT_FALSE(search_free_motion(scene, model, registered, RegistrationParameters{}, 0.2,
                                  FreeMotionSearchParameters{})
                   .has_value());
  FreeMotionSearchParameters off;
  off.enabled = false;
  EXPECT_FALSE(
      search_free_motion(scene, model, registered, RegistrationParameters{}, 0.2, off).has_value());
}

}  // namespace
}  // namespace cosmos::testing
