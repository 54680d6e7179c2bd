#pragma once
// The bit streams of the model base's compact registration points
// (packed_registration_points.hpp): signed integers in Golomb-Rice codes (a prediction
// residual r as zigzag(r) = q * 2^k + rest: q one-bits, a zero, k bits of rest) and run
// lengths in Elias-gamma codes, most significant bit first.
//
// Reading never fails and never reads outside its bytes: past the end it sees zero bits, so
// a stream cut short or crafted decodes to some values, which the caller bounds
// (packed_registration_points.cpp clamps every value into its view's checked range).
#include <bit>
#include <cstdint>
#include <cstring>
#include <span>
#include <vector>

namespace cosmos {

// A Rice quotient of this many one-bits is an escape: the zigzag value follows in 32 bits.
inline constexpr int kRiceEscapeQuotient = 24;
inline constexpr int kMaxRiceBits = 24;

inline std::uint32_t zigzag(std::int64_t value) {
  return static_cast<std::uint32_t>(value >= 0 ? 2 * value : -2 * value - 1);
}
inline std::int64_t unzigzag(std::uint32_t value) {
  return (value & 1u) ? -static_cast<std::int64_t>(value >> 1) - 1
                      : static_cast<std::int64_t>(value >> 1);
}

// Bits a Rice code with parameter k spends on a zigzagged value.
inline int rice_code_bits(std::uint32_t zigzagged, int k) {
  const std::uint32_t quotient = zigzagged >> k;
  return quotient < kRiceEscapeQuotient ? static_cast<int>(quotient) + 1 + k
                                        : kRiceEscapeQuotient + 32;
}

class BitWriter {
 public:
  void put(std::uint32_t value, int bits);  // the low `bits` (<= 32) bits of value
  void put_rice(std::int64_t value, int k);
  void put_gamma(std::uint32_t value);  // value >= 1
  // The bytes so far, the last one zero-padded.
  const std::vector<std::uint8_t>& finish();

 private:
  std::vector<std::uint8_t> bytes_;
  std::uint64_t buffer_ = 0;
  int buffered_ = 0;
};

class BitReader {
 public:
  BitReader() = default;
  explicit BitReader(std::span<const std::uint8_t> bytes) : bytes_(bytes) {}
  std::uint32_t get(int bits) {  // bits <= 32
    if (bits == 0) return 0;
    const std::uint64_t word = window();
    position_bits_ += static_cast<std::uint64_t>(bits);
    return static_cast<std::uint32_t>(word >> (64 - bits));
  }
  // Inlined: unpacking a view reads six codes per control point.
  std::int64_t get_rice(int k) {
    const std::uint64_t word = window();
    const int ones = std::countl_one(word);
    if (ones >= kRiceEscapeQuotient) {
      position_bits_ += kRiceEscapeQuotient;
      return unzigzag(get(32));
    }
    // The quotient, its terminating zero and k bits of rest lie within the 57-bit window.
    const int used = ones + 1 + k;
    if (used <= 57) {
      position_bits_ += static_cast<std::uint64_t>(used);
      const std::uint32_t rest =
          k == 0 ? 0u : static_cast<std::uint32_t>((word << (ones + 1)) >> (64 - k));
      return unzigzag((static_cast<std::uint32_t>(ones) << k) | rest);
    }
    position_bits_ += static_cast<std::uint64_t>(ones) + 1;
    return unzigzag((static_cast<std::uint32_t>(ones) << k) | get(k));
  }
  // A gamma code longer than 32 bits (only a crafted stream has one) reads as 0.
  std::uint32_t get_gamma();
  // Bits consumed, counting those read past the end.
  std::uint64_t position_bits() const { return position_bits_; }

 private:
  // 57 bits from the position on, in the top of a 64-bit word (zeros past the end).
  std::uint64_t window() const {
    const std::uint64_t first = position_bits_ / 8;
    std::uint64_t word = 0;
    if (first + 8 <= bytes_.size()) {
      std::memcpy(&word, bytes_.data() + first, 8);
      if constexpr (std::endian::native == std::endian::little) word = __builtin_bswap64(word);
    } else {
      for (std::uint64_t k = 0; k < 8; ++k)
        word = (word << 8) | (first + k < bytes_.size() ? bytes_[first + k] : 0u);
    }
    return word << (position_bits_ % 8);
  }

  std::span<const std::uint8_t> bytes_;
  std::uint64_t position_bits_ = 0;
};

}  // namespace cosmos
