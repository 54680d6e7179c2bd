#include "realtime/web/status_json.hpp"

namespace cosmos {

nlohmann::ordered_json status_json(const CellStatus& status) {
  nlohmann::ordered_json json = {
      {"utime_us", status.utime_us},
      {"state", to_string(status.state)},
      {"state_text", status.state_text},
  };
  CellStatus::visit_totals(
      status, [&json](const char* name, std::int64_t total, const char*) { json[name] = total; });
  json["profile_time_p50_us"] = status.profile_time_p50_us;
  json["profile_time_p99_us"] = status.profile_time_p99_us;
  json["profile_time_max_us"] = status.profile_time_max_us;
  json["recognition_queue_depth"] = status.recognition_queue_depth;
  json["publish_queue_depth"] = status.publish_queue_depth;
  return json;
}

}  // namespace cosmos
