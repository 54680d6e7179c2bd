// Base64 as the browser's atob() reads it: RFC 4648's test vectors, padding included.
#include "realtime/web/base64.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace cosmos {
namespace {

std::string encode(const std::string& text) {
  const std::vector<std::uint8_t> bytes(text.begin(), text.end());
  return base64_encode(bytes);
}

TEST(Base64, EncodesTheRfc4648Vectors) {
  EXPECT_EQ(encode(""), "");
  EXPECT_EQ(encode("f"), "Zg==");
  EXPECT_EQ(encode("fo"), "Zm8=");
  EXPECT_EQ(encode("foo"), "Zm9v");
  EXPECT_EQ(encode("foob"), "Zm9vYg==");
  EXPECT_EQ(encode("fooba"), "Zm9vYmE=");
  EXPECT_EQ(encode("foobar"), "Zm9vYmFy");
}

TEST(Base64, EncodesHighBytes) {
  const std::vector<std::uint8_t> bytes = {0xff, 0xfe, 0x00, 0x80};
  EXPECT_EQ(base64_encode(bytes), "//4AgA==");
}

}  // namespace
}  // namespace cosmos
