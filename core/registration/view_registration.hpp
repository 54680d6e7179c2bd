#pragma once
// Registration of a scene view onto a model view (chapter 6): from an initial
// T_model_scene, iterate (§6.4)
//   (i)  for every scene control point p_i: intersect the line T p_i + s T n_i with the model
//        surface, take the tangent plane S_i there (TangentPlaneCorrespondence);
//   (ii) find the increment that minimizes the sum of (weighted) squared point-to-plane
//        distances, linearized in a small rotation about the inliers' centroid;
//   (iii) T <- increment * T,
// either unweighted (Chen-Medioni, Eq. 6.4) or with each d_s^2 weighted by 1/sigma_ds^2
// (the minimum-variance estimator, Eqs. 6.8 and 6.21-6.23).
//
// Outliers (occluded or missing surface, §6.5: "occluded and noisy surface points can be
// considered such") are rejected before each solve: a correspondence is kept when the line
// met the model within max_correspondence_distance_mm, the two normals agree within
// max_normal_angle_deg, and |d_s| is at most the rejection distance
//   clamp(rejection_mad_factor * 1.4826 * median |d_s|, min_rejection_distance_mm,
//         max_correspondence_distance_mm),
// i.e. a few robust standard deviations of the current residuals: wide while the views are
// far apart, tight (but never below sensor-noise scale) near convergence. A previous inlier
// keeps its place up to 1.25 times that distance, so points on the threshold do not flicker.
//
// A part known to lie on the belt is held on it (belt_contact.hpp): its lowest hull corners are
// rows of step (ii) beside the inliers, weighing BeltContact::weight times all of them.
//
// Convergence is tested on the increment (rotation and shift of the inliers' centroid below
// tolerances) rather than on the change of e^k as in §6.4, which jumps whenever the inlier
// set changes; a period-2 oscillation below the tolerances (a point at the model's edge
// matched every other pass) also counts as converged. Budgets are iterations and
// intersection steps, never time.
#include <span>
#include <vector>

#include "core/parameter_visitor.hpp"
#include "core/registration/belt_contact.hpp"
#include "core/registration/registration_points.hpp"
#include "core/rigid_transform.hpp"
#include "core/task_runner.hpp"

namespace cosmos {

enum class RegistrationEstimator {
  kChenMedioni,      // §6.4, Eq. 6.4: every d_s^2 counts the same
  kMinimumVariance,  // §6.6, Eq. 6.23: d_s^2 / sigma_ds^2
};

inline std::span<const ParameterChoice<RegistrationEstimator>> parameter_choices(
    RegistrationEstimator) {
  static constexpr ParameterChoice<RegistrationEstimator> kChoices[] = {
      {RegistrationEstimator::kChenMedioni, "chen_medioni"},
      {RegistrationEstimator::kMinimumVariance, "minimum_variance"}};
  return kChoices;
}

struct RegistrationParameters {
  RegistrationEstimator estimator = RegistrationEstimator::kMinimumVariance;
  int max_iterations = 50;         // iteration budget
  int max_intersection_steps = 6;  // per control point and iteration (correspondence budget)
  double max_correspondence_distance_mm = 5.0;
  double max_normal_angle_deg = 45.0;
  double rejection_mad_factor = 3.0;
  double min_rejection_distance_mm = 0.2;  // several times the d_s noise of 0.02-0.05 mm data
  // MVE: sigma_ds never below this, so that the weight of near-vertical surface, where
  // Eq. 6.21 tends to 0, stays bounded by the model's interpolation error rather than
  // growing without limit.
  double min_distance_sigma_mm = 0.002;
  // Converged when one increment rotates less than this and translates less than that.
  double convergence_rotation_rad = 1e-6;
  double convergence_translation_mm = 1e-5;
  int min_inliers = 12;  // 6 parameters, twice over

