#include "realtime/lcm/pose_publisher.hpp"

#include <lcm/lcm-cpp.hpp>

#include "realtime/lcm/lcm_codec.hpp"
#include "realtime/lcm/lcm_connection.hpp"
#include "realtime/lcm/lcm_message_conversion.hpp"

namespace cosmos {

struct LcmPublisher::Messages {
  cosmos_lcm::part_pose_t pose{};
  cosmos_lcm::cell_status_t status{};
  cosmos_lcm::range_profile_t profile{};
};

LcmPublisher::LcmPublisher(const std::string& url, const LcmChannelNames& channels)
    : channels_(channels), lcm_(open_lcm(url)), messages_(std::make_unique<Messages>()) {}

LcmPublisher::~LcmPublisher() = default;

template <class Message>
bool LcmPublisher::send(const std::string& channel, const Message& message) {
  if (!encode_message(message, bytes_)) return false;
  return lcm_->publish(channel, bytes_.data(), static_cast<unsigned>(bytes_.size())) == 0;
}

bool LcmPublisher::publish(const PartPose& pose) {
  to_message(pose, messages_->pose);
  return send(channels_.pose, messages_->pose);
}

bool LcmPublisher::publish(const CellStatus& status) {
  to_message(status, messages_->status);
  return send(channels_.status, messages_->status);
}

bool LcmPublisher::publish(const Profile& profile) {
  to_message(profile, messages_->profile);
  return send(channels_.profile, messages_->profile);
}

}  // namespace cosmos
