// Whether a pose rests on the belt (check_resting): a 40 x 20 x 10 mm box, its six resting
// poses and its hull's corners, in poses that rest, float, sink or lean.
#include "core/recognition/resting_pose_search.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <numbers>

namespace cosmos {
namespace {

constexpr double kDegree = std::numbers::pi / 180;

ModelPart box_part(int resting_poses_kept) {
  ModelPart part;
  part.name = "box";
  for (double x : {-20.0, 20.0})
    for (double y : {-10.0, 10.0})
      for (double z : {-5.0, 5.0}) part.hull_vertices_mm.emplace_back(x, y, z);
  // Face down: -z, +z, -y, +y, -x, +x; the larger faces likelier.
  const Eigen::Matrix3d flip =
      Eigen::AngleAxisd(std::numbers::pi, Eigen::Vector3d::UnitX()).toRotationMatrix();
  const Eigen::Matrix3d y_down =
      Eigen::AngleAxisd(-std::numbers::pi / 2, Eigen::Vector3d::UnitX()).toRotationMatrix();
  const Eigen::Matrix3d x_down =
      Eigen::AngleAxisd(std::numbers::pi / 2, Eigen::Vector3d::UnitY()).toRotationMatrix();
  const std::vector<RestingPose> all = {{Eigen::Matrix3d::Identity(), 5, 0.3},
                                        {flip, 5, 0.3},
                                        {y_down, 10, 0.15},
                                        {flip * y_down, 10, 0.15},
                                        {x_down, 20, 0.05},
                                        {flip * x_down, 20, 0.05}};
  part.resting_poses.assign(all.begin(), all.begin() + resting_poses_kept);
  return part;
}

// T_part_scene of the box lying with `R_belt_part`, turned about the vertical and moved on
// the belt, its origin `lift_mm` above its resting height.
RigidTransform lying(const RestingPose& pose, double turn_deg, double lift_mm) {
  RigidTransform T_scene_part;
  T_scene_part.rotation =
      Eigen::AngleAxisd(turn_deg * kDegree, Eigen::Vector3d::UnitZ()).toRotationMatrix() *
      pose.R_belt_part;
  T_scene_part.translation_mm = Eigen::Vector3d(12, -30, pose.height_mm + lift_mm);
  return T_scene_part.inverse();
}

TEST(RestingPoseSearch, APoseOnAStableFaceTurnedAnywhereRests) {
  const ModelPart part = box_part(6);
  for (const RestingPose& pose : part.resting_poses)
    for (double turn_deg : {0.0, 37.0, 190.0}) {
      const RestingCheck check = check_resting(part, lying(pose, turn_deg, 0), {});
      EXPECT_TRUE(check.at_rest);
      EXPECT_TRUE(check.covered);
      EXPECT_NEAR(check.lowest_point_mm, 0, 1e-9);
      EXPECT_NEAR(check.tilt_deg, 0, 1e-4);
    }
}

TEST(RestingPoseSearch, AFloatingOrSunkenPartDoesNotRest) {
  const ModelPart part = box_part(6);
  const RestingSearchParameters parameters;
  const RestingCheck floating =
      check_resting(part, lying(part.resting_poses[2], 10, 3), parameters);
  EXPECT_FALSE(floating.at_rest);
  EXPECT_NEAR(floating.lowest_point_mm, 3, 1e-9);
  const RestingCheck sunk = check_resting(part, lying(part.resting_poses[0], 10, -3), parameters);
  EXPECT_FALSE(sunk.at_rest);
  EXPECT_NEAR(sunk.lowest_point_mm, -3, 1e-9);
  EXPECT_TRUE(check_resting(part, lying(part.resting_poses[0], 10, 1.5), parameters).at_rest);
}

TEST(RestingPoseSearch, ALeaningPartTouchingTheBeltDoesNotRestUnlessItsPosesAreUnknown) {
  // Tilted 20 degrees about the box's long axis and lowered onto the belt: one edge touches.
  RigidTransform T_scene_part;
  T_scene_part.rotation =
      Eigen::AngleAxisd(20 * kDegree, Eigen::Vector3d::UnitX()).toRotationMatrix();
  double lowest = 0;
  for (const Eigen::Vector3d& corner : box_part(6).hull_vertices_mm)
    lowest = std::min(lowest, (T_scene_part.rotation * corner).z());
  T_scene_part.translation_mm = Eigen::Vector3d(0, 0, -lowest);
  const RestingCheck leaning = check_resting(box_part(6), T_scene_part.inverse(), {});
  EXPECT_NEAR(leaning.lowest_point_mm, 0, 1e-9);
  EXPECT_NEAR(leaning.tilt_deg, 20, 1e-6);
  EXPECT_FALSE(leaning.at_rest);
  // With only the two likeliest poses kept (60 % of the chance) the part's stable poses are
  // not known well enough to refuse a lean: the contact alone decides.
  const RestingCheck uncovered = check_resting(box_part(2), T_scene_part.inverse(), {});
  EXPECT_FALSE(uncovered.covered);
  EXPECT_TRUE(uncovered.at_rest);
}

}  // namespace
}  // namespace cosmos
