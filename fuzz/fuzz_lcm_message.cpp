// One LCM message type as a datagram of the cell's network (`cosmos listen`, the cell's
// subscribers): decoded through realtime/lcm/lcm_codec.hpp and converted to the project's
// struct, chosen by COSMOS_FUZZ_MESSAGE (1: range_profile_t, 2: part_pose_t,
// 3: cell_status_t). What decodes is encoded again.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "realtime/lcm/lcm_codec.hpp"
#include "realtime/lcm/lcm_message_conversion.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::vector<std::uint8_t> bytes;
#if COSMOS_FUZZ_MESSAGE == 1
  cosmos_lcm::range_profile_t message;
  if (!cosmos::decode_message(data, size, cosmos::kMaxProfileWidth, message)) return 0;
  cosmos::Profile profile;
  if (cosmos::from_message(message, profile)) cosmos::to_message(profile, message);
#elif COSMOS_FUZZ_MESSAGE == 2
  cosmos_lcm::part_pose_t message;
  if (!cosmos::decode_message(data, size, message)) return 0;
  cosmos::PartPose pose;
  cosmos::from_message(message, pose);
  cosmos::to_message(pose, message);
#else
  cosmos_lcm::cell_status_t message;
  if (!cosmos::decode_message(data, size, message)) return 0;
  cosmos::CellStatus status;
  cosmos::from_message(message, status);
  cosmos::to_message(status, message);
#endif
  cosmos::encode_message(message, bytes);
  return 0;
}
