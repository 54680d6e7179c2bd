// Image headers (core/io/image_header.hpp): the dimensions a TIFF or PFM declares, read
// without decoding, in every byte order and offset size; nothing for a header that does not
// state them.
#include "core/io/image_header.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <limits>
#include <string>

#include "tests/common/scratch_directory_test.hpp"
#include "tests/sim/handmade_image_files.hpp"

namespace cosmos {
namespace {

namespace fs = std::filesystem;

using ImageHeader = testing::ScratchDirectoryTest;

void expect_dimensions(const std::optional<ImageDimensions>& read, std::uint64_t width,
                       std::uint64_t height) {
  ASSERT_TRUE(read.has_value());
  EXPECT_EQ(read->width, width);
  EXPECT_EQ(read->height, height);
}

TEST_F(ImageHeader, BaselineTiffDimensionsAreRead) {
  testing::write_handmade_tiff(file("a.tiff"), 7, 5, 32, 1, testing::TiffSampleFormat::kFloat);
  expect_dimensions(read_tiff_dimensions(file("a.tiff")), 7, 5);
}

TEST_F(ImageHeader, EveryByteOrderAndOffsetSizeIsRead) {
  for (const bool big_endian : {false, true}) {
    for (const bool bigtiff : {false, true}) {
      const fs::path path = file("h.tiff");
      testing::write_tiff_header_only(path, 70000, 300, big_endian, bigtiff);
      SCOPED_TRACE(std::to_string(big_endian) + std::to_string(bigtiff));
      expect_dimensions(read_tiff_dimensions(path), 70000, 300);
    }
  }
}

TEST_F(ImageHeader, PfmDimensionsAreRead) {
  testing::write_handmade_pfm(file("a.pfm"), 9, 4, 1, 1.0f);
  expect_dimensions(read_pfm_dimensions(file("a.pfm")), 9, 4);
  testing::write_text_file(file("b.pfm"), "PF\n  32768\n32683 -1.0\n");
  expect_dimensions(read_pfm_dimensions(file("b.pfm")), 32768, 32683);
}

TEST_F(ImageHeader, HeadersWithoutDimensionsGiveNothing) {
  testing::write_text_file(file("short.tiff"), "II*");
  EXPECT_FALSE(read_tiff_dimensions(file("short.tiff")));
  // An IFD past the end of the file.
  testing::write_text_file(file("far.tiff"), std::string("II*\0\xff\xff\0\0", 8));
  EXPECT_FALSE(read_tiff_dimensions(file("far.tiff")));
  // An IFD claiming 65535 entries in a file that holds none.
  testing::write_text_file(file("many.tiff"), std::string("II*\0\x08\0\0\0\xff\xff", 10));
  EXPECT_FALSE(read_tiff_dimensions(file("many.tiff")));
  testing::write_text_file(file("text.pfm"), "Pf\nwide tall\n-1\n");
  EXPECT_FALSE(read_pfm_dimensions(file("text.pfm")));
  testing::write_text_file(file("p6.pfm"), "P6\n3 3\n255\n");
  EXPECT_FALSE(read_pfm_dimensions(file("p6.pfm")));
  EXPECT_FALSE(read_pfm_dimensions(file("absent.pfm")));
}

TEST_F(ImageHeader, PixelCountSaturates) {
  EXPECT_EQ((ImageDimensions{6, 7}.pixels()), 42u);
  const std::uint64_t huge = std::uint64_t{1} << 40;
  EXPECT_EQ((ImageDimensions{huge, huge}.pixels()), std::numeric_limits<std::uint64_t>::max());
}

}  // namespace
}  // namespace cosmos
