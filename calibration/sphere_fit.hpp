#pragma once
// The centre of a sphere of known radius from points on its visible cap: Gauss-Newton on the
// radial residuals |p - c| - r from the algebraic (linear least-squares) centre. A cap seen
// from above determines the centre well only with the radius fixed, which the target file
// gives.
#include <Eigen/Core>
#include <vector>

namespace cosmos {

struct SphereFit {
  bool ok = false;
  Eigen::Vector3d centre_mm = Eigen::Vector3d::Zero();
  double rms_mm = 0.0;  // radial residual
  int points = 0;
};

SphereFit fit_sphere_known_radius(const std::vector<Eigen::Vector3d>& points, double radius_mm);

}  // namespace cosmos
