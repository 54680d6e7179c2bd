// RigidTransform (core/rigid_transform.hpp): x_a = R x_b + t, composed right to left like the
// matrices (Eq. 6.2 in matrix form), on hand-computed quarter turns; the quaternion
// re-normalization; the exponential map at the ends of its range; rotation angles across the
// +-180 degree seam.
#include "core/rigid_transform.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

namespace cosmos {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180.0;

Eigen::Matrix3d turn(double angle_rad, const Eigen::Vector3d& axis) {
  return Eigen::AngleAxisd(angle_rad, axis.normalized()).toRotationMatrix();
}

TEST(RigidTransform, CompositionAppliesTheRightFactorFirst) {
  const RigidTransform T_a_b{turn(kPi / 2, Eigen::Vector3d::UnitZ()), {1, 0, 0}};
  const RigidTransform T_b_c{turn(kPi / 2, Eigen::Vector3d::UnitX()), {0, 0, 1}};
  const Eigen::Vector3d p_c(0, 1, 0);
  // By hand: T_b_c takes (0, 1, 0) to (0, 0, 1) + (0, 0, 1) = (0, 0, 2); T_a_b turns that about
  // z (unchanged) and adds (1, 0, 0).
  EXPECT_LT(((T_a_b * T_b_c).apply(p_c) - Eigen::Vector3d(1, 0, 2)).norm(), 1e-14);
  // The other order: (0, 1, 0) -> (-1, 0, 0) + (1, 0, 0) = 0, then + (0, 0, 1).
  EXPECT_LT(((T_b_c * T_a_b).apply(p_c) - Eigen::Vector3d(0, 0, 1)).norm(), 1e-14);
  EXPECT_TRUE(RigidTransform::identity().rotation.isIdentity());
  EXPECT_TRUE(RigidTransform::identity().translation_mm.isZero());
}

TEST(RigidTransform, InverseAndDirectionsIgnoreNothingButTheTranslation) {
  const RigidTransform T_a_b{turn(kPi / 2, Eigen::Vector3d::UnitZ()), {1, 2, 3}};
  // -(R^T t): R^T turns (1, 2, 3) by -90 degrees about z to (2, -1, 3).
  const RigidTransform T_b_a = T_a_b.inverse();
  EXPECT_LT((T_b_a.translation_mm - Eigen::Vector3d(-2, 1, -3)).norm(), 1e-14);
  EXPECT_LT((T_b_a.rotation - turn(-kPi / 2, Eigen::Vector3d::UnitZ())).norm(), 1e-14);
  const Eigen::Vector3d p_b(0.3, -1.7, 2.2);
  EXPECT_LT((T_b_a.apply(T_a_b.apply(p_b)) - p_b).norm(), 1e-14);
  // A direction is only turned: (1, 0, 0) -> (0, 1, 0), whatever the translation.
  EXPECT_LT((T_a_b.rotate({1, 0, 0}) - Eigen::Vector3d(0, 1, 0)).norm(), 1e-14);
  EXPECT_LT((T_a_b.apply({1, 0, 0}) - Eigen::Vector3d(1, 3, 3)).norm(), 1e-14);
}

TEST(RigidTransform, NormalizedIsTheNearestRotationAndKeepsTheTranslation) {
  const Eigen::Matrix3d R = turn(0.8, {1, -2, 0.5});
  std::mt19937_64 random(5);
  std::normal_distribution<double> noise(0.0, 1e-4);
  Eigen::Matrix3d drifted = R;
  for (int k = 0; k < 9; ++k) drifted(k / 3, k % 3) += noise(random);
  ASSERT_GT((drifted.transpose() * drifted - Eigen::Matrix3d::Identity()).norm(), 1e-5);
  const RigidTransform repaired = RigidTransform{drifted, {4, 5, 6}}.normalized();
  EXPECT_LT(
      (repaired.rotation.transpose() * repaired.rotation - Eigen::Matrix3d::Identity()).norm(),
      1e-14);
  EXPECT_NEAR(repaired.rotation.determinant(), 1.0, 1e-14);
  EXPECT_LT((repaired.rotation - R).norm(), 1e-3);
  EXPECT_EQ(repaired.translation_mm, Eigen::Vector3d(4, 5, 6));
  // A proper rotation is its own nearest rotation.
  EXPECT_LT((RigidTransform{R, {}}.normalized().rotation - R).norm(), 1e-14);
}

TEST(RigidTransform, ExponentialMapAtTheSeriesSeamAndAtHalfATurn) {
  const Eigen::Vector3d axis = Eigen::Vector3d(0.3, 0.4, -0.5).normalized();
  // Either side of the angle below which the Taylor series replaces sin and cos.
  for (double angle : {0.99e-4, 1.01e-4})
    EXPECT_LT((rotation_from_vector(angle * axis) - turn(angle, axis)).norm(), 1e-14) << angle;
  // Half a turn about x: diag(1, -1, -1); a whole turn: the identity.
  EXPECT_LT(
      (rotation_from_vector({kPi, 0, 0}) - Eigen::Vector3d(1, -1, -1).asDiagonal().toDenseMatrix())
          .norm(),
      1e-14);
  EXPECT_LT((rotation_from_vector(2 * kPi * axis) - Eigen::Matrix3d::Identity()).norm(), 1e-14);
  const RigidTransform step = transform_from_increment({0, 0, kPi / 2}, {1, 2, 3});
  EXPECT_LT((step.apply({1, 0, 0}) - Eigen::Vector3d(1, 3, 3)).norm(), 1e-14);
}

TEST(RigidTransform, RotationAngleBetweenWrapsAroundHalfATurn) {
  const Eigen::Vector3d z = Eigen::Vector3d::UnitZ();
  const double deg = kPi / 180;
  EXPECT_NEAR(rotation_angle_between_rad(turn(30 * deg, z), turn(100 * deg, z)), 70 * deg, 1e-12);
  EXPECT_NEAR(rotation_angle_between_rad(turn(100 * deg, z), turn(30 * deg, z)), 70 * deg, 1e-12);
  // 170 and -170 degrees are 20 degrees apart, not 340.
  EXPECT_NEAR(rotation_angle_between_rad(turn(170 * deg, z), turn(-170 * deg, z)), 20 * deg, 1e-12);
  EXPECT_NEAR(rotation_angle_between_rad(Eigen::Matrix3d::Identity(), turn(kPi, {1, 1, 0})), kPi,
              1e-7);
  const Eigen::Matrix3d R = turn(1.1, {2, -1, 3});
  EXPECT_NEAR(rotation_angle_between_rad(R, R), 0.0, 1e-14);
}

TEST(RigidTransform, ComposeInverseAndApply) {
  const RigidTransform T_a_b{rotation_from_xyz_angles_deg(10, -20, 30), {1, 2, 3}};
  const RigidTransform T_b_c{rotation_from_xyz_angles_deg(-5, 7, 90), {-4, 0.5, 2}};
  const Eigen::Vector3d p_c(0.3, -1.7, 2.2);
  EXPECT_LT(((T_a_b * T_b_c).apply(p_c) - T_a_b.apply(T_b_c.apply(p_c))).norm(), 1e-12);
  const RigidTransform round_trip = T_a_b * T_a_b.inverse();
  EXPECT_LT((round_trip.rotation - Eigen::Matrix3d::Identity()).norm(), 1e-12);
  EXPECT_LT(round_trip.translation_mm.norm(), 1e-12);
  // Eq. 6.2's matrix, written out, for alpha = 10, beta = -20, gamma = 30 degrees.
  const double a = 10 * kDeg, b = -20 * kDeg, g = 30 * kDeg;
  Eigen::Matrix3d eq_6_2;
  eq_6_2 << std::cos(g) * std::cos(b),
      std::cos(g) * std::sin(b) * std::sin(a) - std::sin(g) * std::cos(a),
      std::cos(a) * std::sin(b) * std::cos(g) + std::sin(a) * std::sin(g),  //
      std::sin(g) * std::cos(b),
      std::sin(a) * std::sin(b) * std::sin(g) + std::cos(a) * std::cos(g),
      std::sin(g) * std::sin(b) * std::cos(a) - std::cos(g) * std::sin(a),  //
      -std::sin(b), std::cos(b) * std::sin(a), std::cos(b) * std::cos(a);
  EXPECT_LT((T_a_b.rotation - eq_6_2).norm(), 1e-12);
}

TEST(RigidTransform, ExponentialMapAndRotationErrors) {
  const Eigen::Vector3d axis = Eigen::Vector3d(1, -2, 0.5).normalized();
  for (double angle : {0.0, 1e-7, 1e-3, 0.5, 3.0}) {
    const Eigen::Matrix3d expected = Eigen::AngleAxisd(angle, axis).toRotationMatrix();
    EXPECT_LT((rotation_from_vector(angle * axis) - expected).norm(), 1e-12) << angle;
    EXPECT_NEAR(rotation_angle_between_rad(Eigen::Matrix3d::Identity(), expected), angle, 1e-9);
  }
  // §6.7.3: E_R = 2 sqrt(2) sin(theta / 2) / sqrt(3) for a rotation error theta.
  const Eigen::Matrix3d R = rotation_from_xyz_angles_deg(5, 0, 10);
  const Eigen::Matrix3d R_off = R * Eigen::AngleAxisd(0.01, axis).toRotationMatrix();
  EXPECT_NEAR(relative_rotation_error(R_off, R),
              2 * std::sqrt(2.0) * std::sin(0.005) / std::sqrt(3.0), 1e-12);
  const RigidTransform increment = transform_from_increment({0, 0, 0.1}, {1, 2, 2});
  EXPECT_NEAR(translation_error_mm(increment, RigidTransform::identity()), 3.0, 1e-12);
}

}  // namespace
}  // namespace cosmos
