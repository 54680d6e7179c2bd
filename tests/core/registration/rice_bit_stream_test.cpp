// The bit streams of the compact registration points: Rice and Elias-gamma codes read back
// what was written (escapes included), their lengths are the stated ones, and reading past
// the end sees zero bits instead of memory outside the stream.
#include "core/registration/rice_bit_stream.hpp"

#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace cosmos {
namespace {

TEST(RiceBitStream, ZigzagMapsSmallMagnitudesToSmallCodes) {
  EXPECT_EQ(zigzag(0), 0u);
  EXPECT_EQ(zigzag(-1), 1u);
  EXPECT_EQ(zigzag(1), 2u);
  EXPECT_EQ(zigzag(-2), 3u);
  for (std::int64_t v : {std::int64_t{0}, std::int64_t{-7}, std::int64_t{123456},
                         -(std::int64_t{1} << 30), (std::int64_t{1} << 30)})
    EXPECT_EQ(unzigzag(zigzag(v)), v);
}

TEST(RiceBitStream, RiceCodesReadBackWithTheirStatedLengths) {
  std::mt19937 generator(11);
  std::normal_distribution<double> spread(0.0, 40.0);
  std::vector<std::int64_t> values;
  std::vector<int> ks;
  for (int i = 0; i < 2000; ++i) {
    values.push_back(static_cast<std::int64_t>(spread(generator)));
    ks.push_back(i % 7);
  }
  values.push_back(std::int64_t{1} << 29);  // escapes at any of these k
  ks.push_back(3);
  values.push_back(-(std::int64_t{1} << 29));
  ks.push_back(0);
  BitWriter writer;
  std::uint64_t stated_bits = 0;
  for (std::size_t i = 0; i < values.size(); ++i) {
    writer.put_rice(values[i], ks[i]);
    stated_bits += static_cast<std::uint64_t>(rice_code_bits(zigzag(values[i]), ks[i]));
  }
  const std::vector<std::uint8_t> bytes = writer.finish();
  EXPECT_EQ(bytes.size(), (stated_bits + 7) / 8);
  BitReader reader(bytes);
  for (std::size_t i = 0; i < values.size(); ++i) ASSERT_EQ(reader.get_rice(ks[i]), values[i]) << i;
  EXPECT_EQ(reader.position_bits(), stated_bits);
}

TEST(RiceBitStream, GammaCodesAndRawBitsReadBack) {
  BitWriter writer;
  const std::vector<std::uint32_t> runs = {1, 2, 3, 17, 1000, 65536, 1u << 31};
  for (std::uint32_t run : runs) writer.put_gamma(run);
  writer.put(0x5a5a5a5a, 32);
  writer.put(5, 3);
  const std::vector<std::uint8_t> bytes = writer.finish();
  BitReader reader(bytes);
  for (std::uint32_t run : runs) EXPECT_EQ(reader.get_gamma(), run);
  EXPECT_EQ(reader.get(32), 0x5a5a5a5au);
  EXPECT_EQ(reader.get(3), 5u);
}

TEST(RiceBitStream, ReadingPastTheEndSeesZeros) {
  const std::vector<std::uint8_t> bytes = {0xff, 0xff, 0xff};
  BitReader reader(bytes);
  EXPECT_EQ(reader.get(20), 0xfffffu);
  EXPECT_EQ(reader.get(8), 0xf0u);  // 4 bits of the stream, 4 past its end
  EXPECT_EQ(reader.get_rice(2), 0);
  EXPECT_EQ(reader.get_gamma(), 0u);  // 32 zeros and more: no gamma code
  BitReader nothing(std::span<const std::uint8_t>{});
  EXPECT_EQ(nothing.get_rice(5), 0);
  EXPECT_EQ(nothing.get(32), 0u);
}

}  // namespace
}  // namespace cosmos
