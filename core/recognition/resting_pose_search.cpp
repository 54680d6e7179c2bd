#include "core/recognition/resting_pose_search.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace cosmos {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

// The part's vertical under a resting pose: the belt's normal in the part's frame.
Eigen::Vector3d up_in_part(const RestingPose& pose) {
  return pose.R_belt_part.transpose() * Eigen::Vector3d::UnitZ();
}

// Centroid, in the part's frame, of the view that looks at the part most nearly from
// `up_part`: the surface a scanner above the resting part sees. Of every view, not only the
// coarse ones the pose search starts from: a coarse view can be 20 degrees off the vertical,
// and into a hollow part (an open shell lying on its back) its centroid was 10-20 mm from the
// scene's, beyond where the field stages pull a start in.
Eigen::Vector3d seen_centroid_part(const ModelBase& base, const PartSearchModel& model,
                                   const Eigen::Vector3d& up_part) {
  std::size_t nearest = 0;
  const auto direction = [&](std::size_t k) -> const Eigen::Vector3d& {
    return base.views[static_cast<std::size_t>(model.views[k])].direction_part;
  };
  for (std::size_t s = 1; s < model.views.size(); ++s)
    if (direction(s).dot(up_part) > direction(nearest).dot(up_part)) nearest = s;
  const ModelBaseView& view = base.views[static_cast<std::size_t>(model.views[nearest])];
  return view.T_scanner_part.inverse().apply(model.view_centroid_mm[nearest]);
}

}  // namespace

std::vector<FieldHypothesis> resting_pose_hypotheses(const RegistrationPoints& scene,
                                                     const ModelBase& base, int part,
                                                     const PartSearchModel& model,
                                                     const PartPoseSearchParameters& search,
                                                     const RestingSearchParameters& parameters) {
  const std::vector<RestingPose>& resting =
      base.parts[static_cast<std::size_t>(part)].resting_poses;
  if (resting.empty() || model.views.empty() || scene.size() == 0 || model.field.empty()) return {};
  const Eigen::Vector3d scene_centre = scene.position_mm.rowwise().mean();
  std::vector<FieldHypothesis> starts;
  starts.reserve(resting.size() * static_cast<std::size_t>(parameters.turns));
  for (const RestingPose& pose : resting) {
    const Eigen::Vector3d centroid_part = seen_centroid_part(base, model, up_in_part(pose));
    for (int k = 0; k < parameters.turns; ++k) {
      const double turn_rad = 2.0 * std::numbers::pi * k / parameters.turns;
      RigidTransform T_scene_part;
      T_scene_part.rotation =
          Eigen::AngleAxisd(turn_rad, Eigen::Vector3d::UnitZ()).toRotationMatrix() *
          pose.R_belt_part;
      T_scene_part.translation_mm = scene_centre - T_scene_part.rotation * centroid_part;
      T_scene_part.translation_mm.z() = pose.height_mm;
      starts.push_back({T_scene_part.inverse(), 0.0});
    }
  }
  PartPoseSearchParameters funnel = search;
  funnel.field_candidates = parameters.field_aligned;
  funnel.field_aligned = parameters.field_aligned;
  funnel.refined_hypotheses = parameters.refined_hypotheses;
  return rank_field_starts(scene, model, std::move(starts), funnel);
}

RestingCheck check_resting(const ModelPart& part, const RigidTransform& T_part_scene,
                           const RestingSearchParameters& parameters) {
  RestingCheck check;
  const RigidTransform T_scene_part = T_part_scene.inverse();
  check.lowest_point_mm = std::numeric_limits<double>::infinity();
  for (const Eigen::Vector3d& point : part.hull_vertices_mm)
    check.lowest_point_mm = std::min(check.lowest_point_mm, T_scene_part.apply(point).z());
  const Eigen::Vector3d up_part = T_part_scene.rotation * Eigen::Vector3d::UnitZ();
  double best_cos = -1.0;
  for (const RestingPose& pose : part.resting_poses)
    best_cos = std::max(best_cos, up_part.dot(up_in_part(pose)));
  check.tilt_deg = std::acos(std::clamp(best_cos, -1.0, 1.0)) / kDegree;
  check.covered = part.resting_coverage() >= parameters.min_coverage;
  check.touches_belt = std::abs(check.lowest_point_mm) <= parameters.max_height_error_mm;
  check.at_rest =
      check.touches_belt && (!check.covered || check.tilt_deg <= parameters.max_tilt_deg);
  return check;
}

}  // namespace cosmos
