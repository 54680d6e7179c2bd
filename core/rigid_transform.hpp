#pragma once
// A rigid 3D transform x_a = R x_b + t between two frames, named after them in variables:
// T_model_scene maps scene-frame points into the model frame (Eq. 6.2 in matrix form).
// Composition reads right to left like the matrices: T_a_c = T_a_b * T_b_c.
#include <Eigen/Core>
#include <Eigen/Geometry>

namespace cosmos {

struct RigidTransform {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d translation_mm = Eigen::Vector3d::Zero();

  static RigidTransform identity() { return {}; }

  Eigen::Vector3d apply(const Eigen::Vector3d& point_mm) const {
    return rotation * point_mm + translation_mm;
  }
  // Directions (normals) are only rotated.
  Eigen::Vector3d rotate(const Eigen::Vector3d& direction) const { return rotation * direction; }

  RigidTransform inverse() const {
    return {rotation.transpose(), -(rotation.transpose() * translation_mm)};
  }

  // The nearest proper rotation (through the quaternion), so that long chains of
  // compositions do not drift away from SO(3).
  RigidTransform normalized() const {
    return {Eigen::Quaterniond(rotation).normalized().toRotationMatrix(), translation_mm};
  }

  friend RigidTransform operator*(const RigidTransform& T_a_b, const RigidTransform& T_b_c) {
    return {T_a_b.rotation * T_b_c.rotation,
            T_a_b.rotation * T_b_c.translation_mm + T_a_b.translation_mm};
  }
};

// Exponential map of so(3): the rotation by |rotation_vector_rad| about its direction
// (Rodrigues), exact for any angle, with the series form near zero.
Eigen::Matrix3d rotation_from_vector(const Eigen::Vector3d& rotation_vector_rad);

// The small-angle increment of one registration step: exp(omega) and a translation.
RigidTransform transform_from_increment(const Eigen::Vector3d& omega_rad,
                                        const Eigen::Vector3d& translation_mm);

// Eq. 6.2: rotation by alpha about x, then beta about y, then gamma about z: Rz Ry Rx.
Eigen::Matrix3d rotation_from_xyz_angles_deg(double alpha_deg, double beta_deg, double gamma_deg);

// Angle (rad, in [0, pi]) of the rotation taking a to b, i.e. of a^T b.
double rotation_angle_between_rad(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b);

// §6.7.3: E_R = ||R_estimated - R|| / ||R|| (Frobenius), the RMS distance between the three
// rotated unit axes; about 0.816 times the angle between the rotations for small angles.
double relative_rotation_error(const Eigen::Matrix3d& estimated, const Eigen::Matrix3d& actual);

// §6.7.3: E_t = |t_estimated - t| in mm.
double translation_error_mm(const RigidTransform& estimated, const RigidTransform& actual);

}  // namespace cosmos