  template <class Visitor>
  void visit(Visitor& v) {
    v("estimator", estimator, "chen_medioni (§6.4) or minimum_variance (§6.6)");
    v("max_iterations", max_iterations, "iteration budget", Range{1, 10000});
    v("max_intersection_steps", max_intersection_steps,
      "per control point and iteration (correspondence budget)", Range{1, 1000});
    v("max_correspondence_distance_mm", max_correspondence_distance_mm,
      "farther correspondences are dropped, mm", Range::above(0, 1e4));
    v("max_normal_angle_deg", max_normal_angle_deg, "normals further apart do not correspond, deg",
      Range::above(0, 180));
    v("rejection_mad_factor", rejection_mad_factor, "outliers beyond this many MADs",
      Range::above(0, 100));
    v("min_rejection_distance_mm", min_rejection_distance_mm,
      "outlier distance never below this, mm", Range{0, 1e3});
    v("min_distance_sigma_mm", min_distance_sigma_mm, "MVE: sigma_ds never below this, mm",
      Range::above(0, 10));
    v("convergence_rotation_rad", convergence_rotation_rad, "converged below this rotation, rad",
      Range::above(0, 1));
    v("convergence_translation_mm", convergence_translation_mm, "and below this translation, mm",
      Range::above(0, 10));
    v("min_inliers", min_inliers, "fewer correspondences: no estimate", Range{6, 1000000});
  }
};

enum class RegistrationStatus {
  kConverged,
  kIterationBudgetExhausted,  // T is the last iterate
  kTooFewCorrespondences,     // T is the last iterate with enough inliers (or the initial one)
  kDegenerate,  // the last pass's inliers left 3 or more of the 6 parameters free (a plane):
                // T is the last iterate, stepped only in the constrained directions. 1 or 2
                // free ones (a cylinder, a surface of revolution) keep their current value
                // without this status.
  kInvalidInput,
};

struct RegistrationResult {
  RegistrationStatus status = RegistrationStatus::kInvalidInput;
  bool converged = false;
  RigidTransform T_model_scene;
  double rms_residual_mm = 0.0;  // RMS of d_s over the inliers of the last pass
  double inlier_fraction = 0.0;  // inliers / scene control points, last pass
  int inliers = 0;
  int iterations = 0;
  long intersection_steps = 0;  // total correspondence work spent
  // The last pass's least constrained motion (§6.8): a small rotation omega about
  // twist_centre_mm then a translation tau, in the model frame, as (omega, tau) with the
  // rotation scaled by the inliers' RMS lever arm (so that both halves are in mm of surface
  // motion), unit length; and how much the inliers constrain it (the smallest eigenvalue of
  // the scaled normal equations over their total weight). A surface of revolution leaves the
  // turn about its axis nearly free: the step leaves it at whatever the start made it.
  Eigen::Matrix<double, 6, 1> weakest_motion = Eigen::Matrix<double, 6, 1>::Zero();
  double weakest_lever_mm = 1.0;
  double weakest_constraint = 0.0;
  Eigen::Vector3d twist_centre_mm = Eigen::Vector3d::Zero();
};

// Each pass's correspondences are found in shares of the scene's points on `tasks` and used in
// the points' order: the result is the same for any runner.
RegistrationResult register_views(const RegistrationPoints& scene, const RegistrationPoints& model,
                                  const RigidTransform& T_model_scene_initial,
                                  const RegistrationParameters& parameters,
                                  const TaskRunner& tasks = one_after_another(),
                                  const BeltContact& belt = {});

// How well T_model_scene aligns the views, from one correspondence pass: the mean over all
// scene control points of min(d_s^2, D^2) (no correspondence counts D^2), with D the
// max_correspondence_distance_mm; and the fraction of points within D. Used to choose among
// candidate initial estimates.
struct AlignmentScore {
  double truncated_mean_square_mm2 = 0.0;
  double matched_fraction = 0.0;
};
AlignmentScore score_alignment(const RegistrationPoints& scene, const RegistrationPoints& model,
                               const RigidTransform& T_model_scene,
                               const RegistrationParameters& parameters,
                               const TaskRunner& tasks = one_after_another());

// Per scene control point, |d_s| of its correspondence under T_model_scene (the geometric
// tests of one registration pass), +infinity where it has none: for measuring how much of a
// scene several model views explain together.
void correspondence_distances(const RegistrationPoints& scene, const RegistrationPoints& model,
                              const RigidTransform& T_model_scene,
                              const RegistrationParameters& parameters,
                              std::vector<double>& abs_distance_mm,
                              const TaskRunner& tasks = one_after_another());

}  // namespace cosmos
