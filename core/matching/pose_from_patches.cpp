#include "core/matching/pose_from_patches.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <numbers>

namespace cosmos {
namespace {

constexpr double kRadToDeg = 180.0 / std::numbers::pi;

bool usable(const NormalCorrespondence& c) {
  return std::isfinite(c.weight) && c.weight > 0 && c.scene_normal.allFinite() &&
         c.model_normal.allFinite();
}

double spread_deg(const Eigen::Matrix3d& scatter) {
  const Eigen::Vector3d eigenvalues =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(scatter, Eigen::EigenvaluesOnly).eigenvalues();
  const double largest = eigenvalues(2);
  const double second = std::max(eigenvalues(1), 0.0);
  return largest > 0 ? 2.0 * std::atan(std::sqrt(second / largest)) * kRadToDeg : 0.0;
}

struct GroupGeometry {
  double area_mm2 = 0;
  Eigen::Vector3d normal_sum = Eigen::Vector3d::Zero();    // sum of area * G0
  Eigen::Vector3d centroid_sum = Eigen::Vector3d::Zero();  // sum of area * centroid
};

GroupGeometry group_geometry(const CosmosView& view, const std::vector<int>& ids) {
  GroupGeometry g;
  for (int id : ids) {
    const auto patch = std::find_if(view.patches.begin(), view.patches.end(),
                                    [id](const Csmp& p) { return p.id == id; });
    if (patch == view.patches.end() || !(patch->area_mm2 > 0)) continue;
    g.area_mm2 += patch->area_mm2;
    g.normal_sum += patch->area_mm2 * patch->mean_normal;
    g.centroid_sum += patch->area_mm2 * patch->centroid_mm;
  }
  return g;
}

}  // namespace

RotationFromNormals rotation_from_normals(std::span<const NormalCorrespondence> normals,
                                          double min_normal_spread_deg) {
  RotationFromNormals result;
  Eigen::Matrix3d cross_covariance = Eigen::Matrix3d::Zero();  // sum w n_scene n_model^T
  Eigen::Matrix3d scene_scatter = Eigen::Matrix3d::Zero();
  Eigen::Matrix3d model_scatter = Eigen::Matrix3d::Zero();
  double total_weight = 0;
  for (const NormalCorrespondence& c : normals) {
    if (!usable(c)) continue;
    cross_covariance += c.weight * c.scene_normal * c.model_normal.transpose();
    scene_scatter += c.weight * c.scene_normal * c.scene_normal.transpose();
    model_scatter += c.weight * c.model_normal * c.model_normal.transpose();
    total_weight += c.weight;
  }
  if (!(total_weight > 0)) return result;

  // Kabsch/Horn: R = V diag(1, 1, det(V U^T)) U^T maximizes sum w n_model . (R n_scene).
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(cross_covariance,
                                              Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d reflection_fix = Eigen::Matrix3d::Identity();
  reflection_fix(2, 2) = (svd.matrixV() * svd.matrixU().transpose()).determinant() < 0 ? -1.0 : 1.0;
  result.R_model_scene = svd.matrixV() * reflection_fix * svd.matrixU().transpose();

  double squared_angle_sum = 0;
  for (const NormalCorrespondence& c : normals) {
    if (!usable(c)) continue;
    const Eigen::Vector3d rotated = result.R_model_scene * c.scene_normal;
    const double angle =
        std::atan2(rotated.cross(c.model_normal).norm(), rotated.dot(c.model_normal));
    squared_angle_sum += c.weight * angle * angle;
  }
  result.rms_residual_deg = std::sqrt(squared_angle_sum / total_weight) * kRadToDeg;
  result.normal_spread_deg = std::min(spread_deg(scene_scatter), spread_deg(model_scatter));
  result.status = result.normal_spread_deg >= min_normal_spread_deg
                      ? PatchPoseStatus::kOk
                      : PatchPoseStatus::kDegenerateNormals;
  return result;
}

PoseFromPatches estimate_pose_from_patches(const CosmosView& scene, const CosmosView& model,
                                           const std::vector<MappedPair>& pairs,
                                           const PoseFromPatchesParameters& parameters) {
  PoseFromPatches pose;
  std::vector<NormalCorrespondence> normals;
  Eigen::Vector3d scene_centroid_sum = Eigen::Vector3d::Zero();
  Eigen::Vector3d model_centroid_sum = Eigen::Vector3d::Zero();
  double centroid_weight = 0;
  for (const MappedPair& pair : pairs) {
    const GroupGeometry s = group_geometry(scene, pair.scene_patches);
    const GroupGeometry m = group_geometry(model, pair.model_patches);
    if (!(s.area_mm2 > 0) || !(m.area_mm2 > 0)) continue;
    const double weight = 0.5 * (s.area_mm2 + m.area_mm2) * std::max(pair.goodness.goodness, 0.0);
    if (!(weight > 0)) continue;
    scene_centroid_sum += weight * s.centroid_sum / s.area_mm2;
    model_centroid_sum += weight * m.centroid_sum / m.area_mm2;
    centroid_weight += weight;
    // Eq. 3.7 over the group: the area-weighted mean of its patches' G0.
    const Eigen::Vector3d scene_normal = s.normal_sum / s.area_mm2;
    const Eigen::Vector3d model_normal = m.normal_sum / m.area_mm2;
    if (scene_normal.norm() < parameters.min_group_normal_length ||
        model_normal.norm() < parameters.min_group_normal_length) {
      continue;
    }
    normals.push_back({scene_normal.normalized(), model_normal.normalized(), weight});
  }
  pose.pairs_used = static_cast<int>(normals.size());
  const RotationFromNormals rotation =
      rotation_from_normals(normals, parameters.min_normal_spread_deg);
  pose.status = rotation.status;
  pose.normal_spread_deg = rotation.normal_spread_deg;
  pose.rms_normal_residual_deg = rotation.rms_residual_deg;
  pose.T_model_scene.rotation = rotation.R_model_scene;
  if (centroid_weight > 0) {
    pose.T_model_scene.translation_mm =
        model_centroid_sum / centroid_weight -
        rotation.R_model_scene * (scene_centroid_sum / centroid_weight);
  }
  return pose;
}

}  // namespace cosmos
