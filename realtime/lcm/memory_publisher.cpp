#include "realtime/lcm/memory_publisher.hpp"

namespace cosmos {

bool MemoryPublisher::publish(const PartPose& pose) {
  poses.push_back(pose);
  return true;
}

bool MemoryPublisher::publish(const CellStatus& status) {
  statuses.push_back(status);
  return true;
}

bool MemoryPublisher::publish(const Profile& profile) {
  profiles.push_back(profile);
  return true;
}

}  // namespace cosmos
