#pragma once
// The recognizer's answer for one part, as the publisher sends it to the robot. Millimetres
// like the rest of the pipeline; the LCM message (part_pose_t) carries metres, converted at
// the publisher (lcm_message_conversion.hpp).
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <string>

namespace cosmos {

// Numbered like part_pose_t's constants (checked where they are converted).
enum class PoseStatus : std::int8_t { kOk = 0, kRejected = 1, kError = 2 };

// "OK", "REJECTED", "ERROR", or "UNKNOWN" for a value off the wire that is none of them.
const char* to_string(PoseStatus status);

struct PartPose {
  std::int64_t utime_us = 0;       // the part's last profile's t_us (source clock)
  std::int64_t part_seq = 0;       // running number of parts seen by the cell
  std::int64_t encoder_ticks = 0;  // encoder count at which T_cell_part holds (conveyor tracking)
  // The blob the pose comes from (a reject gate acts on it when there is no pose): encoder
  // count of its first profile (encoder_ticks is its last's), and its bounding box on the belt
  // (across, along, up), mm. A rejected part's translation is the blob's centre.
  std::int64_t encoder_ticks_first = 0;
  Eigen::Vector3d blob_extent_mm = Eigen::Vector3d::Zero();
  std::string part_name;         // catalog name, empty when rejected
  std::int32_t part_index = -1;  // catalog index, -1 when rejected
  std::int32_t view_index = -1;  // matched model-base view, -1 when none
  PoseStatus status = PoseStatus::kRejected;
  std::string reason;  // why rejected or failed, empty when OK

  // T_cell_part: x_cell = rotation_cell_part * x_part + translation_cell_part_mm.
  Eigen::Quaterniond rotation_cell_part = Eigen::Quaterniond::Identity();
  Eigen::Vector3d translation_cell_part_mm = Eigen::Vector3d::Zero();

  double score = 0.0;                // match score in [0, 1]
  double registration_rms_mm = 0.0;  // RMS residual of the final registration
  double latency_ms = 0.0;           // tracker closed the part -> pose published
};

}  // namespace cosmos
