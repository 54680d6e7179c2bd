#pragma once
// The simulated Publisher: keeps every message in memory, in order, so tests of the loop and
// the recognizer check what the robot would have received without any network.
#include <vector>

#include "realtime/lcm/pose_publisher.hpp"

namespace cosmos {

class MemoryPublisher final : public Publisher {
 public:
  bool publish(const PartPose& pose) override;
  bool publish(const CellStatus& status) override;
  bool publish(const Profile& profile) override;

  std::vector<PartPose> poses;
  std::vector<CellStatus> statuses;
  std::vector<Profile> profiles;
};

}  // namespace cosmos
