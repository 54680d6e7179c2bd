// In-process round trip over memq://: what LcmPublisher sends is what a subscriber decodes,
// field for field, with the pipeline's millimetres arriving as metres.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <lcm/lcm-cpp.hpp>
#include <string>
#include <type_traits>
#include <vector>

#include "realtime/lcm/lcm_codec.hpp"
#include "realtime/lcm/lcm_message_conversion.hpp"
#include "realtime/lcm/memory_publisher.hpp"
#include "realtime/lcm/pose_publisher.hpp"
#include "tests/realtime/lcm_test_messages.hpp"

namespace cosmos {
namespace {

using testing::sample_pose;
using testing::sample_profile;
using testing::sample_status;

struct Arrival {
  std::string channel;
  std::vector<std::uint8_t> bytes;
};

class LcmMemqRoundTrip : public ::testing::Test {
 protected:
  void SetUp() override {
    for (const char* channel : {kPoseChannel, kStatusChannel, kProfileChannel}) {
      publisher_.lcm().subscribe(channel, &LcmMemqRoundTrip::on_message, this);
    }
  }

  void on_message(const lcm::ReceiveBuffer* buffer, const std::string& channel) {
    const auto* data = static_cast<const std::uint8_t*>(buffer->data);
    arrivals_.push_back({channel, std::vector<std::uint8_t>(data, data + buffer->data_size)});
  }

  // memq:// delivers when the instance handles its queue; bounded so a lost message fails.
  void receive(std::size_t count) {
    for (int attempt = 0; attempt < 100 && arrivals_.size() < count; ++attempt)
      publisher_.lcm().handleTimeout(10);
    ASSERT_EQ(arrivals_.size(), count);
  }

  template <class Message>
  Message decoded(std::size_t arrival, const char* channel) const {
    EXPECT_EQ(arrivals_[arrival].channel, channel);
    Message message{};
    const auto& bytes = arrivals_[arrival].bytes;
    if constexpr (std::is_same_v<Message, cosmos_lcm::range_profile_t>) {
      EXPECT_TRUE(decode_message(bytes.data(), bytes.size(), kMaxProfileWidth, message));
    } else {
      EXPECT_TRUE(decode_message(bytes.data(), bytes.size(), message));
    }
    return message;
  }

