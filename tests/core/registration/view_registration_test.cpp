// Chapter 6 reproduction: Chen-Medioni and minimum-variance registration (§6.4, §6.6) on view
// pairs with known transforms (Tables 6.1 and 6.3), started from the identity or from the
// principal-axes estimate (§6.7.2); degenerate and missing overlap.
#include "core/registration/view_registration.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "core/registration/principal_axes_estimate.hpp"
#include "core/registration/registration_points.hpp"
#include "core/rigid_transform.hpp"
#include "sim/free_form_view_pair.hpp"
#include "tests/core/registration/plane_range_image.hpp"

namespace cosmos::testing {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// ---------------------------------------------------------------- registration, Tables 6.1 / 6.3

struct TrialStatistics {
  int trials = 0, converged = 0;
  double sum_E_R = 0, sum_E_t = 0, sum_iterations = 0, sum_inlier_fraction = 0, sum_rms_mm = 0;
  void add(const RegistrationResult& r, const RigidTransform& truth) {
    ++trials;
    converged += r.converged ? 1 : 0;
    sum_E_R += relative_rotation_error(r.T_model_scene.rotation, truth.rotation);
    sum_E_t += translation_error_mm(r.T_model_scene, truth);
    sum_iterations += r.iterations;
    sum_inlier_fraction += r.inlier_fraction;
    sum_rms_mm += r.rms_residual_mm;
  }
  double mean_E_R() const { return sum_E_R / trials; }
  double mean_E_t() const { return sum_E_t / trials; }
};

struct ViewPairExperiment {
  const char* name;
  RigidTransform T_scanner2_part;  // view 2 (the scene); view 1 (the model) is the part frame
  double noise_mm;                 // on both views
  // 0: start from the identity. Otherwise start from the principal-axes estimate (§6.7.2)
  // turned by this angle about a random axis and shifted 1 mm, per trial: with this part the
  // estimate is already within ~0.05 degrees, far better than the thesis's coarse starts.
  double principal_axes_perturbation_deg;
};

struct ExperimentOutcome {
  TrialStatistics chen_medioni, minimum_variance;
  double mean_initial_angle_deg = 0;
};

constexpr int kTrials = 50;

// Per trial: fresh seeded noise on both views, model control points at every pixel, scene
// control points every 2nd pixel (~2,250), both estimators from the same start.
ExperimentOutcome run_experiment(const ViewPairExperiment& e) {
  const FreeFormPartSpec spec;
  const RangeImage model_clean = render_free_form_part(RigidTransform::identity(), spec);
  const RangeImage scene_clean = render_free_form_part(e.T_scanner2_part, spec);
  const RigidTransform truth = e.T_scanner2_part.inverse();  // T_model_scene
  ExperimentOutcome outcome;
  int scene_points = 0;
  for (int trial = 0; trial < kTrials; ++trial) {
    RangeImage model_image = model_clean, scene_image = scene_clean;
    add_z_noise(model_image, e.noise_mm, 2 * trial + 1);
    add_z_noise(scene_image, e.noise_mm, 2 * trial + 2);
    const auto model = build_registration_points(model_image, {.stride_px = 1});
    const auto scene = build_registration_points(scene_image, {.stride_px = 2});
    EXPECT_EQ(model.status, RegistrationPointsStatus::kOk);
    EXPECT_EQ(scene.status, RegistrationPointsStatus::kOk);
    scene_points = scene.points.size();
    RegistrationParameters parameters;
    RigidTransform initial = RigidTransform::identity();
    if (e.principal_axes_perturbation_deg > 0) {
      initial = estimate_by_principal_axes(scene.points, model.points, parameters).T_model_scene;
      std::mt19937_64 generator(1000 + trial);
      std::normal_distribution<double> normal;
      Eigen::Vector3d axis, shift_mm;
      for (int k = 0; k < 3; ++k) axis(k) = normal(generator);
      for (int k = 0; k < 3; ++k) shift_mm(k) = normal(generator);
      const RigidTransform perturbation{
          Eigen::AngleAxisd(e.principal_axes_perturbation_deg * kDeg, axis.normalized())
              .toRotationMatrix(),
          shift_mm.normalized()};
      initial = perturbation * initial;
    }
    outcome.mean_initial_angle_deg +=
        rotation_angle_between_rad(initial.rotation, truth.rotation) / kDeg / kTrials;
    parameters.estimator = RegistrationEstimator::kChenMedioni;
    outcome.chen_medioni.add(register_views(scene.points, model.points, initial, parameters),
                             truth);
    parameters.estimator = RegistrationEstimator::kMinimumVariance;
    outcome.minimum_variance.add(register_views(scene.points, model.points, initial, parameters),
                                 truth);
  }
  std::printf(
      "%s, noise %.2f mm, %d trials, %d scene control points, initial rotation error %.2f deg\n",
      e.name, e.noise_mm, kTrials, scene_points, outcome.mean_initial_angle_deg);
  for (const auto& [label, s] :
       {std::pair{"C-M", &outcome.chen_medioni}, std::pair{"MVE", &outcome.minimum_variance}})
    std::printf(
        "  %s: converged %d/%d, mean E_R %.6f, mean E_t %.5f mm, iterations %.1f, inliers %.3f, "
        "rms %.4f mm\n",
        label, s->converged, s->trials, s->mean_E_R(), s->mean_E_t(), s->sum_iterations / s->trials,
        s->sum_inlier_fraction / s->trials, s->sum_rms_mm / s->trials);
  ::testing::Test::RecordProperty("chen_medioni_mean_E_R",
                                  std::to_string(outcome.chen_medioni.mean_E_R()));
  ::testing::Test::RecordProperty("mve_mean_E_R",
                                  std::to_string(outcome.minimum_variance.mean_E_R()));
  ::testing::Test::RecordProperty("chen_medioni_mean_E_t_mm",
                                  std::to_string(outcome.chen_medioni.mean_E_t()));
  ::testing::Test::RecordProperty("mve_mean_E_t_mm",
                                  std::to_string(outcome.minimum_variance.mean_E_t()));
  return outcome;
}

void expect_thesis_claims(const ExperimentOutcome& outcome) {
  const TrialStatistics& cm = outcome.chen_medioni;
  const TrialStatistics& mve = outcome.minimum_variance;
  EXPECT_EQ(cm.converged, kTrials);
  EXPECT_EQ(mve.converged, kTrials);
  // §6.7.4: the minimum-variance estimate is closer to the truth than Chen-Medioni's.
  EXPECT_LE(mve.mean_E_R(), cm.mean_E_R());
  EXPECT_LT(mve.mean_E_R(), 0.01);
  EXPECT_LT(cm.mean_E_R(), 0.01);
  EXPECT_LT(mve.mean_E_t(), 0.1);
  EXPECT_LT(cm.mean_E_t(), 0.1);
  // Tighter than the thesis asks: ~2,000 control points and 0.03-0.05 mm noise measure about
  // 1e-4 here (0.006 degrees); a regression that lost an order of magnitude shows.
  EXPECT_LT(mve.mean_E_R(), 5e-4);
  EXPECT_LT(mve.mean_E_t(), 0.01);
}

// Table 6.1 (cobra): view 2 turned 5 degrees about x and 10 about z; started from the
// identity, i.e. 11.2 degrees off.
TEST(ViewRegistration, Table6_1_FiveDegreesAboutXAndTenAboutZ) {
  const ExperimentOutcome outcome =
      run_experiment({"Table 6.1: 5 deg about x + 10 deg about z",
                      {rotation_from_xyz_angles_deg(5, 0, 10), {1.5, -1.0, 0.8}},
                      0.03,
                      0.0});
  expect_thesis_claims(outcome);
  EXPECT_NEAR(outcome.mean_initial_angle_deg, 11.18, 0.01);
}

// Table 6.3 (Big-Y): view 2 turned 45 degrees about z, the noisier case; started from the
// principal-axes estimate perturbed by 4 degrees.
TEST(ViewRegistration, Table6_3_FortyFiveDegreesAboutZ) {
  const ExperimentOutcome outcome =
      run_experiment({"Table 6.3: 45 deg about z",
                      {rotation_from_xyz_angles_deg(0, 0, 45), {-2.0, 1.5, 0.5}},
                      0.05,
                      4.0});
  expect_thesis_claims(outcome);
}

TEST(ViewRegistration, ReportsDegenerateAndMissingOverlap) {
  RangeImage plane_image = tilted_plane(10.0, 61, 0.5);
  add_z_noise(plane_image, 0.02, 3);
  const auto plane = build_registration_points(plane_image, {}).points;
  const auto plane_scene = build_registration_points(plane_image, {.stride_px = 2}).points;
  // A plane leaves the in-plane translations and the rotation about its normal free (§6.8).
  EXPECT_EQ(register_views(plane_scene, plane, RigidTransform::identity(), {}).status,
            RegistrationStatus::kDegenerate);
  const RangeImage part_image =
      render_free_form_part(RigidTransform::identity(), FreeFormPartSpec{});
  const auto part = build_registration_points(part_image, {}).points;
  const auto part_scene = build_registration_points(part_image, {.stride_px = 2}).points;
  const RegistrationResult far =
      register_views(part_scene, part, {Eigen::Matrix3d::Identity(), {500, 0, 0}}, {});
  EXPECT_EQ(far.status, RegistrationStatus::kTooFewCorrespondences);
  EXPECT_FALSE(far.converged);
  EXPECT_EQ(register_views(RegistrationPoints{}, part, {}, {}).status,
            RegistrationStatus::kInvalidInput);
  // Identical views from the identity: converged at once, zero residual.
  const RegistrationResult same = register_views(part_scene, part, {}, {});
  EXPECT_TRUE(same.converged);
  EXPECT_LT(same.rms_residual_mm, 1e-3);
  EXPECT_LT(relative_rotation_error(same.T_model_scene.rotation, Eigen::Matrix3d::Identity()),
            1e-6);
}

// A roof of two faces sloping 1 in 2, the ridge at x = 5 mm, two thirds of it the face on its
// left: a start moved 0.45 mm along that face fits it exactly and leaves the other face 0.36 mm
// off. With no point nearer than 0.2 mm rejected, the other face's points are outliers to the
// face that fits, and nothing pulls the pose back; a floor above their offset keeps them, and
// they do.
TEST(ViewRegistration, ARejectionFloorAboveTheOffsetLetsTheOtherFacePullThePoseBack) {
  RangeImage roof(61, 61, 0.5, 0.5);
  roof.origin_x_mm = roof.origin_y_mm = -15.0;
  for (int row = 0; row < roof.height(); ++row)
    for (int column = 0; column < roof.width(); ++column) {
      const double x = roof.x_mm(column);
      roof.z_mm(column, row) = static_cast<float>(5.0 + 0.5 * std::min(x, 10.0 - x));
    }
  const auto model = build_registration_points(roof, {}).points;
  const auto scene = build_registration_points(roof, {.stride_px = 2}).points;
  const Eigen::Vector3d along_left_face = Eigen::Vector3d(1.0, 0.0, 0.5).normalized();
  const RigidTransform start{Eigen::Matrix3d::Identity(), 0.45 * along_left_face};
  RegistrationParameters tight;
  tight.min_rejection_distance_mm = 0.2;
  RegistrationParameters wide = tight;
  wide.min_rejection_distance_mm = 0.5;
  const double stuck_mm =
      register_views(scene, model, start, tight).T_model_scene.translation_mm.norm();
  const double pulled_mm =
      register_views(scene, model, start, wide).T_model_scene.translation_mm.norm();
  EXPECT_GT(stuck_mm, 0.3);
  EXPECT_LT(pulled_mm, 0.05);
}

// The same roof, 10 mm higher, as the top of a block standing on the belt (z = 0), with no
// point nearer than 0.2 mm rejected: the start slid along the left face sinks the block 0.2 mm
// into the belt. Held on the belt by its lowest corners, the registration slides it back up the
// face; free of it, or with the belt's weight 0, the pose stays where the face fits.
TEST(ViewRegistration, ThePartsLowestCornerHeldOnTheBeltStopsASlideAlongAFace) {
  const auto top_mm = [](double x) { return 15.0 + 0.5 * std::min(x, 10.0 - x); };
  RangeImage roof(61, 61, 0.5, 0.5);
  roof.origin_x_mm = roof.origin_y_mm = -15.0;
  for (int row = 0; row < roof.height(); ++row)
    for (int column = 0; column < roof.width(); ++column) {
      const double x = roof.x_mm(column);
      roof.z_mm(column, row) = static_cast<float>(top_mm(x));
    }
  const auto model = build_registration_points(roof, {}).points;
  const auto scene = build_registration_points(roof, {.stride_px = 2}).points;
  std::vector<Eigen::Vector3d> block_corners_mm;
  for (const double x : {-15.0, 15.0})
    for (const double y : {-15.0, 15.0}) {
      block_corners_mm.emplace_back(x, y, 0.0);
      block_corners_mm.emplace_back(x, y, top_mm(x));
    }
  block_corners_mm.emplace_back(5.0, -15.0, top_mm(5.0));
  block_corners_mm.emplace_back(5.0, 15.0, top_mm(5.0));
  const Eigen::Vector3d along_left_face = Eigen::Vector3d(1.0, 0.0, 0.5).normalized();
  const RigidTransform start{Eigen::Matrix3d::Identity(), 0.45 * along_left_face};
  RegistrationParameters tight;
  tight.min_rejection_distance_mm = 0.2;
  const BeltContact belt{block_corners_mm, RigidTransform::identity(), 1.0};
  const RegistrationResult held =
      register_views(scene, model, start, tight, one_after_another(), belt);
  const RegistrationResult free = register_views(scene, model, start, tight);
  EXPECT_LT(held.T_model_scene.translation_mm.norm(), 0.05);
  EXPECT_LT(rotation_angle_between_rad(held.T_model_scene.rotation, Eigen::Matrix3d::Identity()),
            1e-3);
  EXPECT_GT(free.T_model_scene.translation_mm.norm(), 0.3);
  BeltContact weightless = belt;
  weightless.weight = 0.0;
  EXPECT_GT(register_views(scene, model, start, tight, one_after_another(), weightless)
                .T_model_scene.translation_mm.norm(),
            0.3);
}

}  // namespace
}  // namespace cosmos::testing
