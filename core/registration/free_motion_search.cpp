#include "core/registration/free_motion_search.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace cosmos {

std::optional<RigidTransform> search_free_motion(const RegistrationPoints& scene,
                                                 const RegistrationPoints& model,
                                                 const RegistrationResult& registered,
                                                 const RegistrationParameters& registration,
                                                 double inlier_distance_mm,
                                                 const FreeMotionSearchParameters& parameters,
                                                 const TaskRunner& tasks) {
  const RigidTransform& T_registered = registered.T_model_scene;
  if (!parameters.enabled || registered.status == RegistrationStatus::kInvalidInput ||
      !(registered.weakest_constraint < parameters.max_constraint))
    return std::nullopt;
  RegistrationParameters strict = registration;
  strict.max_correspondence_distance_mm = inlier_distance_mm;
  const auto explained = [&](const RigidTransform& T) {
    return score_alignment(scene, model, T, strict).matched_fraction;
  };
  // The motion in parameters: a rotation vector (rad) and a translation (mm), per mm of
  // surface motion (the rotation half was scaled by the lever arm).
  const Eigen::Vector3d rotation_per_mm =
      registered.weakest_motion.head<3>() / registered.weakest_lever_mm;
  const Eigen::Vector3d translation_per_mm = registered.weakest_motion.tail<3>();
  // The motion as a screw (Chasles): a turn about an axis through `on_axis` with a slide
  // along it. Turned by large angles about that axis, not about the inliers' centre: the
  // linear step's translation is only the tangent of the circle the centre moves on.
  const double rad_per_mm = rotation_per_mm.norm();
  const Eigen::Vector3d axis =
      rad_per_mm > 0 ? Eigen::Vector3d(rotation_per_mm / rad_per_mm) : Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d on_axis =
      rad_per_mm > 0
          ? Eigen::Vector3d(registered.twist_centre_mm +
                            rotation_per_mm.cross(translation_per_mm) / (rad_per_mm * rad_per_mm))
          : registered.twist_centre_mm;
  const double slide_per_mm = rad_per_mm > 0 ? axis.dot(translation_per_mm) : 0.0;
  const auto moved_by = [&](double surface_mm) {
    if (!(rad_per_mm > 0))
      return RigidTransform{Eigen::Matrix3d::Identity(), surface_mm * translation_per_mm} *
             T_registered;
    const Eigen::Matrix3d R = Eigen::AngleAxisd(surface_mm * rad_per_mm, axis).matrix();
    const RigidTransform T_new_old{R, on_axis - R * on_axis + surface_mm * slide_per_mm * axis};
    return (T_new_old * T_registered).normalized();
  };
  // Mostly a turn (more of the motion is rotation than translation): the whole circle;
  // else a slide over its range.
  const bool turn =
      registered.weakest_motion.head<3>().norm() > registered.weakest_motion.tail<3>().norm();
  double step_mm = parameters.slide_step_mm;
  int steps = static_cast<int>(std::floor(parameters.slide_range_mm / step_mm));
  if (turn) {
    const double mm_per_rad = 1.0 / rad_per_mm;
    step_mm = parameters.turn_step_deg * std::numbers::pi / 180 * mm_per_rad;
    steps = static_cast<int>(std::floor(180.0 / parameters.turn_step_deg));
  }
  // Position k (0 the registered pose) at step k - steps; each scored into its own slot.
  const int positions = 2 * steps + 1;
  std::vector<double> fractions(static_cast<std::size_t>(positions));
  run_in_shares(tasks, positions, share_count(tasks, positions, 1), [&](int, int begin, int end) {
    for (int k = begin; k < end; ++k)
      fractions[static_cast<std::size_t>(k)] =
          explained(k == steps ? T_registered : moved_by((k - steps) * step_mm));
  });
  const double registered_fraction = fractions[static_cast<std::size_t>(steps)];
  double best_fraction = registered_fraction;
  int best = steps;
  for (int k = 0; k < positions; ++k)
    if (fractions[static_cast<std::size_t>(k)] > best_fraction) {
      best_fraction = fractions[static_cast<std::size_t>(k)];
      best = k;
    }
  if (best_fraction < registered_fraction + parameters.min_gain) return std::nullopt;
  return moved_by((best - steps) * step_mm);
}

}  // namespace cosmos
