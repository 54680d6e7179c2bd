#include "core/rigid_transform.hpp"

#include <cmath>
#include <numbers>

namespace cosmos {

Eigen::Matrix3d rotation_from_vector(const Eigen::Vector3d& rotation_vector_rad) {
  const double theta = rotation_vector_rad.norm();
  Eigen::Matrix3d K;
  K << 0, -rotation_vector_rad.z(), rotation_vector_rad.y(),  //
      rotation_vector_rad.z(), 0, -rotation_vector_rad.x(),   //
      -rotation_vector_rad.y(), rotation_vector_rad.x(), 0;
  // sin(t)/t and (1 - cos(t))/t^2 lose all precision near 0: use their Taylor series there.
  double a, b;
  if (theta < 1e-4) {
    const double t2 = theta * theta;
    a = 1.0 - t2 / 6.0;
    b = 0.5 - t2 / 24.0;
  } else {
    a = std::sin(theta) / theta;
    b = (1.0 - std::cos(theta)) / (theta * theta);
  }
  return Eigen::Matrix3d::Identity() + a * K + b * K * K;
}

RigidTransform transform_from_increment(const Eigen::Vector3d& omega_rad,
                                        const Eigen::Vector3d& translation_mm) {
  return {rotation_from_vector(omega_rad), translation_mm};
}

Eigen::Matrix3d rotation_from_xyz_angles_deg(double alpha_deg, double beta_deg, double gamma_deg) {
  constexpr double kRadPerDeg = std::numbers::pi / 180.0;
  return (Eigen::AngleAxisd(gamma_deg * kRadPerDeg, Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd(beta_deg * kRadPerDeg, Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(alpha_deg * kRadPerDeg, Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

double rotation_angle_between_rad(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) {
  // Through the quaternion: acos of the trace is inaccurate for small angles.
  return Eigen::AngleAxisd(Eigen::Quaterniond(a.transpose() * b).normalized()).angle();
}

double relative_rotation_error(const Eigen::Matrix3d& estimated, const Eigen::Matrix3d& actual) {
  return (estimated - actual).norm() / actual.norm();
}

double translation_error_mm(const RigidTransform& estimated, const RigidTransform& actual) {
  return (estimated.translation_mm - actual.translation_mm).norm();
}

}  // namespace cosmos
