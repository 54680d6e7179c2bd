#pragma once
// Encoding and decoding of generated LCM message types into caller-owned buffers, so that
// publishing reuses one buffer (lcm::LCM::publish(channel, msg) would allocate per message)
// and decoding of untrusted bytes (network, log files) reports failure instead of throwing.
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
