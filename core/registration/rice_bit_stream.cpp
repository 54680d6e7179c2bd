#include "core/registration/rice_bit_stream.hpp"

#include <algorithm>

namespace cosmos {
void BitWriter::put(std::uint32_t value, int bits) {
  if (bits == 0) return;
  const std::uint64_t masked = bits == 32 ? value : (value & ((std::uint32_t{1} << bits) - 1));
  buffer_ = (buffer_ << bits) | masked;
  buffered_ += bits;
  while (buffered_ >= 8) {
    buffered_ -= 8;
    bytes_.push_back(static_cast<std::uint8_t>(buffer_ >> buffered_));
  }
  buffer_ &= (std::uint64_t{1} << buffered_) - 1;
}

void BitWriter::put_rice(std::int64_t value, int k) {
  const std::uint32_t zigzagged = zigzag(value);
  const std::uint32_t quotient = zigzagged >> k;
  if (quotient >= kRiceEscapeQuotient) {
    put((std::uint32_t{1} << kRiceEscapeQuotient) - 1, kRiceEscapeQuotient);
    put(zigzagged, 32);
    return;
  }
  put(((std::uint32_t{1} << quotient) - 1) << 1, static_cast<int>(quotient) + 1);
  put(zigzagged, k);
}

void BitWriter::put_gamma(std::uint32_t value) {
  const int bits = std::bit_width(value);
  put(0, bits - 1);
  put(value, bits);
}

const std::vector<std::uint8_t>& BitWriter::finish() {
  if (buffered_ > 0) {
    bytes_.push_back(static_cast<std::uint8_t>(buffer_ << (8 - buffered_)));
    buffer_ = 0;
    buffered_ = 0;
  }
  return bytes_;
}

std::uint32_t BitReader::get_gamma() {
  int zeros = 0;
  for (;;) {
    const int run = std::min(std::countl_zero(window()), 56);
    zeros += run;
    position_bits_ += static_cast<std::uint64_t>(run);
    if (zeros >= 32) return 0;
    if (run < 56) break;
  }
  return get(zeros + 1);
}

}  // namespace cosmos
