#include "realtime/web/pose_json.hpp"

#include <cmath>
#include <numbers>

namespace cosmos {

nlohmann::ordered_json pose_json(const PartPose& pose, std::int64_t first_profile,
                                 std::int64_t last_profile) {
  const Eigen::Vector3d& t = pose.translation_cell_part_mm;
  const Eigen::Quaterniond& q = pose.rotation_cell_part;
  // R = Rz(a) Ry(b) Rx(c): eulerAngles(2, 1, 0) gives [a, b, c].
  const Eigen::Vector3d zyx =
      q.toRotationMatrix().eulerAngles(2, 1, 0) * (180.0 / std::numbers::pi);
  return {
      {"part_seq", pose.part_seq},
      {"part_name", pose.part_name},
      {"status", to_string(pose.status)},
      {"reason", pose.reason},
      {"translation_mm", {t.x(), t.y(), t.z()}},
      {"rotation_wxyz", {q.w(), q.x(), q.y(), q.z()}},
      {"rotation_deg", {zyx[2], zyx[1], zyx[0]}},
      {"score", pose.score},
      {"registration_rms_mm", pose.registration_rms_mm},
      {"latency_ms", pose.latency_ms},
      {"encoder_ticks", pose.encoder_ticks},
      {"utime_us", pose.utime_us},
      {"part_index", pose.part_index},
      {"view_index", pose.view_index},
      {"first_profile", first_profile},
      {"last_profile", last_profile},
  };
}

}  // namespace cosmos
