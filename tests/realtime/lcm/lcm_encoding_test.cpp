// Determinism at the wire: the same input gives the same bytes, decoding and encoding again
// gives them back unchanged, and bytes that are not the expected type are refused, not thrown.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <type_traits>
#include <vector>

#include "realtime/lcm/lcm_codec.hpp"
#include "realtime/lcm/lcm_message_conversion.hpp"
#include "tests/realtime/lcm_test_messages.hpp"

namespace cosmos {
namespace {

template <class Input, class Message>
std::vector<std::uint8_t> encoded(const Input& input, Message message) {
  to_message(input, message);
  std::vector<std::uint8_t> bytes;
  EXPECT_TRUE(encode_message(message, bytes));
  return bytes;
}

template <class Message>
std::vector<std::uint8_t> reencoded(const std::vector<std::uint8_t>& bytes) {
  Message message{};
  if constexpr (std::is_same_v<Message, cosmos_lcm::range_profile_t>) {
    EXPECT_TRUE(decode_message(bytes.data(), bytes.size(), kMaxProfileWidth, message));
  } else {
    EXPECT_TRUE(decode_message(bytes.data(), bytes.size(), message));
  }
  std::vector<std::uint8_t> again;
  EXPECT_TRUE(encode_message(message, again));
  return again;
}

TEST(LcmEncoding, PoseBytesDependOnlyOnTheInput) {
  const auto first = encoded(testing::sample_pose(4), cosmos_lcm::part_pose_t{});
  const auto second = encoded(testing::sample_pose(4), cosmos_lcm::part_pose_t{});
  // hash 8 + 3 int64 + name (4 + 7 + 1) + 2 int32 + int8 + reason (4 + 0 + 1) + 10 doubles
  // + the blob's first encoder count (int64) and extent (3 doubles)
  EXPECT_EQ(first.size(), 8U + 24U + 12U + 8U + 1U + 5U + 80U + 8U + 24U);
  EXPECT_EQ(first, second);
  EXPECT_EQ(reencoded<cosmos_lcm::part_pose_t>(first), first);
  EXPECT_NE(encoded(testing::sample_pose(5), cosmos_lcm::part_pose_t{}), first);
}

TEST(LcmEncoding, QuaternionSignDoesNotChangeTheBytes) {
  PartPose pose = testing::sample_pose(4);
  const auto negative_w = encoded(pose, cosmos_lcm::part_pose_t{});
  pose.rotation_cell_part.coeffs() = -pose.rotation_cell_part.coeffs();
  EXPECT_EQ(encoded(pose, cosmos_lcm::part_pose_t{}), negative_w);
}

TEST(LcmEncoding, StatusBytesDependOnlyOnTheInput) {
  const auto first = encoded(testing::sample_status("ok"), cosmos_lcm::cell_status_t{});
  const auto second = encoded(testing::sample_status("ok"), cosmos_lcm::cell_status_t{});
  // hash 8 + int64 + int8 + text (4 + 2 + 1) + 14 int64 + 3 doubles + 8 int64 + 2 int32
  EXPECT_EQ(first.size(), 8U + 8U + 1U + 7U + 112U + 24U + 64U + 8U);
  EXPECT_EQ(first, second);
  EXPECT_EQ(reencoded<cosmos_lcm::cell_status_t>(first), first);
}

TEST(LcmEncoding, ProfileBytesDependOnlyOnTheInputNaNsIncluded) {
  const auto first = encoded(testing::sample_profile(3), cosmos_lcm::range_profile_t{});
  const auto second = encoded(testing::sample_profile(3), cosmos_lcm::range_profile_t{});
  // hash 8 + 3 int64 + 2 doubles + int32 + 640 floats
  EXPECT_EQ(first.size(), 8U + 24U + 16U + 4U + 4U * 640U);
  EXPECT_EQ(first, second);
  EXPECT_EQ(reencoded<cosmos_lcm::range_profile_t>(first), first);
  // A reused message (the publisher keeps one) encodes a narrower profile exactly as a fresh one.
  cosmos_lcm::range_profile_t reused{};
  to_message(testing::sample_profile(3), reused);
  EXPECT_EQ(encoded(testing::sample_profile(4, 100), reused),
            encoded(testing::sample_profile(4, 100), cosmos_lcm::range_profile_t{}));
}

TEST(LcmEncoding, ForeignAndDamagedBytesAreRefused) {
  const auto pose_bytes = encoded(testing::sample_pose(1), cosmos_lcm::part_pose_t{});
  cosmos_lcm::range_profile_t profile{};
  EXPECT_FALSE(decode_message(pose_bytes.data(), pose_bytes.size(), kMaxProfileWidth,
                              profile));  // type hash differs

  cosmos_lcm::part_pose_t pose{};
  EXPECT_FALSE(decode_message(pose_bytes.data(), pose_bytes.size() - 1, pose));  // truncated

  // A corrupt width of -2 must not reach an allocation of 2^64 floats as an exception.
  auto profile_bytes = encoded(testing::sample_profile(1, 4), cosmos_lcm::range_profile_t{});
  const std::size_t width_offset = 8 + 24 + 16;
  const std::uint8_t minus_two[] = {0xFF, 0xFF, 0xFF, 0xFE};  // big-endian int32
  std::memcpy(profile_bytes.data() + width_offset, minus_two, sizeof minus_two);
  EXPECT_FALSE(
      decode_message(profile_bytes.data(), profile_bytes.size(), kMaxProfileWidth, profile));
}

void set_int32(std::vector<std::uint8_t>& bytes, std::size_t offset, std::uint32_t value) {
  for (int k = 0; k < 4; ++k)
    bytes[offset + static_cast<std::size_t>(k)] = static_cast<std::uint8_t>(value >> (24 - 8 * k));
}

// A string length of INT_MIN passed the generated decode's check and overflowed to INT_MAX:
// a 2 GB copy from past the datagram (found by fuzz/fuzz_lcm_message.cpp). Every string of
// both types, and lengths that are zero or longer than the message, are refused.
TEST(LcmEncoding, StringLengthsOutsideTheMessageAreRefusedBeforeDecoding) {
  const auto pose_bytes = encoded(testing::sample_pose(1), cosmos_lcm::part_pose_t{});
  const std::size_t name_offset = 8 + 3 * 8;
  cosmos_lcm::part_pose_t pose{};
  ASSERT_TRUE(decode_message(pose_bytes.data(), pose_bytes.size(), pose));
  const std::size_t reason_offset = name_offset + 4 + pose.part_name.size() + 1 + 4 + 4 + 1;
  for (const std::size_t offset : {name_offset, reason_offset})
    for (const std::uint32_t length : {0x80000000u, 0u, 0xFFFFFFFFu, 1000000u}) {
      auto damaged = pose_bytes;
      set_int32(damaged, offset, length);
      EXPECT_FALSE(decode_message(damaged.data(), damaged.size(), pose))
          << "offset " << offset << ", length " << length;
    }

  const auto status_bytes =
      encoded(testing::sample_status("scanning"), cosmos_lcm::cell_status_t{});
  cosmos_lcm::cell_status_t status{};
  ASSERT_TRUE(decode_message(status_bytes.data(), status_bytes.size(), status));
  for (const std::uint32_t length : {0x80000000u, 0u, 0x7FFFFFFFu}) {
    auto damaged = status_bytes;
    set_int32(damaged, 8 + 8 + 1, length);
    EXPECT_FALSE(decode_message(damaged.data(), damaged.size(), status)) << "length " << length;
  }
}

void set_width(std::vector<std::uint8_t>& bytes, std::uint32_t width) {
  const std::uint8_t big_endian[] = {
      static_cast<std::uint8_t>(width >> 24), static_cast<std::uint8_t>(width >> 16),
      static_cast<std::uint8_t>(width >> 8), static_cast<std::uint8_t>(width)};
  std::memcpy(bytes.data() + kRangeProfileWidthOffset, big_endian, sizeof big_endian);
}

TEST(LcmEncoding, AProfileWidthBeyondTheBoundOrTheBytesIsRefusedBeforeDecoding) {
  // 139 bytes as a hostile datagram: 4 * 2^29 wraps the generated decode's int size check,
  // which then read gigabytes past the message.
  auto bytes = encoded(testing::sample_profile(1, 22), cosmos_lcm::range_profile_t{});
  ASSERT_EQ(bytes.size(), 52U + 4U * 22U);
  bytes.resize(139);
  set_width(bytes, 1U << 29);
  cosmos_lcm::range_profile_t message{};
  EXPECT_EQ(encoded_profile_width(bytes.data(), bytes.size()), 1 << 29);
  EXPECT_FALSE(decode_message(bytes.data(), bytes.size(), kMaxProfileWidth, message));
  EXPECT_LT(message.z_mm.capacity(), 1000U);  // refused before the generated resize

  // A width the bytes hold but wider than the reader's profiles.
  auto wide = encoded(testing::sample_profile(1, 300), cosmos_lcm::range_profile_t{});
  EXPECT_FALSE(decode_message(wide.data(), wide.size(), 256, message));
  EXPECT_TRUE(decode_message(wide.data(), wide.size(), 300, message));
  EXPECT_EQ(message.width, 300);
  // Short by one sample.
  EXPECT_FALSE(decode_message(wide.data(), wide.size() - 4, 300, message));
  EXPECT_EQ(encoded_profile_width(wide.data(), kRangeProfileWidthOffset + 3), -1);
}

TEST(LcmEncoding, AProfileWithoutAUsableSpacingOrOriginDoesNotConvert) {
  cosmos_lcm::range_profile_t message{};
  to_message(testing::sample_profile(1, 8), message);
  Profile profile;
  ASSERT_TRUE(from_message(message, profile));
  for (const double dx_mm : {0.0, 1e-300, -0.5, 1e300, std::nan("")}) {
    message.dx_mm = dx_mm;
    profile.seq = 77;
    EXPECT_FALSE(from_message(message, profile)) << dx_mm;
    EXPECT_EQ(profile.seq, 77U);  // untouched
  }
  message.dx_mm = 0.5;
  message.x0_mm = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(from_message(message, profile));
}

}  // namespace
}  // namespace cosmos
