#include "core/recognition/pose_hypotheses.hpp"

#include <Eigen/Geometry>
#include <numbers>

#include "core/registration/principal_axes_estimate.hpp"

namespace cosmos {
namespace {

Eigen::Vector3d centroid_mm(const RegistrationPoints& points) {
  return points.position_mm.rowwise().mean();
}

}  // namespace

RigidTransform in_plane_turn(int k, int turns, const Eigen::Vector3d& scene_centre_mm,
                             const Eigen::Vector3d& model_centre_mm) {
  const double angle_rad = 2.0 * std::numbers::pi * k / turns;
  const Eigen::Matrix3d R = Eigen::AngleAxisd(angle_rad, Eigen::Vector3d::UnitZ()).matrix();
  return {R, model_centre_mm - R * scene_centre_mm};
}

std::vector<RigidTransform> generate_pose_hypotheses(const RegistrationPoints& scene,
                                                     const RegistrationPoints& model,
                                                     const PoseFromPatches& from_patches,
                                                     const PoseHypothesisParameters& parameters) {
  std::vector<RigidTransform> hypotheses;
  if (scene.size() == 0 || model.size() == 0) return hypotheses;
  if (from_patches.status == PatchPoseStatus::kOk) hypotheses.push_back(from_patches.T_model_scene);
  for (const RigidTransform& T_model_scene : principal_axes_candidates(scene, model))
    hypotheses.push_back(T_model_scene);
  const Eigen::Vector3d scene_centre = centroid_mm(scene);
  const Eigen::Vector3d model_centre = centroid_mm(model);
  for (int k = 0; k < parameters.in_plane_turns; ++k)
    hypotheses.push_back(in_plane_turn(k, parameters.in_plane_turns, scene_centre, model_centre));
  return hypotheses;
}

}  // namespace cosmos
