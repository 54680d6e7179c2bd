#pragma once
// The correspondence step of Chen-Medioni registration (§6.4): the line through a
// transformed scene control point along its transformed normal is intersected with the model
// surface Q, and the tangent plane S of Q there gives the signed point-to-plane distance d_s
// (Eq. 6.5); plus the variance of d_s that the minimum-variance estimator needs (§6.6.1,
// Eqs. 6.21-6.22, linear-regression form).
//
// The model surface between its control points is the bilinear blend of the local fits of
// the four surrounding grid cells, each evaluated at the query: continuous, so the
// correspondences, and hence the iteration, move smoothly with T. The line-surface
// intersection ("an iterative search near the neighbourhood of prospective intersection
// points", §6.4) is a fixed-point iteration: intersect the line with the blended tangent
// plane under its current foot, move the foot there, repeat; a bounded number of steps.
#include <Eigen/Core>

#include "core/registration/registration_points.hpp"

namespace cosmos {

enum class CorrespondenceStatus {
  kFound,
  kOffModel,      // the line leaves the model's control-point grid (or hits a hole in it)
  kGrazing,       // the line is nearly parallel to the model's tangent plane
  kNotConverged,  // the foot still moved after the step budget
};

struct TangentPlaneCorrespondence {
  Eigen::Vector3d model_point_mm = Eigen::Vector3d::Zero();  // q, on the blended surface
  Eigen::Vector3d model_normal = Eigen::Vector3d::UnitZ();   // unit normal of S at q
  Eigen::Vector2d model_slope = Eigen::Vector2d::Zero();     // (a, b) of S
  double distance_mm = 0.0;      // d_s = n_q . (T p - q): positive above the model surface
  double travel_mm = 0.0;        // |T p - q|: how far along the line the surface was met
  int nearest_model_point = -1;  // control point whose plane covariance S inherits
  int steps = 0;                 // intersection steps spent (the correspondence budget)
};

// `point_mm` and `line_direction` are the scene control point and normal already mapped
// into the model frame. Stops after `max_steps` plane intersections, or when the foot moves
// less than a thousandth of a grid cell.
CorrespondenceStatus find_tangent_plane(const RegistrationPoints& model,
                                        const Eigen::Vector3d& point_mm,
                                        const Eigen::Vector3d& line_direction, int max_steps,
                                        TangentPlaneCorrespondence& out);

// Eqs. 6.21-6.22: sigma^2 of d_s = grad^T Gamma_hz grad, with Gamma_h the regression
// covariance of the nearest model control point's fit, sigma_model^2 (A^T A)^-1 (§6.6.1; the
// text's "A^T Gamma_Z A" is meant as the inverse of the information matrix, which is what
// Eq. 6.7's least squares gives), and the last entry the variance of the scene point along
// its own viewing axis. The scene point is the fitted height at its pixel
// (RegistrationPoints), so that variance is `scene_height_variance_mm2` =
// sigma_scene^2 (A^T A)^-1 [height, height] rather than the raw sigma^2;
// `scene_view_axis` is the scene's z axis in the model frame (the scene's z error moves
// T p along it).
double distance_variance_mm2(const RegistrationPoints& model,
                             const TangentPlaneCorrespondence& correspondence,
                             const Eigen::Vector3d& point_mm, double scene_height_variance_mm2,
                             const Eigen::Vector3d& scene_view_axis);

}  // namespace cosmos
