#include "realtime/web/status_json.hpp"

namespace cosmos {

nlohmann::ordered_json status_json(const CellStatus& status) {
  return {
      {"utime_us", status.utime_us},
      {"state", to_string(status.state)},
      {"state_text", status.state_text},
      {"profiles_acquired", status.profiles_acquired},
      {"profiles_dropped", status.profiles_dropped},
      {"deadline_overruns", status.deadline_overruns},
      {"profile_time_p50_us", status.profile_time_p50_us},
      {"profile_time_p99_us", status.profile_time_p99_us},
      {"profile_time_max_us", status.profile_time_max_us},
      {"parts_seen", status.parts_seen},
      {"parts_recognized", status.parts_recognized},
      {"parts_rejected", status.parts_rejected},
      {"recognition_queue_depth", status.recognition_queue_depth},
      {"publish_queue_depth", status.publish_queue_depth},
  };
}

}  // namespace cosmos
