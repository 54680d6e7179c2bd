#pragma once
// Where the cell's results go. The publisher sits behind an interface like the scanner and
// the GPIO lines, so the loop runs the same code against the robot's LCM network, an
// in-process memq:// bus in tests, or a MemoryPublisher.
//
// A publisher is driven by the publisher thread only: converting and sending may allocate
// and block on the network, which the acquisition thread must never do.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/profile.hpp"
#include "realtime/cell/cell_status.hpp"
#include "realtime/cell/part_pose.hpp"
#include "realtime/lcm/lcm_channels.hpp"

namespace lcm {
class LCM;
}

namespace cosmos {

class Publisher {
 public:
  virtual ~Publisher() = default;
  // Each returns false when the message could not be sent. The caller counts it and moves
  // on: a late pose is worse than none for a robot tracking the conveyor.
  virtual bool publish(const PartPose& pose) = 0;      // COSMOS_POSE
  virtual bool publish(const CellStatus& status) = 0;  // COSMOS_STATUS
  virtual bool publish(const Profile& profile) = 0;    // COSMOS_PROFILE
};

// Publishes on an LCM network (udpm://, or memq:// inside one process).
class LcmPublisher final : public Publisher {
 public:
  // Throws InputError naming the URL and the reason when LCM cannot open it.
  explicit LcmPublisher(const std::string& url = kDefaultLcmUrl,
                        const LcmChannelNames& channels = {});
  ~LcmPublisher() override;
  LcmPublisher(const LcmPublisher&) = delete;
  LcmPublisher& operator=(const LcmPublisher&) = delete;

  bool publish(const PartPose& pose) override;
  bool publish(const CellStatus& status) override;
  bool publish(const Profile& profile) override;

  // The instance it publishes on, for subscribers in the same process (memq:// delivers
  // only to subscribers of the publishing instance).
  lcm::LCM& lcm() { return *lcm_; }

 private:
  // Generated message types, kept out of this header; one per type, reused so that
  // publishing stops allocating once the widest profile and longest strings have been seen.
  struct Messages;

  template <class Message>
  bool send(const std::string& channel, const Message& message);

  LcmChannelNames channels_;
  std::unique_ptr<lcm::LCM> lcm_;
  std::unique_ptr<Messages> messages_;
  std::vector<std::uint8_t> bytes_;  // encoding buffer, reused
};

}  // namespace cosmos
