// A published pose as the web view's JSON: millimetres, the robot's quaternion, and
// rotation_deg [rx, ry, rz] that rebuilds the rotation as R = Rz Ry Rx.
#include "realtime/web/pose_json.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>

namespace cosmos {
namespace {

double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }

PartPose sample_pose() {
  PartPose pose;
  pose.utime_us = 123456;
  pose.part_seq = 7;
  pose.encoder_ticks = 98765;
  pose.part_name = "elephant";
  pose.part_index = 3;
  pose.view_index = 41;
  pose.status = PoseStatus::kOk;
  pose.rotation_cell_part = Eigen::AngleAxisd(radians(30), Eigen::Vector3d::UnitZ()) *
                            Eigen::AngleAxisd(radians(-20), Eigen::Vector3d::UnitY()) *
                            Eigen::AngleAxisd(radians(10), Eigen::Vector3d::UnitX());
  pose.translation_cell_part_mm = Eigen::Vector3d(-1.5, 80.25, 28.0);
  pose.score = 0.812;
  pose.registration_rms_mm = 0.0125;
  pose.latency_ms = 48.5;
  return pose;
}

TEST(PoseJson, CarriesThePoseInTheCellsUnits) {
  const nlohmann::ordered_json json = pose_json(sample_pose(), 1200, 1480);
  EXPECT_EQ(json.at("part_seq"), 7);
  EXPECT_EQ(json.at("part_name"), "elephant");
  EXPECT_EQ(json.at("status"), "OK");
  EXPECT_EQ(json.at("reason"), "");
  EXPECT_EQ(json.at("translation_mm"), nlohmann::ordered_json({-1.5, 80.25, 28.0}));
  EXPECT_DOUBLE_EQ(json.at("score").get<double>(), 0.812);
  EXPECT_DOUBLE_EQ(json.at("registration_rms_mm").get<double>(), 0.0125);
  EXPECT_DOUBLE_EQ(json.at("latency_ms").get<double>(), 48.5);
  EXPECT_EQ(json.at("encoder_ticks"), 98765);
  EXPECT_EQ(json.at("utime_us"), 123456);
  EXPECT_EQ(json.at("part_index"), 3);
  EXPECT_EQ(json.at("view_index"), 41);
  EXPECT_EQ(json.at("first_profile"), 1200);
  EXPECT_EQ(json.at("last_profile"), 1480);
}

TEST(PoseJson, RotationDegreesRebuildTheRotationAsRzRyRx) {
  const PartPose pose = sample_pose();
  const nlohmann::ordered_json json = pose_json(pose, 0, 0);
  const auto deg = json.at("rotation_deg").get<std::vector<double>>();
  ASSERT_EQ(deg.size(), 3u);
  const Eigen::Matrix3d rebuilt = (Eigen::AngleAxisd(radians(deg[2]), Eigen::Vector3d::UnitZ()) *
                                   Eigen::AngleAxisd(radians(deg[1]), Eigen::Vector3d::UnitY()) *
                                   Eigen::AngleAxisd(radians(deg[0]), Eigen::Vector3d::UnitX()))
                                      .toRotationMatrix();
  EXPECT_TRUE(rebuilt.isApprox(pose.rotation_cell_part.toRotationMatrix(), 1e-12));
  EXPECT_NEAR(deg[0], 10, 1e-9);
  EXPECT_NEAR(deg[1], -20, 1e-9);
  EXPECT_NEAR(deg[2], 30, 1e-9);

  const auto wxyz = json.at("rotation_wxyz").get<std::vector<double>>();
  ASSERT_EQ(wxyz.size(), 4u);
  EXPECT_DOUBLE_EQ(wxyz[0], pose.rotation_cell_part.w());
  EXPECT_DOUBLE_EQ(wxyz[3], pose.rotation_cell_part.z());
}

TEST(PoseJson, ARejectedPoseKeepsItsReason) {
  PartPose pose;
  pose.status = PoseStatus::kRejected;
  pose.reason = "no view cluster matched";
  const nlohmann::ordered_json json = pose_json(pose, 0, 10);
  EXPECT_EQ(json.at("status"), "REJECTED");
  EXPECT_EQ(json.at("reason"), "no view cluster matched");
  EXPECT_EQ(json.at("part_name"), "");
}

}  // namespace
}  // namespace cosmos
