#pragma once
// Hand-made messages with known values for the LCM tests, and field-for-field comparisons
// (bitwise for the profile heights, so NaN positions count too).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>

#include "core/profile.hpp"
#include "realtime/cell/cell_status.hpp"
#include "realtime/cell/part_pose.hpp"

namespace cosmos::testing {

// Rotation given with w < 0 on purpose: the message must carry the w >= 0 twin.
inline PartPose sample_pose(std::int64_t part_seq) {
  PartPose pose;
  pose.utime_us = 1'700'000'000'000'000 + part_seq;
  pose.part_seq = part_seq;
  pose.encoder_ticks = 40'000 + 1000 * part_seq;
  pose.part_name = "bunny_" + std::to_string(part_seq);
  pose.part_index = static_cast<std::int32_t>(part_seq % 5);
  pose.view_index = 17 + static_cast<std::int32_t>(part_seq);
  pose.status = part_seq % 2 == 0 ? PoseStatus::kOk : PoseStatus::kRejected;
  pose.reason = pose.status == PoseStatus::kOk ? "" : "score below 0.6";
  const Eigen::Quaterniond q(Eigen::AngleAxisd(0.7 + 0.1 * static_cast<double>(part_seq),
                                               Eigen::Vector3d(1.0, 2.0, 3.0).normalized()));
  pose.rotation_cell_part.coeffs() = -q.coeffs();
  pose.translation_cell_part_mm =
      Eigen::Vector3d(123.4 + static_cast<double>(part_seq), -56.7, 30.0);
  pose.score = 0.93;
  pose.registration_rms_mm = 0.08;
  pose.latency_ms = 14.2;
  pose.encoder_ticks_first = 39'000 + 1000 * part_seq;
  pose.blob_extent_mm = Eigen::Vector3d(61.5, 88.25, 30.5);
  return pose;
}

inline CellStatus sample_status(const std::string& state_text) {
  CellStatus status;
  status.utime_us = 1'700'000'000'123'456;
  status.state = CellState::kScanning;
  status.state_text = state_text;
  // A different value in every total, so a field the conversion forgets or swaps shows.
  std::int64_t value = 123'456;
  CellStatus::visit_totals(status, [&value](const char*, std::int64_t& total, const char*) {
    total = value;
    value += 7;
  });
  status.profile_time_p50_us = 112.5;
  status.profile_time_p99_us = 287.25;
  status.profile_time_max_us = 911.0;
  status.recognition_queue_depth = 1;
  status.publish_queue_depth = 0;
  return status;
}

// A belt edge to edge: no data at both ends and in a gap in the middle.
inline Profile sample_profile(std::uint64_t seq, std::size_t width = 640) {
  Profile profile;
  profile.seq = seq;
  profile.encoder_ticks = 1'000'000 + static_cast<std::int64_t>(seq) * 4;
  profile.t_us = 5'000'000 + static_cast<std::int64_t>(seq) * 250;
  profile.x0_mm = -160.0;
  profile.dx_mm = 0.5;
  profile.resize(width);
  for (std::size_t i = 10; i + 10 < width; ++i) {
    if (i >= width / 2 && i < width / 2 + 5) continue;
    profile.z_mm[i] = 20.0F + 0.01F * static_cast<float>(i) + static_cast<float>(seq);
  }
  return profile;
}

inline std::uint32_t float_bits(float value) {
  std::uint32_t bits = 0;
  std::memcpy(&bits, &value, sizeof bits);
  return bits;
}

// Translation within 1e-12 mm: mm -> m -> mm may round in the last bit.
inline void expect_same_pose(const PartPose& expected, const PartPose& actual) {
  EXPECT_EQ(actual.utime_us, expected.utime_us);
  EXPECT_EQ(actual.part_seq, expected.part_seq);
  EXPECT_EQ(actual.encoder_ticks, expected.encoder_ticks);
  EXPECT_EQ(actual.part_name, expected.part_name);
  EXPECT_EQ(actual.part_index, expected.part_index);
  EXPECT_EQ(actual.view_index, expected.view_index);
  EXPECT_EQ(actual.status, expected.status);
  EXPECT_EQ(actual.reason, expected.reason);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(actual.translation_cell_part_mm[i], expected.translation_cell_part_mm[i], 1e-12)
        << i;
  }
  const Eigen::Matrix3d rotation_difference =
      actual.rotation_cell_part.toRotationMatrix() - expected.rotation_cell_part.toRotationMatrix();
  EXPECT_LT(rotation_difference.cwiseAbs().maxCoeff(), 1e-15);
  EXPECT_GE(actual.rotation_cell_part.w(), 0.0);
  EXPECT_EQ(actual.score, expected.score);
  EXPECT_EQ(actual.registration_rms_mm, expected.registration_rms_mm);
  EXPECT_EQ(actual.latency_ms, expected.latency_ms);
  EXPECT_EQ(actual.encoder_ticks_first, expected.encoder_ticks_first);
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR(actual.blob_extent_mm[i], expected.blob_extent_mm[i], 1e-12) << i;
}

inline void expect_same_status(const CellStatus& expected, const CellStatus& actual) {
  EXPECT_EQ(actual.utime_us, expected.utime_us);
  EXPECT_EQ(actual.state, expected.state);
  EXPECT_EQ(actual.state_text, expected.state_text);
  CellStatus::visit_totals(
      expected, [&actual](const char* name, const std::int64_t& total, const char*) {
        std::int64_t actual_total = -1;
        CellStatus::visit_totals(actual,
                                 [&](const char* other, const std::int64_t& value, const char*) {
                                   if (std::string_view(other) == name) actual_total = value;
                                 });
        EXPECT_EQ(actual_total, total) << name;
      });
  EXPECT_EQ(actual.profile_time_p50_us, expected.profile_time_p50_us);
  EXPECT_EQ(actual.profile_time_p99_us, expected.profile_time_p99_us);
  EXPECT_EQ(actual.profile_time_max_us, expected.profile_time_max_us);
  EXPECT_EQ(actual.recognition_queue_depth, expected.recognition_queue_depth);
  EXPECT_EQ(actual.publish_queue_depth, expected.publish_queue_depth);
}

inline void expect_same_profile(const Profile& expected, const Profile& actual) {
  EXPECT_EQ(actual.seq, expected.seq);
  EXPECT_EQ(actual.encoder_ticks, expected.encoder_ticks);
  EXPECT_EQ(actual.t_us, expected.t_us);
  EXPECT_EQ(actual.x0_mm, expected.x0_mm);
  EXPECT_EQ(actual.dx_mm, expected.dx_mm);
  ASSERT_EQ(actual.width(), expected.width());
  std::size_t differing = 0;
  for (std::size_t i = 0; i < expected.width(); ++i) {
    if (float_bits(actual.z_mm[i]) != float_bits(expected.z_mm[i])) ++differing;
  }
  EXPECT_EQ(differing, 0U) << "of " << expected.width() << " samples";
}

}  // namespace cosmos::testing
