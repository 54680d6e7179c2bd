#include "realtime/lcm/lcm_message_conversion.hpp"

#include <cmath>
#include <cstddef>

namespace cosmos {

static_assert(static_cast<int>(PoseStatus::kOk) == cosmos_lcm::part_pose_t::OK);
static_assert(static_cast<int>(PoseStatus::kRejected) == cosmos_lcm::part_pose_t::REJECTED);
static_assert(static_cast<int>(PoseStatus::kError) == cosmos_lcm::part_pose_t::ERROR);
static_assert(static_cast<int>(CellState::kIdle) == cosmos_lcm::cell_status_t::IDLE);
static_assert(static_cast<int>(CellState::kScanning) == cosmos_lcm::cell_status_t::SCANNING);
static_assert(static_cast<int>(CellState::kFault) == cosmos_lcm::cell_status_t::FAULT);

void to_message(const PartPose& pose, cosmos_lcm::part_pose_t& message) {
  message.utime = pose.utime_us;
  message.part_seq = pose.part_seq;
  message.encoder_ticks = pose.encoder_ticks;
  message.part_name = pose.part_name;
  message.part_index = pose.part_index;
  message.view_index = pose.view_index;
  message.status = static_cast<std::int8_t>(pose.status);
  message.reason = pose.reason;
  for (int i = 0; i < 3; ++i) {
    message.position_m[i] = pose.translation_cell_part_mm[i] / kMillimetresPerMetre;
  }
  // q and -q are the same rotation: w >= 0 makes the message a function of the rotation.
  Eigen::Quaterniond q = pose.rotation_cell_part.normalized();
  if (q.w() < 0.0) q.coeffs() = -q.coeffs();
  message.orientation_wxyz[0] = q.w();
  message.orientation_wxyz[1] = q.x();
  message.orientation_wxyz[2] = q.y();
  message.orientation_wxyz[3] = q.z();
  message.score = pose.score;
  message.registration_rms_mm = pose.registration_rms_mm;
  message.latency_ms = pose.latency_ms;
  message.encoder_ticks_first = pose.encoder_ticks_first;
  for (int i = 0; i < 3; ++i)
    message.blob_extent_m[i] = pose.blob_extent_mm[i] / kMillimetresPerMetre;
}

void from_message(const cosmos_lcm::part_pose_t& message, PartPose& pose) {
  pose.utime_us = message.utime;
  pose.part_seq = message.part_seq;
  pose.encoder_ticks = message.encoder_ticks;
  pose.part_name = message.part_name;
  pose.part_index = message.part_index;
  pose.view_index = message.view_index;
  pose.status = static_cast<PoseStatus>(message.status);
  pose.reason = message.reason;
  for (int i = 0; i < 3; ++i) {
    pose.translation_cell_part_mm[i] = message.position_m[i] * kMillimetresPerMetre;
  }
  pose.rotation_cell_part =
      Eigen::Quaterniond(message.orientation_wxyz[0], message.orientation_wxyz[1],
                         message.orientation_wxyz[2], message.orientation_wxyz[3]);
  pose.score = message.score;
  pose.registration_rms_mm = message.registration_rms_mm;
  pose.latency_ms = message.latency_ms;
  pose.encoder_ticks_first = message.encoder_ticks_first;
  for (int i = 0; i < 3; ++i)
    pose.blob_extent_mm[i] = message.blob_extent_m[i] * kMillimetresPerMetre;
}

void to_message(const CellStatus& status, cosmos_lcm::cell_status_t& message) {
  message.utime = status.utime_us;
  message.state = static_cast<std::int8_t>(status.state);
  message.state_text = status.state_text;
  message.profiles_acquired = status.profiles_acquired;
  message.profiles_dropped = status.profiles_dropped;
  message.deadline_overruns = status.deadline_overruns;
  message.profile_time_p50_us = status.profile_time_p50_us;
  message.profile_time_p99_us = status.profile_time_p99_us;
  message.profile_time_max_us = status.profile_time_max_us;
  message.parts_seen = status.parts_seen;
  message.parts_recognized = status.parts_recognized;
  message.parts_rejected = status.parts_rejected;
  message.recognition_queue_depth = status.recognition_queue_depth;
  message.publish_queue_depth = status.publish_queue_depth;
  message.profiles_lost = status.profiles_lost;
  message.profiles_refused = status.profiles_refused;
  message.samples_too_high = status.samples_too_high;
  message.camera_timeouts = status.camera_timeouts;
  message.encoder_errors = status.encoder_errors;
  message.encoder_reversals = status.encoder_reversals;
  message.gpio_edges_lost = status.gpio_edges_lost;
  message.photo_eye_bounces = status.photo_eye_bounces;
  message.encoder_stalls = status.encoder_stalls;
  message.laser_off_profiles = status.laser_off_profiles;
  message.encoder_counts_unsettled = status.encoder_counts_unsettled;
  message.parts_dropped = status.parts_dropped;
  message.parts_truncated = status.parts_truncated;
  message.runs_dropped = status.runs_dropped;
  message.blobs_merged = status.blobs_merged;
  message.specks_discarded = status.specks_discarded;
}

void from_message(const cosmos_lcm::cell_status_t& message, CellStatus& status) {
  status.utime_us = message.utime;
  status.state = static_cast<CellState>(message.state);
  status.state_text = message.state_text;
  status.profiles_acquired = message.profiles_acquired;
  status.profiles_dropped = message.profiles_dropped;
  status.deadline_overruns = message.deadline_overruns;
  status.profile_time_p50_us = message.profile_time_p50_us;
  status.profile_time_p99_us = message.profile_time_p99_us;
  status.profile_time_max_us = message.profile_time_max_us;
  status.parts_seen = message.parts_seen;
  status.parts_recognized = message.parts_recognized;
  status.parts_rejected = message.parts_rejected;
  status.recognition_queue_depth = message.recognition_queue_depth;
  status.publish_queue_depth = message.publish_queue_depth;
  status.profiles_lost = message.profiles_lost;
  status.profiles_refused = message.profiles_refused;
  status.samples_too_high = message.samples_too_high;
  status.camera_timeouts = message.camera_timeouts;
  status.encoder_errors = message.encoder_errors;
  status.encoder_reversals = message.encoder_reversals;
  status.gpio_edges_lost = message.gpio_edges_lost;
  status.photo_eye_bounces = message.photo_eye_bounces;
  status.encoder_stalls = message.encoder_stalls;
  status.laser_off_profiles = message.laser_off_profiles;
  status.encoder_counts_unsettled = message.encoder_counts_unsettled;
  status.parts_dropped = message.parts_dropped;
  status.parts_truncated = message.parts_truncated;
  status.runs_dropped = message.runs_dropped;
  status.blobs_merged = message.blobs_merged;
  status.specks_discarded = message.specks_discarded;
}

void to_message(const Profile& profile, cosmos_lcm::range_profile_t& message) {
  // LCM has no unsigned types; a stream would need 2^63 profiles to wrap.
  message.seq = static_cast<std::int64_t>(profile.seq);
  message.encoder_ticks = profile.encoder_ticks;
  message.t_us = profile.t_us;
  message.x0_mm = profile.x0_mm;
  message.dx_mm = profile.dx_mm;
  message.width = static_cast<std::int32_t>(profile.width());
  message.z_mm.assign(profile.z_mm.begin(), profile.z_mm.end());
}

bool from_message(const cosmos_lcm::range_profile_t& message, Profile& profile) {
  // Generated decode() leaves z_mm as it was when width is 0, so only the first `width`
  // entries are this message's.
  if (message.width < 0 || message.z_mm.size() < static_cast<std::size_t>(message.width))
    return false;
  // Written as "not inside" so that NaN fails too.
  if (!(message.dx_mm >= kMinProfileSpacingMm && message.dx_mm <= kMaxProfileSpacingMm) ||
      !(std::abs(message.x0_mm) <= kMaxProfileOriginMm))
    return false;
  profile.seq = static_cast<std::uint64_t>(message.seq);
  profile.encoder_ticks = message.encoder_ticks;
  profile.t_us = message.t_us;
  profile.x0_mm = message.x0_mm;
  profile.dx_mm = message.dx_mm;
  profile.z_mm.assign(message.z_mm.begin(), message.z_mm.begin() + message.width);
  return true;
}

}  // namespace cosmos
