#pragma once
// XXH64 (Yann Collet's xxHash, 64-bit variant), written out here because only Debian's
// registry is reachable and the model-base file needs just this one function: a 64-bit
// checksum of the payload that runs near memory speed, so verifying a base of hundreds of
// megabytes costs a fraction of its load-time budget (bench/model_base_file_bench.cpp times
// the whole load). Same results as the reference implementation
// (XXH64("", 0) = 0xEF46DB3751D8E999).
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace cosmos {

std::uint64_t xxh64(const void* data, std::size_t size_bytes, std::uint64_t seed = 0);

inline std::uint64_t xxh64(std::string_view text, std::uint64_t seed = 0) {
  return xxh64(text.data(), text.size(), seed);
}

// Incremental form, for hashing several pieces (a catalog and its mesh files) as if they
// were one byte string.
class Xxh64Stream {
 public:
  explicit Xxh64Stream(std::uint64_t seed = 0);
  void update(const void* data, std::size_t size_bytes);
  void update(std::string_view text) { update(text.data(), text.size()); }
  std::uint64_t digest() const;

 private:
  std::uint64_t lanes_[4];
  std::uint64_t seed_;
  std::uint64_t total_bytes_ = 0;
  unsigned char buffer_[32];
  std::size_t buffered_bytes_ = 0;
};

}  // namespace cosmos
