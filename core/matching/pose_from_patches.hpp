#pragma once
// Initial pose from corresponding patch groups (§5.3.5): the rotation that aligns the mean
// normals (G0, Eq. 3.7) of the scene's patch groups with those of their model partners, and
// the translation that then aligns their area-weighted centroids.
//
// §5.3.5 (after Flynn and Jain) computes an axis and angle from each two MappedPairs and
// averages the consistent ones; we solve the same alignment for all pairs at once as the
// weighted least-squares rotation between two sets of directions (Kabsch/Horn via a 3x3
// SVD), which equals the two-pair construction when there are exactly two pairs and
// averages the rest optimally instead of by thresholds. Any two non-parallel normals fix the
// rotation; with fewer the rotation about the common normal is free and the status says so.
// The registration of chapter 6 refines this estimate.
#include <Eigen/Core>
#include <span>
#include <vector>

#include "core/matching/patch_group_matching.hpp"
#include "core/parameter_visitor.hpp"
#include "core/representation/cosmos_view.hpp"
#include "core/rigid_transform.hpp"

namespace cosmos {

enum class PatchPoseStatus {
  kOk,
  kTooFewPairs,        // no pair with a usable mean normal and positive weight
  kDegenerateNormals,  // the normals (on either side) are too close to parallel
};

struct NormalCorrespondence {
  Eigen::Vector3d scene_normal = Eigen::Vector3d::UnitZ();  // unit
  Eigen::Vector3d model_normal = Eigen::Vector3d::UnitZ();  // unit
  double weight = 1;
};

struct RotationFromNormals {
  PatchPoseStatus status = PatchPoseStatus::kTooFewPairs;
  // n_model ~ R_model_scene n_scene. Filled in for degenerate_normals too, but then its
  // angle about the common normal is arbitrary.
  Eigen::Matrix3d R_model_scene = Eigen::Matrix3d::Identity();
  // How far from parallel the normals are: 2 atan(sqrt(l2 / l1)) of the two largest
  // eigenvalues of the weighted scatter sum w n n^T, the smaller over both sides. For two
  // equally weighted normals it is the angle between them.
  double normal_spread_deg = 0;
  double rms_residual_deg = 0;  // weighted RMS angle between R n_scene and n_model
};

// Weights <= 0 and non-finite entries are ignored.
RotationFromNormals rotation_from_normals(std::span<const NormalCorrespondence> normals,
                                          double min_normal_spread_deg);

struct PoseFromPatchesParameters {
  // Normals closer to parallel than this (as normal_spread_deg) do not fix a rotation.
  double min_normal_spread_deg = 5.0;
  // A group whose patch normals nearly cancel (|area-weighted mean| below this, e.g. a whole
  // cylinder) has no orientation (§3.2.2, the centre of the unit sphere): left out of R.
  double min_group_normal_length = 0.3;

  template <class Visitor>
  void visit(Visitor& v) {
    v("min_normal_spread_deg", min_normal_spread_deg, "less spread normals fix no rotation, deg",
      Range{0, 180});
    v("min_group_normal_length", min_group_normal_length,
      "shorter mean group normals have no orientation", Range{0, 1});
  }
};

struct PoseFromPatches {
  PatchPoseStatus status = PatchPoseStatus::kTooFewPairs;
  RigidTransform T_model_scene;  // x_model = R x_scene + t
  double normal_spread_deg = 0;
  double rms_normal_residual_deg = 0;
  int pairs_used = 0;  // pairs whose normals entered the rotation
};

// Each MappedPair weighs the mean area (mm^2) of its two groups times its goodness
// (§5.3.3), so large, well matched groups dominate, as larger patch-groups do in the
// quality. Group normals and centroids are area-weighted over the group's patches. The
// translation t = c_model - R c_scene aligns the weighted centroids of all pairs.
PoseFromPatches estimate_pose_from_patches(const CosmosView& scene, const CosmosView& model,
                                           const std::vector<MappedPair>& pairs,
                                           const PoseFromPatchesParameters& parameters = {});

}  // namespace cosmos
