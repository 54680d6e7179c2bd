#pragma once
// Encoding and decoding of generated LCM message types into caller-owned buffers, so that
// publishing reuses one buffer (lcm::LCM::publish(channel, msg) would allocate per message)
// and decoding of untrusted bytes (network, log files) reports failure instead of throwing.
#include <cosmos_lcm/cell_status_t.hpp>
#include <cosmos_lcm/part_pose_t.hpp>
#include <cosmos_lcm/range_profile_t.hpp>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <type_traits>
#include <vector>

namespace cosmos {

// Overwrites `bytes` with the encoding of `message` (hash + fields, as on the wire). The
// vector only grows, so a reused one stops allocating. False if the message cannot be encoded
// (an array length field that disagrees with its array).
template <class Message>
bool encode_message(const Message& message, std::vector<std::uint8_t>& bytes) {
  const int size = message.getEncodedSize();
  if (size < 0) return false;
  bytes.resize(static_cast<std::size_t>(size));
  return message.encode(bytes.data(), 0, size) == size;
}

// Decodes `size` bytes into `message`. False when the type hash differs (another message
// type on the channel), the bytes are short or a length field is absurd.
namespace detail {
template <class Message>
bool decode_generated(const void* data, std::size_t size, Message& message) {
  try {
    return message.decode(data, 0, static_cast<int>(size)) >= 0;
  } catch (const std::exception&) {
    // A corrupt negative length reaches std::vector::resize inside the generated code.
    return false;
  }
}
}  // namespace detail

// A range_profile_t decodes only through the bounded overload below.
template <class Message>
bool decode_message(const void* data, std::size_t size, Message& message) {
  static_assert(!std::is_same_v<Message, cosmos_lcm::range_profile_t>,
                "decode a range_profile_t with its maximum width");
  return detail::decode_generated(data, size, message);
}

// The generated decode of a string reads its length L (the bytes plus a '\0'), checks only
// L <= the bytes left, then copies L - 1 bytes: L = INT_MIN overflows to INT_MAX and copies
// 2 GB from past the message (other L <= 0 make std::string throw, which is caught). The
// strings of part_pose_t and cell_status_t are checked here first, at the offsets their
// types give them (realtime/lcm/types/*.lcm; fields added after the last string move none).
namespace detail {
inline std::int64_t encoded_int32(const std::uint8_t* bytes) {
  const std::uint32_t bits = (std::uint32_t{bytes[0]} << 24) | (std::uint32_t{bytes[1]} << 16) |
                             (std::uint32_t{bytes[2]} << 8) | std::uint32_t{bytes[3]};
  return static_cast<std::int32_t>(bits);
}
// The string whose length is at `offset`: true when its length is in [1, bytes left]; `offset`
// then moves past it. False when the bytes end first (decode refuses those itself).
inline bool valid_encoded_string(const void* data, std::size_t size, std::size_t& offset) {
  if (size < offset + 4) return true;
  const std::int64_t length = encoded_int32(static_cast<const std::uint8_t*>(data) + offset);
  if (length < 1 || static_cast<std::uint64_t>(length) > size - offset - 4) return false;
  offset += 4 + static_cast<std::size_t>(length);
  return true;
}
}  // namespace detail

// part_pose_t: hash, utime, part_seq, encoder_ticks, part_name, part_index, view_index,
// status, reason, ...
inline bool decode_message(const void* data, std::size_t size, cosmos_lcm::part_pose_t& message) {
  std::size_t offset = 8 + 3 * 8;
  if (!detail::valid_encoded_string(data, size, offset)) return false;
  offset += 4 + 4 + 1;
  if (!detail::valid_encoded_string(data, size, offset)) return false;
  return detail::decode_generated(data, size, message);
}

// cell_status_t: hash, utime, state, state_text, ...
inline bool decode_message(const void* data, std::size_t size, cosmos_lcm::cell_status_t& message) {
  std::size_t offset = 8 + 8 + 1;
  if (!detail::valid_encoded_string(data, size, offset)) return false;
  return detail::decode_generated(data, size, message);
}

// range_profile_t's width field: after the type hash and five 8-byte fields (seq,
// encoder_ticks, t_us, x0_mm, dx_mm), big-endian like every LCM integer.
inline constexpr std::size_t kRangeProfileWidthOffset = 8 + 5 * 8;

// The width a range_profile_t's bytes claim, or -1 when they are too short to hold it.
inline std::int64_t encoded_profile_width(const void* data, std::size_t size) {
  if (size < kRangeProfileWidthOffset + 4) return -1;
  const auto* bytes = static_cast<const std::uint8_t*>(data) + kRangeProfileWidthOffset;
  const std::uint32_t bits = (std::uint32_t{bytes[0]} << 24) | (std::uint32_t{bytes[1]} << 16) |
                             (std::uint32_t{bytes[2]} << 8) | std::uint32_t{bytes[3]};
  return static_cast<std::int32_t>(bits);
}

// The generated decode computes 4 * width in int (a width >= 2^29 wraps negative and passes
// its length check, then reads past the message) and resizes z_mm to width before checking
// the bytes: the width is checked here first, against the widest profile the reader accepts
// and against the bytes there are.
inline bool decode_message(const void* data, std::size_t size, std::size_t max_width,
                           cosmos_lcm::range_profile_t& message) {
  const std::int64_t width = encoded_profile_width(data, size);
  if (width < 0 || static_cast<std::uint64_t>(width) > max_width ||
      size < kRangeProfileWidthOffset + 4 + 4 * static_cast<std::uint64_t>(width))
    return false;
  // decode() keeps the old array when width is 0: an emptied one keeps its capacity.
  message.z_mm.clear();
  return detail::decode_generated(data, size, message);
}

}  // namespace cosmos
