// The principal-axes estimate (§6.7.2): R = M_model M_scene^-1 from the eigenvectors of the
// two views' scatter matrices, t from the centroids; eigenvectors have no sign, so four proper
// rotations are candidates, and the one that aligns the views best is kept.
#include "core/registration/principal_axes_estimate.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "core/registration/registration_points.hpp"
#include "core/rigid_transform.hpp"
#include "sim/free_form_view_pair.hpp"

namespace cosmos::testing {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// Scene-like points with positions only (what the estimate looks at).
RegistrationPoints points_at(const std::vector<Eigen::Vector3d>& positions_mm) {
  RegistrationPoints points;
  points.position_mm.resize(3, static_cast<Eigen::Index>(positions_mm.size()));
  for (std::size_t i = 0; i < positions_mm.size(); ++i)
    points.position_mm.col(static_cast<Eigen::Index>(i)) = positions_mm[i];
  points.normal = Eigen::Matrix3Xd::Zero(3, points.position_mm.cols());
  points.normal.row(2).setOnes();
  points.surface = Eigen::Matrix<double, kSurfaceCoefficients, Eigen::Dynamic>::Zero(
      kSurfaceCoefficients, points.position_mm.cols());
  points.residual_rms_mm = Eigen::VectorXd::Zero(points.position_mm.cols());
  return points;
}

std::vector<Eigen::Vector3d> transformed(const std::vector<Eigen::Vector3d>& positions_mm,
                                         const RigidTransform& T) {
  std::vector<Eigen::Vector3d> out;
  for (const Eigen::Vector3d& p : positions_mm) out.push_back(T.apply(p));
  return out;
}

// Points spread uniformly over a 30 x 12 x 4 mm box: three well-separated axes.
std::vector<Eigen::Vector3d> anisotropic_cloud() {
  std::mt19937_64 generator(17);
  std::uniform_real_distribution<double> unit(-0.5, 0.5);
  std::vector<Eigen::Vector3d> cloud;
  for (int i = 0; i < 400; ++i)
    cloud.emplace_back(30 * unit(generator), 12 * unit(generator), 4 * unit(generator));
  return cloud;
}

TEST(PrincipalAxesEstimate, CandidatesAreTheTrueRotationAndItsThreeHalfTurns) {
  const RigidTransform T_model_scene{rotation_from_xyz_angles_deg(20, -35, 110), {4, -7, 12}};
  const std::vector<Eigen::Vector3d> model_positions = anisotropic_cloud();
  const RegistrationPoints model = points_at(model_positions);
  const RegistrationPoints scene = points_at(transformed(model_positions, T_model_scene.inverse()));
  const std::vector<RigidTransform> candidates = principal_axes_candidates(scene, model);
  ASSERT_EQ(candidates.size(), 4u);
  const Eigen::Vector3d scene_centroid = scene.position_mm.rowwise().mean();
  const Eigen::Vector3d model_centroid = model.position_mm.rowwise().mean();
  int true_ones = 0, half_turns = 0;
  for (const RigidTransform& candidate : candidates) {
    EXPECT_NEAR(candidate.rotation.determinant(), 1.0, 1e-12);
    EXPECT_LT(
        (candidate.rotation * candidate.rotation.transpose() - Eigen::Matrix3d::Identity()).norm(),
        1e-12);
    // Every candidate takes the scene's centroid onto the model's.
    EXPECT_LT((candidate.apply(scene_centroid) - model_centroid).norm(), 1e-9);
    const double angle = rotation_angle_between_rad(candidate.rotation, T_model_scene.rotation);
    if (angle < 1e-9) {
      ++true_ones;
      EXPECT_LT(translation_error_mm(candidate, T_model_scene), 1e-9);
    }
    half_turns += std::abs(angle - std::numbers::pi) < 1e-9;
  }
  EXPECT_EQ(true_ones, 1);
  EXPECT_EQ(half_turns, 3);
}

// Six points at +-(a, 0, 0), +-(0, b, 0), +-(0, 0, c): the scatter is diag(a^2, b^2, c^2) / 3,
// so the smallest relative gap between consecutive eigenvalues is known in closed form.
std::vector<Eigen::Vector3d> six_points(double a, double b, double c) {
  return {{a, 0, 0}, {-a, 0, 0}, {0, b, 0}, {0, -b, 0}, {0, 0, c}, {0, 0, -c}};
}

TEST(PrincipalAxesEstimate, EigenvalueGapDecidesWhetherTheAxesAreDefined) {
  const RigidTransform T_model_scene{rotation_from_xyz_angles_deg(0, 0, 30), {1, 2, 3}};
  const RegistrationParameters parameters;
  const auto estimate_for = [&](double a, double b, double c, double min_gap) {
    const std::vector<Eigen::Vector3d> model_positions = six_points(a, b, c);
    return estimate_by_principal_axes(
        points_at(transformed(model_positions, T_model_scene.inverse())),
        points_at(model_positions), parameters, min_gap);
  };
  // Eigenvalues 1/3, 4/3, 3: gaps 1 and 5/3, relative to the largest: 1/3.
  const PrincipalAxesEstimate distinct = estimate_for(3, 2, 1, 0.05);
  EXPECT_EQ(distinct.status, PrincipalAxesStatus::kOk);
  EXPECT_NEAR(distinct.min_relative_eigenvalue_gap, 1.0 / 3, 1e-12);
  // a = 2.1, b = 2: (4.41 - 4) / 4.41.
  EXPECT_NEAR(estimate_for(2.1, 2, 1, 0.05).min_relative_eigenvalue_gap, 0.41 / 4.41, 1e-12);
  EXPECT_EQ(estimate_for(2.1, 2, 1, 0.05).status, PrincipalAxesStatus::kOk);
  EXPECT_EQ(estimate_for(2.1, 2, 1, 0.1).status, PrincipalAxesStatus::kAmbiguousAxes);
  // A round footprint: the in-plane axes are anyone's.
  const PrincipalAxesEstimate round = estimate_for(2, 2, 1, 0.05);
  EXPECT_EQ(round.status, PrincipalAxesStatus::kAmbiguousAxes);
  EXPECT_NEAR(round.min_relative_eigenvalue_gap, 0.0, 1e-12);
}

TEST(PrincipalAxesEstimate, FewerThanThreePointsGiveNothing) {
  const RegistrationPoints two = points_at({{0, 0, 0}, {1, 0, 0}});
  const RegistrationPoints many = points_at(six_points(3, 2, 1));
  EXPECT_TRUE(principal_axes_candidates(two, many).empty());
  EXPECT_TRUE(principal_axes_candidates(many, two).empty());
  EXPECT_EQ(estimate_by_principal_axes(two, many, RegistrationParameters{}).status,
            PrincipalAxesStatus::kTooFewPoints);
}

// The free-form part turned 45 degrees about z (Table 6.3's pose): of the four candidates the
// estimate keeps the one with the lowest truncated mean square, and it is within half a degree
// and half a millimetre of the truth.
TEST(PrincipalAxesEstimate, RecoversTheFortyFiveDegreeTurnOfTheFreeFormPart) {
  const RigidTransform T_scanner2_part{rotation_from_xyz_angles_deg(0, 0, 45), {-2.0, 1.5, 0.5}};
  RangeImage model_image = render_free_form_part(RigidTransform::identity(), FreeFormPartSpec{});
  RangeImage scene_image = render_free_form_part(T_scanner2_part, FreeFormPartSpec{});
  add_z_noise(model_image, 0.05, 11);
  add_z_noise(scene_image, 0.05, 12);
  const auto model = build_registration_points(model_image, {}).points;
  const auto scene = build_registration_points(scene_image, {.stride_px = 2}).points;
  const RegistrationParameters parameters;
  const PrincipalAxesEstimate estimate = estimate_by_principal_axes(scene, model, parameters);
  EXPECT_EQ(estimate.status, PrincipalAxesStatus::kOk);
  const RigidTransform truth = T_scanner2_part.inverse();
  EXPECT_LT(rotation_angle_between_rad(estimate.T_model_scene.rotation, truth.rotation) / kDeg,
            0.5);
  EXPECT_LT(translation_error_mm(estimate.T_model_scene, truth), 0.5);
  EXPECT_GT(estimate.score.matched_fraction, 0.9);
  double best_mm2 = 1e300;
  int worse = 0;
  for (const RigidTransform& candidate : principal_axes_candidates(scene, model)) {
    const double mm2 =
        score_alignment(scene, model, candidate, parameters).truncated_mean_square_mm2;
    best_mm2 = std::min(best_mm2, mm2);
    worse += mm2 > 10 * estimate.score.truncated_mean_square_mm2;
  }
  EXPECT_DOUBLE_EQ(estimate.score.truncated_mean_square_mm2, best_mm2);
  EXPECT_EQ(worse, 3);  // the three half turns do not fit
}

}  // namespace
}  // namespace cosmos::testing