  LcmPublisher publisher_{"memq://"};
  std::vector<Arrival> arrivals_;
};

TEST_F(LcmMemqRoundTrip, PoseArrivesFieldForFieldInMetres) {
  const PartPose sent = sample_pose(2);
  ASSERT_TRUE(publisher_.publish(sent));
  receive(1);
  const auto message = decoded<cosmos_lcm::part_pose_t>(0, kPoseChannel);

  // 125.4 mm, -56.7 mm, 30 mm on the wire as metres.
  EXPECT_DOUBLE_EQ(message.position_m[0], 0.1254);
  EXPECT_DOUBLE_EQ(message.position_m[1], -0.0567);
  EXPECT_DOUBLE_EQ(message.position_m[2], 0.030);
  for (int i = 0; i < 3; ++i)
    EXPECT_EQ(message.position_m[i], sent.translation_cell_part_mm[i] / 1000.0);
  // The sample's quaternion has w < 0: the message carries its w >= 0 twin (same rotation).
  ASSERT_LT(sent.rotation_cell_part.w(), 0.0);
  EXPECT_NEAR(message.orientation_wxyz[0], -sent.rotation_cell_part.w(), 1e-15);
  EXPECT_NEAR(message.orientation_wxyz[1], -sent.rotation_cell_part.x(), 1e-15);
  EXPECT_NEAR(message.orientation_wxyz[2], -sent.rotation_cell_part.y(), 1e-15);
  EXPECT_NEAR(message.orientation_wxyz[3], -sent.rotation_cell_part.z(), 1e-15);
  EXPECT_EQ(message.status, cosmos_lcm::part_pose_t::OK);
  EXPECT_EQ(message.part_name, "bunny_2");
  EXPECT_EQ(message.encoder_ticks, 42'000);

  PartPose received;
  from_message(message, received);
  testing::expect_same_pose(sent, received);
}

TEST_F(LcmMemqRoundTrip, RejectedPoseKeepsItsReason) {
  PartPose sent = sample_pose(3);
  sent.part_index = -1;
  sent.part_name.clear();
  ASSERT_TRUE(publisher_.publish(sent));
  receive(1);
  const auto message = decoded<cosmos_lcm::part_pose_t>(0, kPoseChannel);
  EXPECT_EQ(message.status, cosmos_lcm::part_pose_t::REJECTED);
  EXPECT_EQ(message.part_index, -1);
  EXPECT_EQ(message.reason, "score below 0.6");
  PartPose received;
  from_message(message, received);
  testing::expect_same_pose(sent, received);
}

TEST_F(LcmMemqRoundTrip, StatusArrivesFieldForField) {
  const CellStatus sent = sample_status("scanning, 3 parts on the belt");
  ASSERT_TRUE(publisher_.publish(sent));
  receive(1);
  const auto message = decoded<cosmos_lcm::cell_status_t>(0, kStatusChannel);
  EXPECT_EQ(message.state, cosmos_lcm::cell_status_t::SCANNING);
  EXPECT_EQ(message.profiles_dropped, sent.profiles_dropped);
  EXPECT_EQ(message.runs_dropped, sent.runs_dropped);
  CellStatus received;
  from_message(message, received);
  testing::expect_same_status(sent, received);
}

TEST_F(LcmMemqRoundTrip, ProfileArrivesBitForBitWithItsNaNs) {
  const Profile sent = sample_profile(9);
  ASSERT_TRUE(publisher_.publish(sent));
  receive(1);
  const auto message = decoded<cosmos_lcm::range_profile_t>(0, kProfileChannel);
  ASSERT_EQ(message.width, 640);
  std::size_t nan_count = 0;
  for (const float z_mm : message.z_mm) nan_count += std::isnan(z_mm) ? 1 : 0;
  EXPECT_EQ(nan_count, 25U);  // 10 at each end + the 5-sample gap
  Profile received;
  ASSERT_TRUE(from_message(message, received));
  testing::expect_same_profile(sent, received);
}

// The cell's publishing code sees only Publisher: the in-memory stand-in and the LCM one
// must end with the same messages in the same order.
void publish_cell_output(Publisher& publisher) {
  EXPECT_TRUE(publisher.publish(sample_profile(0)));
  EXPECT_TRUE(publisher.publish(sample_pose(0)));
  EXPECT_TRUE(publisher.publish(sample_profile(1, 0)));  // an empty profile is still a profile
  EXPECT_TRUE(publisher.publish(sample_status("idle")));
  EXPECT_TRUE(publisher.publish(sample_pose(1)));
}

TEST_F(LcmMemqRoundTrip, SameMessagesAsTheMemoryPublisher) {
  MemoryPublisher memory;
  publish_cell_output(memory);
  publish_cell_output(publisher_);
  receive(5);
  ASSERT_EQ(memory.poses.size(), 2U);
  ASSERT_EQ(memory.profiles.size(), 2U);
  ASSERT_EQ(memory.statuses.size(), 1U);

  const char* expected_channels[] = {kProfileChannel, kPoseChannel, kProfileChannel, kStatusChannel,
                                     kPoseChannel};
  for (std::size_t i = 0; i < 5; ++i) EXPECT_EQ(arrivals_[i].channel, expected_channels[i]) << i;
  PartPose pose;
  Profile profile;
  CellStatus status;
  from_message(decoded<cosmos_lcm::part_pose_t>(1, kPoseChannel), pose);
  testing::expect_same_pose(memory.poses[0], pose);
  from_message(decoded<cosmos_lcm::part_pose_t>(4, kPoseChannel), pose);
  testing::expect_same_pose(memory.poses[1], pose);
  ASSERT_TRUE(from_message(decoded<cosmos_lcm::range_profile_t>(0, kProfileChannel), profile));
  testing::expect_same_profile(memory.profiles[0], profile);
  ASSERT_TRUE(from_message(decoded<cosmos_lcm::range_profile_t>(2, kProfileChannel), profile));
  testing::expect_same_profile(memory.profiles[1], profile);
  EXPECT_EQ(profile.width(), 0U);
  from_message(decoded<cosmos_lcm::cell_status_t>(3, kStatusChannel), status);
  testing::expect_same_status(memory.statuses[0], status);
}

struct ChannelRecorder {
  std::vector<std::string> channels;
  void on_message(const lcm::ReceiveBuffer*, const std::string& channel) {
    channels.push_back(channel);
  }
};

TEST(LcmChannels, ConfiguredNamesReplaceTheDefaults) {
  LcmPublisher publisher("memq://", {"CELL2_POSE", "CELL2_STATUS", "CELL2_PROFILE"});
  ChannelRecorder recorder;
  publisher.lcm().subscribe(".*", &ChannelRecorder::on_message, &recorder);  // every channel
  ASSERT_TRUE(publisher.publish(sample_pose(1)));
  ASSERT_TRUE(publisher.publish(sample_status("renamed")));
  ASSERT_TRUE(publisher.publish(sample_profile(3)));
  while (publisher.lcm().handleTimeout(0) > 0) {
  }
  EXPECT_EQ(recorder.channels,
            (std::vector<std::string>{"CELL2_POSE", "CELL2_STATUS", "CELL2_PROFILE"}));
}

}  // namespace
}  // namespace cosmos
