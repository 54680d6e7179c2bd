#pragma once
// The LCM channels the cell publishes on and the network it publishes to by default. The
// robot side and every tool (cosmos listen, lcm-logger, lcm-spy) use these exact names.
#include <string>

namespace cosmos {

inline constexpr char kPoseChannel[] = "COSMOS_POSE";        // part_pose_t, one per part
inline constexpr char kStatusChannel[] = "COSMOS_STATUS";    // cell_status_t, 1 Hz
inline constexpr char kProfileChannel[] = "COSMOS_PROFILE";  // range_profile_t, record/replay

// The names a cell actually uses: these defaults, unless its config's lcm: section renames
// them (two cells on one network).
struct LcmChannelNames {
  std::string pose = kPoseChannel;
  std::string status = kStatusChannel;
  std::string profile = kProfileChannel;
};

// LCM's own default group and port; ttl=0 keeps the traffic on this host until a deployment
// sets the TTL that reaches the robot's controller.
inline constexpr char kDefaultLcmUrl[] = "udpm://239.255.76.67:7667?ttl=0";

}  // namespace cosmos
