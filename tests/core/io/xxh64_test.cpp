// XXH64 (core/io/xxh64.hpp), the model-base file's payload checksum: the reference
// implementation's published values, and the incremental form agreeing with the one-shot one.
#include "core/io/xxh64.hpp"

#include <gtest/gtest.h>

#include <string>
#include <string_view>

namespace cosmos {
namespace {

TEST(Xxh64, MatchesTheReferenceVectors) {
  EXPECT_EQ(xxh64(""), 0xEF46DB3751D8E999ULL);
  EXPECT_EQ(xxh64("abc"), 0x44BC2CF5AD770999ULL);
  std::string text(1000, '\0');
  for (std::size_t k = 0; k < text.size(); ++k) text[k] = static_cast<char>(k * 7 + 3);
  for (std::size_t split : {0u, 5u, 32u, 33u, 999u}) {
    Xxh64Stream stream;
    stream.update(std::string_view(text).substr(0, split));
    stream.update(std::string_view(text).substr(split));
    EXPECT_EQ(stream.digest(), xxh64(text)) << split;
  }
}

}  // namespace
}  // namespace cosmos
