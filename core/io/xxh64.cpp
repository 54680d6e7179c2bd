#include "core/io/xxh64.hpp"

#include <algorithm>
#include <bit>
#include <cstring>

namespace cosmos {
namespace {

static_assert(std::endian::native == std::endian::little, "XXH64 reads little-endian words");

constexpr std::uint64_t kPrime1 = 0x9E3779B185EBCA87ULL;
constexpr std::uint64_t kPrime2 = 0xC2B2AE3D27D4EB4FULL;
constexpr std::uint64_t kPrime3 = 0x165667B19E3779F9ULL;
constexpr std::uint64_t kPrime4 = 0x85EBCA77C2B2AE63ULL;
constexpr std::uint64_t kPrime5 = 0x27D4EB2F165667C5ULL;

std::uint64_t read64(const unsigned char* p) {
  std::uint64_t v;
  std::memcpy(&v, p, sizeof v);
  return v;
}

std::uint32_t read32(const unsigned char* p) {
  std::uint32_t v;
  std::memcpy(&v, p, sizeof v);
  return v;
}

std::uint64_t round(std::uint64_t lane, std::uint64_t input) {
  lane += input * kPrime2;
  return std::rotl(lane, 31) * kPrime1;
}

std::uint64_t merge_round(std::uint64_t hash, std::uint64_t lane) {
  hash ^= round(0, lane);
  return hash * kPrime1 + kPrime4;
}

// The tail (< 32 bytes) and the final avalanche, common to both forms.
std::uint64_t finish(std::uint64_t hash, const unsigned char* p, std::size_t remaining) {
  while (remaining >= 8) {
    hash ^= round(0, read64(p));
    hash = std::rotl(hash, 27) * kPrime1 + kPrime4;
    p += 8;
    remaining -= 8;
  }
  if (remaining >= 4) {
    hash ^= static_cast<std::uint64_t>(read32(p)) * kPrime1;
    hash = std::rotl(hash, 23) * kPrime2 + kPrime3;
    p += 4;
    remaining -= 4;
  }
  while (remaining > 0) {
    hash ^= (*p) * kPrime5;
    hash = std::rotl(hash, 11) * kPrime1;
    ++p;
    --remaining;
  }
  hash ^= hash >> 33;
  hash *= kPrime2;
  hash ^= hash >> 29;
  hash *= kPrime3;
  hash ^= hash >> 32;
  return hash;
}

std::uint64_t converge(const std::uint64_t lanes[4]) {
  std::uint64_t hash = std::rotl(lanes[0], 1) + std::rotl(lanes[1], 7) + std::rotl(lanes[2], 12) +
                       std::rotl(lanes[3], 18);
  for (int k = 0; k < 4; ++k) hash = merge_round(hash, lanes[k]);
  return hash;
}

void consume_stripes(std::uint64_t lanes[4], const unsigned char*& p, std::size_t& remaining) {
  while (remaining >= 32) {
    for (int k = 0; k < 4; ++k) lanes[k] = round(lanes[k], read64(p + 8 * k));
    p += 32;
    remaining -= 32;
  }
}

void init_lanes(std::uint64_t lanes[4], std::uint64_t seed) {
  lanes[0] = seed + kPrime1 + kPrime2;
  lanes[1] = seed + kPrime2;
  lanes[2] = seed;
  lanes[3] = seed - kPrime1;
}

}  // namespace

std::uint64_t xxh64(const void* data, std::size_t size_bytes, std::uint64_t seed) {
  const auto* p = static_cast<const unsigned char*>(data);
  std::size_t remaining = size_bytes;
  std::uint64_t hash;
  if (size_bytes >= 32) {
    std::uint64_t lanes[4];
    init_lanes(lanes, seed);
    consume_stripes(lanes, p, remaining);
    hash = converge(lanes);
  } else {
    hash = seed + kPrime5;
  }
  hash += size_bytes;
  return finish(hash, p, remaining);
}

Xxh64Stream::Xxh64Stream(std::uint64_t seed) : seed_(seed) { init_lanes(lanes_, seed); }

void Xxh64Stream::update(const void* data, std::size_t size_bytes) {
  const auto* p = static_cast<const unsigned char*>(data);
  std::size_t remaining = size_bytes;
  total_bytes_ += size_bytes;
  if (buffered_bytes_ > 0) {
    const std::size_t take = std::min(remaining, sizeof buffer_ - buffered_bytes_);
    std::memcpy(buffer_ + buffered_bytes_, p, take);
    buffered_bytes_ += take;
    p += take;
    remaining -= take;
    if (buffered_bytes_ < sizeof buffer_) return;
    const unsigned char* full = buffer_;
    std::size_t full_size = sizeof buffer_;
    consume_stripes(lanes_, full, full_size);
    buffered_bytes_ = 0;
  }
  consume_stripes(lanes_, p, remaining);
  std::memcpy(buffer_, p, remaining);
  buffered_bytes_ = remaining;
}

std::uint64_t Xxh64Stream::digest() const {
  std::uint64_t hash = total_bytes_ >= 32 ? converge(lanes_) : seed_ + kPrime5;
  hash += total_bytes_;
  return finish(hash, buffer_, buffered_bytes_);
}

}  // namespace cosmos
