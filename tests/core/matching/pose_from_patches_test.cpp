// Initial pose from corresponding patch groups (§5.3.5).
#include "core/matching/pose_from_patches.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <vector>

#include "core/matching/patch_group_matching.hpp"
#include "core/rigid_transform.hpp"
#include "tests/core/matching_fixture.hpp"

namespace cosmos {
namespace {

using testing::analytic_view;
using testing::relief_view;
using testing::rotation_about_z_deg;

constexpr double kDegToRad = std::numbers::pi / 180.0;

Eigen::Matrix3d known_rotation() {
  return Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
}

std::vector<Eigen::Vector3d> some_normals() {
  return {Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(0.6, 0, 0.8),
          Eigen::Vector3d(-0.3, 0.5, 0.81).normalized(),
          Eigen::Vector3d(0.1, -0.7, 0.7).normalized(),
          Eigen::Vector3d(-0.8, -0.2, 0.56).normalized()};
}

double max_abs_difference(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) {
  return (a - b).cwiseAbs().maxCoeff();
}

TEST(PoseFromPatches, HandMadeNormalsGiveTheKnownRotationTo1e9) {
  const Eigen::Matrix3d R_model_scene = known_rotation();
  std::vector<NormalCorrespondence> normals;
  double weight = 1.0;
  for (const Eigen::Vector3d& n : some_normals()) {
    normals.push_back({n, R_model_scene * n, weight});
    weight *= 1.7;  // unequal weights must not matter for exact data
  }
  const RotationFromNormals rotation = rotation_from_normals(normals, 5.0);
  EXPECT_EQ(rotation.status, PatchPoseStatus::kOk);
  EXPECT_LT(max_abs_difference(rotation.R_model_scene, R_model_scene), 1e-9);
  EXPECT_LT(rotation.rms_residual_deg, 1e-9);
  EXPECT_NEAR(rotation.R_model_scene.determinant(), 1.0, 1e-12);
}

TEST(PoseFromPatches, TwoPairsTurnAboutTheAxisOfTheThesisConstruction) {
  // §5.3.5: with two MappedPairs the rotation axis is (n_m1 - n_s1) x (n_m2 - n_s2).
  const Eigen::Matrix3d R_model_scene = known_rotation();
  const Eigen::Vector3d n_s1(0, 0, 1);
  const Eigen::Vector3d n_s2 = Eigen::Vector3d(0.6, 0.2, 0.77).normalized();
  const Eigen::Vector3d n_m1 = R_model_scene * n_s1;
  const Eigen::Vector3d n_m2 = R_model_scene * n_s2;
  const std::vector<NormalCorrespondence> normals = {{n_s1, n_m1, 1.0}, {n_s2, n_m2, 3.0}};
  const RotationFromNormals rotation = rotation_from_normals(normals, 5.0);
  EXPECT_EQ(rotation.status, PatchPoseStatus::kOk);
  const Eigen::Vector3d thesis_axis = (n_m1 - n_s1).cross(n_m2 - n_s2).normalized();
  const Eigen::AngleAxisd recovered(rotation.R_model_scene);
  EXPECT_NEAR(std::abs(recovered.axis().dot(thesis_axis)), 1.0, 1e-9);
  EXPECT_LT(max_abs_difference(rotation.R_model_scene, R_model_scene), 1e-9);
}

TEST(PoseFromPatches, NormalSpreadIsTheAngleBetweenTwoEquallyWeightedNormals) {
  const Eigen::Vector3d a(0, 0, 1);
  const Eigen::Vector3d b(std::sin(30 * kDegToRad), 0, std::cos(30 * kDegToRad));
  const std::vector<NormalCorrespondence> normals = {{a, a, 2.0}, {b, b, 2.0}};
  const RotationFromNormals rotation = rotation_from_normals(normals, 5.0);
  EXPECT_NEAR(rotation.normal_spread_deg, 30.0, 1e-9);
  EXPECT_EQ(rotation.status, PatchPoseStatus::kOk);
  EXPECT_LT(max_abs_difference(rotation.R_model_scene, Eigen::Matrix3d::Identity()), 1e-12);
}

TEST(PoseFromPatches, FewerThanTwoNonParallelNormalsAreReported) {
  EXPECT_EQ(rotation_from_normals({}, 5.0).status, PatchPoseStatus::kTooFewPairs);
  const Eigen::Vector3d z = Eigen::Vector3d::UnitZ();
  const std::vector<NormalCorrespondence> zero_weight = {{z, z, 0.0}};
  EXPECT_EQ(rotation_from_normals(zero_weight, 5.0).status, PatchPoseStatus::kTooFewPairs);
  const std::vector<NormalCorrespondence> one = {{z, z, 1.0}};
  EXPECT_EQ(rotation_from_normals(one, 5.0).status, PatchPoseStatus::kDegenerateNormals);
  const std::vector<NormalCorrespondence> parallel = {{z, z, 1.0}, {z, z, 5.0}, {-z, -z, 1.0}};
  EXPECT_EQ(rotation_from_normals(parallel, 5.0).status, PatchPoseStatus::kDegenerateNormals);
  const Eigen::Vector3d tilted(std::sin(3 * kDegToRad), 0, std::cos(3 * kDegToRad));
  const std::vector<NormalCorrespondence> close = {{z, z, 1.0}, {tilted, tilted, 1.0}};
  const RotationFromNormals nearly = rotation_from_normals(close, 5.0);
  EXPECT_EQ(nearly.status, PatchPoseStatus::kDegenerateNormals);
  EXPECT_NEAR(nearly.normal_spread_deg, 3.0, 1e-9);
}

// A hand-made model view and the scene view of the same patches placed by T_scene_model.
struct HandViews {
  CosmosView model;
  CosmosView scene;
};

HandViews hand_views(const RigidTransform& T_scene_model) {
  HandViews views;
  const std::vector<Eigen::Vector3d> normals = some_normals();
  for (int i = 0; i < static_cast<int>(normals.size()); ++i) {
    Csmp patch;
    patch.id = 10 + i;
    patch.area_mm2 = 50.0 + 30.0 * i;
    patch.mean_normal = normals[i];
    patch.centroid_mm = Eigen::Vector3d(5.0 * i, -3.0 * i * i, 40.0 + i);
    views.model.patches.push_back(patch);
    patch.mean_normal = T_scene_model.rotate(normals[i]);
    patch.centroid_mm = T_scene_model.apply(patch.centroid_mm);
    views.scene.patches.push_back(patch);
  }
  return views;
}

TEST(PoseFromPatches, HandMadeViewsGiveTheKnownPoseTo1e9) {
  const RigidTransform T_model_scene{known_rotation(), Eigen::Vector3d(12.0, -7.5, 3.25)};
  const HandViews views = hand_views(T_model_scene.inverse());
  // Singles and one group of two patches (its normal and centroid are area-weighted means,
  // which rotate with the patches).
  std::vector<MappedPair> pairs = {
      {{10}, {10}, {}}, {{11, 12}, {11, 12}, {}}, {{13}, {13}, {}}, {{14}, {14}, {}}};
  const PoseFromPatches pose = estimate_pose_from_patches(views.scene, views.model, pairs);
  EXPECT_EQ(pose.status, PatchPoseStatus::kOk);
  EXPECT_EQ(pose.pairs_used, 4);
  EXPECT_LT(max_abs_difference(pose.T_model_scene.rotation, T_model_scene.rotation), 1e-9);
  EXPECT_LT((pose.T_model_scene.translation_mm - T_model_scene.translation_mm).norm(), 1e-9);
}

TEST(PoseFromPatches, GroupsWithoutAnOrientationAreLeftOut) {
  const HandViews views = hand_views(RigidTransform{});
  CosmosView scene = views.scene;
  CosmosView model = views.model;
  // Two opposite patches of equal area: their mean normal vanishes (§3.2.2).
  for (CosmosView* view : {&scene, &model}) {
    view->patches[3].mean_normal = Eigen::Vector3d(1, 0, 0);
    view->patches[4].mean_normal = Eigen::Vector3d(-1, 0, 0);
    view->patches[4].area_mm2 = view->patches[3].area_mm2;
  }
  const std::vector<MappedPair> pairs = {
      {{10}, {10}, {}}, {{11}, {11}, {}}, {{13, 14}, {13, 14}, {}}};
  const PoseFromPatches pose = estimate_pose_from_patches(scene, model, pairs);
  EXPECT_EQ(pose.pairs_used, 2);
  EXPECT_EQ(pose.status, PatchPoseStatus::kOk);
  EXPECT_LT(max_abs_difference(pose.T_model_scene.rotation, Eigen::Matrix3d::Identity()), 1e-9);
}

TEST(PoseFromPatches, CapsuleCorrespondenceGivesTheTurnAboutZ) {
  const auto& scene = analytic_view(AnalyticShape::kCapsule, 35);
  const auto& model = analytic_view(AnalyticShape::kCapsule, 0);
  const PatchGroupMatch match = match_patch_groups(scene.view, model.view);
  const PoseFromPatches pose = estimate_pose_from_patches(scene.view, model.view, match.pairs);
  ASSERT_EQ(pose.status, PatchPoseStatus::kOk);
  const Eigen::Matrix3d R_true = model.R_scanner_part * scene.R_scanner_part.transpose();
  // The capsule is symmetric under a half turn about z, and the match cannot tell its caps
  // apart: either pose is right.
  const double error_deg =
      std::min(rotation_angle_between_rad(pose.T_model_scene.rotation, R_true),
               rotation_angle_between_rad(pose.T_model_scene.rotation,
                                          rotation_about_z_deg(180) * R_true)) /
      kDegToRad;
  EXPECT_LT(error_deg, 3.0);
  EXPECT_LT(pose.T_model_scene.translation_mm.norm(), 2.0);
}

TEST(PoseFromPatches, FreeFormCorrespondenceGivesTheTurnAboutZ) {
  const auto& scene = relief_view(40);
  const auto& model = relief_view(0);
  const PatchGroupMatch match = match_patch_groups(scene.view, model.view);
  const PoseFromPatches pose = estimate_pose_from_patches(scene.view, model.view, match.pairs);
  ASSERT_EQ(pose.status, PatchPoseStatus::kOk);
  const Eigen::Matrix3d R_true = model.R_scanner_part * scene.R_scanner_part.transpose();
  EXPECT_LT(rotation_angle_between_rad(pose.T_model_scene.rotation, R_true) / kDegToRad, 2.0);
  // Both views see the whole round footprint, turned about its centre: t = 0.
  EXPECT_LT(pose.T_model_scene.translation_mm.norm(), 2.0);
  EXPECT_GT(pose.normal_spread_deg, 20.0);
}

TEST(PoseFromPatches, TorusNormalsAllAlongZDoNotFixARotation) {
  const auto& torus = analytic_view(AnalyticShape::kTorus, 0);
  const PatchGroupMatch match = match_patch_groups(torus.view, torus.view);
  const PoseFromPatches pose = estimate_pose_from_patches(torus.view, torus.view, match.pairs);
  EXPECT_EQ(pose.status, PatchPoseStatus::kDegenerateNormals);
  EXPECT_LT(pose.normal_spread_deg, 5.0);
}

}  // namespace
}  // namespace cosmos
