// The five pictures `cosmos inspect` writes: the files exist, are deterministic, and decode
// to exactly the pictures the render functions return (PNG is lossless).
#include "core/render/view_pictures.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <array>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <opencv2/imgcodecs.hpp>
#include <string>
#include <vector>

#include "core/input_error.hpp"
#include "core/render/csmp_picture.hpp"
#include "core/render/gauss_map_picture.hpp"
#include "core/render/range_picture.hpp"
#include "core/render/shape_index_picture.hpp"
#include "core/render/spectrum_picture.hpp"
#include "tests/core/hand_made_view.hpp"

namespace cosmos::testing {
namespace {

namespace fs = std::filesystem;

// Width and height from a PNG's IHDR chunk (big-endian at bytes 16 and 20).
std::array<int, 2> png_size(const fs::path& path) {
  std::ifstream file(path, std::ios::binary);
  std::vector<unsigned char> head(24);
  file.read(reinterpret_cast<char*>(head.data()), 24);
  const auto be32 = [&](int at) {
    return int(head[at]) << 24 | int(head[at + 1]) << 16 | int(head[at + 2]) << 8 |
           int(head[at + 3]);
  };
  return {be32(16), be32(20)};
}

std::string file_bytes(const fs::path& path) {
  std::ifstream file(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(file), {}};
}

class ViewPictures : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = fs::temp_directory_path() / ("cosmos-view-pictures-" + std::to_string(::getpid()));
    fs::remove_all(root_);
  }
  void TearDown() override { fs::remove_all(root_); }
  fs::path root_;
};

TEST_F(ViewPictures, WritesFiveDeterministicPngs) {
  const ViewAnalysis analysis = hand_made_view_analysis();
  const RangeImage image = hand_made_range_image();
  const fs::path dir = root_ / "out";
  write_view_pictures(image, analysis, dir);
  const std::string first_range = file_bytes(dir / "range.png");
  write_view_pictures(image, analysis, dir);
  EXPECT_EQ(file_bytes(dir / "range.png"), first_range);

  const auto expect_size = [&](const char* name, const BgrPicture& picture) {
    ASSERT_TRUE(fs::exists(dir / name)) << name;
    EXPECT_EQ(png_size(dir / name), (std::array<int, 2>{picture.width(), picture.height()}))
        << name;
  };
  expect_size("range.png", render_range_picture(image));
  expect_size("shape_index.png",
              render_shape_index_picture(analysis.field, kHandPixelMm, kHandPixelMm));
  expect_size("csmps.png", render_csmp_picture(analysis.segmentation, kHandPixelMm, kHandPixelMm));
  expect_size("gauss_map.png", render_gauss_map_picture(analysis.view));
  expect_size("spectrum.png", render_spectrum_picture(analysis.spectrum, analysis.moments));
}

TEST_F(ViewPictures, FilesDecodeToTheRenderedPicturesPixelForPixel) {
  const ViewAnalysis analysis = hand_made_view_analysis();
  const RangeImage image = hand_made_range_image();
  write_view_pictures(image, analysis, root_);
  const auto expect_same = [&](const char* name, const BgrPicture& picture) {
    const cv::Mat decoded = cv::imread((root_ / name).string(), cv::IMREAD_COLOR);
    ASSERT_EQ(decoded.type(), CV_8UC3) << name;
    ASSERT_EQ(decoded.cols, picture.width()) << name;
    ASSERT_EQ(decoded.rows, picture.height()) << name;
    int different = 0;
    for (int row = 0; row < picture.height(); ++row)
      for (int column = 0; column < picture.width(); ++column) {
        const cv::Vec3b pixel = decoded.at<cv::Vec3b>(row, column);
        const BgrColor& expected = picture(column, row);
        different +=
            pixel[0] != expected.blue || pixel[1] != expected.green || pixel[2] != expected.red;
      }
    EXPECT_EQ(different, 0) << name;
  };
  expect_same("range.png", render_range_picture(image));
  expect_same("shape_index.png",
              render_shape_index_picture(analysis.field, kHandPixelMm, kHandPixelMm));
  expect_same("csmps.png", render_csmp_picture(analysis.segmentation, kHandPixelMm, kHandPixelMm));
  expect_same("gauss_map.png", render_gauss_map_picture(analysis.view));
  expect_same("spectrum.png", render_spectrum_picture(analysis.spectrum, analysis.moments));
}

TEST_F(ViewPictures, AnUnwritableDirectoryIsReportedWithItsPath) {
  fs::create_directories(root_);
  const fs::path file = root_ / "a-file";
  std::ofstream(file) << "not a directory";
  const fs::path dir = file / "pictures";
  try {
    write_view_pictures(hand_made_range_image(), hand_made_view_analysis(), dir);
    FAIL() << "no error for " << dir;
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find(dir.string()), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace cosmos::testing
