// Initial-pose hypotheses for registering a scene view onto a model view: the COSMOS pose
// (§5.3.5) when there is one, the four principal-axes candidates (§6.7.2), and turns about
// the viewing axis that align the centroids. On a hand-made pair of views whose true
// T_model_scene is a turn about z and a shift, the true pose is among them.
#include "core/recognition/pose_hypotheses.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "core/registration/registration_points.hpp"
#include "core/rigid_transform.hpp"

namespace cosmos {
namespace {

constexpr double kPi = std::numbers::pi;

RegistrationPoints points_at(const std::vector<Eigen::Vector3d>& positions_mm) {
  RegistrationPoints points;
  const auto n = static_cast<Eigen::Index>(positions_mm.size());
  points.position_mm.resize(3, n);
  for (Eigen::Index i = 0; i < n; ++i)
    points.position_mm.col(i) = positions_mm[static_cast<std::size_t>(i)];
  points.normal = Eigen::Matrix3Xd::Zero(3, n);
  points.normal.row(2).setOnes();
  points.surface =
      Eigen::Matrix<double, kSurfaceCoefficients, Eigen::Dynamic>::Zero(kSurfaceCoefficients, n);
  points.residual_rms_mm = Eigen::VectorXd::Zero(n);
  return points;
}

// A model view: a seeded cloud over an elongated 40 x 16 mm footprint with a 3 mm relief; the
// scene: the same points seen after the part turned 90 degrees about the viewing axis and
// moved, i.e. scene = T_model_scene^-1 (model).
struct ViewPair {
  RegistrationPoints scene, model;
  RigidTransform T_model_scene;
};

ViewPair turned_pair(double turn_deg) {
  std::mt19937_64 generator(23);
  std::uniform_real_distribution<double> unit(-0.5, 0.5);
  std::vector<Eigen::Vector3d> model_positions, scene_positions;
  ViewPair pair;
  pair.T_model_scene = {
      Eigen::AngleAxisd(turn_deg * kPi / 180, Eigen::Vector3d::UnitZ()).toRotationMatrix(),
      {12.0, -5.0, 0.0}};
  const RigidTransform T_scene_model = pair.T_model_scene.inverse();
  for (int i = 0; i < 300; ++i) {
    const Eigen::Vector3d p(40 * unit(generator), 16 * unit(generator), 50 + 3 * unit(generator));
    model_positions.push_back(p);
    scene_positions.push_back(T_scene_model.apply(p));
  }
  pair.scene = points_at(scene_positions);
  pair.model = points_at(model_positions);
  return pair;
}

bool same_pose(const RigidTransform& a, const RigidTransform& b, double tolerance) {
  return rotation_angle_between_rad(a.rotation, b.rotation) < tolerance &&
         translation_error_mm(a, b) < tolerance;
}

TEST(PoseHypotheses, InPlaneTurnTurnsAboutZAndTakesTheSceneCentreOntoTheModels) {
  const Eigen::Vector3d scene_centre(1, 2, 3), model_centre(-4, 5, 6);
  for (int k = 0; k < 8; ++k) {
    const RigidTransform T = in_plane_turn(k, 8, scene_centre, model_centre);
    EXPECT_LT((T.apply(scene_centre) - model_centre).norm(), 1e-12) << k;
    EXPECT_LT((T.rotate(Eigen::Vector3d::UnitZ()) - Eigen::Vector3d::UnitZ()).norm(), 1e-12);
    EXPECT_NEAR(rotation_angle_between_rad(Eigen::Matrix3d::Identity(), T.rotation),
                k <= 4 ? k * kPi / 4 : (8 - k) * kPi / 4, 1e-12)
        << k;
  }
  // Turn 1 of 4: a quarter turn counter-clockwise, x onto y.
  const RigidTransform quarter = in_plane_turn(1, 4, scene_centre, model_centre);
  EXPECT_LT((quarter.rotate(Eigen::Vector3d::UnitX()) - Eigen::Vector3d::UnitY()).norm(), 1e-12);
}

TEST(PoseHypotheses, TheTruePoseIsAmongTheTurnsAndThePrincipalAxesCandidates) {
  const ViewPair pair = turned_pair(90.0);
  const std::vector<RigidTransform> hypotheses =
      generate_pose_hypotheses(pair.scene, pair.model, PoseFromPatches{}, {.in_plane_turns = 12});
  // No COSMOS pose: 4 principal-axes candidates, then the 12 turns.
  ASSERT_EQ(hypotheses.size(), 4u + 12u);
  int principal_matches = 0;
  for (int k = 0; k < 4; ++k)
    principal_matches +=
        same_pose(hypotheses[static_cast<std::size_t>(k)], pair.T_model_scene, 1e-9);
  EXPECT_EQ(principal_matches, 1);
  // 90 degrees is turn 3 of 12: exact.
  for (int k = 0; k < 12; ++k)
    EXPECT_EQ(same_pose(hypotheses[static_cast<std::size_t>(4 + k)], pair.T_model_scene, 1e-9),
              k == 3)
        << "turn " << k;
  // At 100 degrees no turn is exact, but the nearest is within the 15 degrees half spacing,
  // and the principal axes still find the pose.
  const ViewPair off = turned_pair(100.0);
  const std::vector<RigidTransform> off_hypotheses =
      generate_pose_hypotheses(off.scene, off.model, PoseFromPatches{}, {.in_plane_turns = 12});
  double nearest_turn_rad = kPi;
  for (std::size_t k = 4; k < off_hypotheses.size(); ++k)
    nearest_turn_rad = std::min(
        nearest_turn_rad,
        rotation_angle_between_rad(off_hypotheses[k].rotation, off.T_model_scene.rotation));
  EXPECT_NEAR(nearest_turn_rad, 10 * kPi / 180, 1e-9);
  int off_principal_matches = 0;
  for (int k = 0; k < 4; ++k)
    off_principal_matches +=
        same_pose(off_hypotheses[static_cast<std::size_t>(k)], off.T_model_scene, 1e-9);
  EXPECT_EQ(off_principal_matches, 1);
}

TEST(PoseHypotheses, TheCosmosPoseComesFirstWhenThereIsOne) {
  const ViewPair pair = turned_pair(90.0);
  PoseFromPatches from_patches;
  from_patches.status = PatchPoseStatus::kOk;
  from_patches.T_model_scene = {Eigen::Matrix3d::Identity(), {1.0, 2.0, 3.0}};
  const std::vector<RigidTransform> hypotheses =
      generate_pose_hypotheses(pair.scene, pair.model, from_patches, {.in_plane_turns = 6});
  ASSERT_EQ(hypotheses.size(), 1u + 4u + 6u);
  EXPECT_TRUE(same_pose(hypotheses[0], from_patches.T_model_scene, 1e-15));
  // A pose that failed is left out.
  from_patches.status = PatchPoseStatus::kTooFewPairs;
  EXPECT_EQ(
      generate_pose_hypotheses(pair.scene, pair.model, from_patches, {.in_plane_turns = 6}).size(),
      4u + 6u);
  EXPECT_EQ(
      generate_pose_hypotheses(pair.scene, pair.model, PoseFromPatches{}, {.in_plane_turns = 0})
          .size(),
      4u);
}

TEST(PoseHypotheses, AnEmptyViewGivesNoHypotheses) {
  const ViewPair pair = turned_pair(90.0);
  EXPECT_TRUE(
      generate_pose_hypotheses(RegistrationPoints{}, pair.model, PoseFromPatches{}, {}).empty());
  EXPECT_TRUE(
      generate_pose_hypotheses(pair.scene, RegistrationPoints{}, PoseFromPatches{}, {}).empty());
}

}  // namespace
}  // namespace cosmos
