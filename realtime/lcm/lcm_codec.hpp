#pragma once
// Encoding and decoding of generated LCM message types into caller-owned buffers, so that
// publishing reuses one buffer (lcm::LCM::publish(channel, msg) would allocate per message)
// and decoding of untrusted bytes (network, log files) reports failure instead of throwing.
#include <cstddef>
#include <cstdint>
#include <exception>
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
template <class Message>
bool decode_message(const void* data, std::size_t size, Message& message) {
  try {
    return message.decode(data, 0, static_cast<int>(size)) >= 0;
  } catch (const std::exception&) {
    // A corrupt negative length reaches std::vector::resize inside the generated code.
    return false;
  }
}

}  // namespace cosmos
