#include "realtime/cell/part_pose.hpp"

namespace cosmos {

const char* to_string(PoseStatus status) {
  switch (status) {
    case PoseStatus::kOk:
      return "OK";
    case PoseStatus::kRejected:
      return "REJECTED";
    case PoseStatus::kError:
      return "ERROR";
  }
  return "UNKNOWN";
}

}  // namespace cosmos
