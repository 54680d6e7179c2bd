#include "core/registration/principal_axes_estimate.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>

namespace cosmos {
namespace {

struct PrincipalAxes {
  Eigen::Vector3d centroid_mm;
  Eigen::Matrix3d axes;  // columns: major, middle, minor; det +1
  double min_relative_gap;
};

PrincipalAxes principal_axes(const RegistrationPoints& points) {
  const Eigen::Vector3d centroid = points.position_mm.rowwise().mean();
  const Eigen::Matrix3Xd centred = points.position_mm.colwise() - centroid;
  const Eigen::Matrix3d scatter = centred * centred.transpose() / points.size();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(scatter);
  const Eigen::Vector3d values = eigen.eigenvalues();  // ascending
  Eigen::Matrix3d axes;
  axes << eigen.eigenvectors().col(2), eigen.eigenvectors().col(1), eigen.eigenvectors().col(0);
  if (axes.determinant() < 0) axes.col(2) = -axes.col(2);
  const double gap =
      std::min(values(2) - values(1), values(1) - values(0)) / std::max(values(2), 1e-300);
  return {centroid, axes, gap};
}

// The sign flips of the axes that keep det = +1.
constexpr std::array<std::array<double, 3>, 4> kFlips{
    {{1, 1, 1}, {-1, -1, 1}, {-1, 1, -1}, {1, -1, -1}}};

RigidTransform candidate(const PrincipalAxes& scene, const PrincipalAxes& model,
                         const std::array<double, 3>& flip) {
  RigidTransform T_model_scene;
  // R = M_model M_scene^-1, M orthonormal so its inverse is its transpose.
  T_model_scene.rotation =
      model.axes * Eigen::Vector3d(flip[0], flip[1], flip[2]).asDiagonal() * scene.axes.transpose();
  T_model_scene.translation_mm = model.centroid_mm - T_model_scene.rotation * scene.centroid_mm;
  return T_model_scene;
}

}  // namespace

std::vector<RigidTransform> principal_axes_candidates(const RegistrationPoints& scene,
                                                      const RegistrationPoints& model) {
  std::vector<RigidTransform> candidates;
  if (scene.size() < 3 || model.size() < 3) return candidates;
  const PrincipalAxes scene_axes = principal_axes(scene);
  const PrincipalAxes model_axes = principal_axes(model);
  for (const auto& flip : kFlips) candidates.push_back(candidate(scene_axes, model_axes, flip));
  return candidates;
}

PrincipalAxesEstimate estimate_by_principal_axes(const RegistrationPoints& scene,
                                                 const RegistrationPoints& model,
                                                 const RegistrationParameters& parameters,
                                                 double min_relative_gap) {
  PrincipalAxesEstimate estimate;
  if (scene.size() < 3 || model.size() < 3) return estimate;
  const PrincipalAxes scene_axes = principal_axes(scene);
  const PrincipalAxes model_axes = principal_axes(model);
  bool first = true;
  for (const auto& flip : kFlips) {
    const RigidTransform T_model_scene = candidate(scene_axes, model_axes, flip);
    const AlignmentScore score = score_alignment(scene, model, T_model_scene, parameters);
    if (first || score.truncated_mean_square_mm2 < estimate.score.truncated_mean_square_mm2) {
      estimate.T_model_scene = T_model_scene;
      estimate.score = score;
      first = false;
    }
  }
  estimate.min_relative_eigenvalue_gap =
      std::min(scene_axes.min_relative_gap, model_axes.min_relative_gap);
  estimate.status = estimate.min_relative_eigenvalue_gap < min_relative_gap
                        ? PrincipalAxesStatus::kAmbiguousAxes
                        : PrincipalAxesStatus::kOk;
  return estimate;
}

}  // namespace cosmos
