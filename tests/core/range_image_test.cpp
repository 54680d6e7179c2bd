// RangeImage (core/range_image.hpp): the pixel-to-scanner-frame convention every tool shares,
// x = x0 + i dx, y = y0 + j dy, z = value, and NaN as "no data".
#include "core/range_image.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace cosmos {
namespace {

TEST(RangeImage, StartsWithNoDataAnywhere) {
  const RangeImage image(6, 4, 0.5, 0.25);
  EXPECT_EQ(image.width(), 6);
  EXPECT_EQ(image.height(), 4);
  EXPECT_EQ(image.pixel_size_x_mm, 0.5);
  EXPECT_EQ(image.pixel_size_y_mm, 0.25);
  EXPECT_EQ(image.count_valid(), 0u);
  for (float z : image.z_mm.values()) EXPECT_TRUE(std::isnan(z));
  EXPECT_FALSE(image.has_data(2, 2));
  EXPECT_FALSE(image.ground_truth.has_value());
}

TEST(RangeImage, PixelsMapToTheScannerFrame) {
  RangeImage image(6, 8, 0.5, 0.25);
  image.origin_x_mm = -3.0;
  image.origin_y_mm = 2.0;
  image.z_mm(4, 6) = 12.5f;
  EXPECT_DOUBLE_EQ(image.x_mm(0), -3.0);
  EXPECT_DOUBLE_EQ(image.x_mm(4), -1.0);
  EXPECT_DOUBLE_EQ(image.y_mm(6), 3.5);
  const Eigen::Vector3d p = image.point_mm(4, 6);
  EXPECT_DOUBLE_EQ(p.x(), -1.0);
  EXPECT_DOUBLE_EQ(p.y(), 3.5);
  EXPECT_DOUBLE_EQ(p.z(), 12.5);
}

TEST(RangeImage, OnlyFiniteDepthsInsideTheImageAreData) {
  RangeImage image(3, 2, 1.0, 1.0);
  image.z_mm(0, 0) = 1.0f;
  image.z_mm(1, 0) = -0.0f;
  image.z_mm(2, 1) = 40.0f;
  image.z_mm(0, 1) = std::numeric_limits<float>::infinity();
  EXPECT_TRUE(image.has_data(0, 0));
  EXPECT_TRUE(image.has_data(1, 0));
  EXPECT_TRUE(image.has_data(2, 1));
  EXPECT_FALSE(image.has_data(0, 1));  // infinite
  EXPECT_FALSE(image.has_data(2, 0));  // NaN
  EXPECT_FALSE(image.has_data(3, 0));  // outside
  EXPECT_FALSE(image.has_data(0, -1));
  EXPECT_EQ(image.count_valid(), 3u);
}

}  // namespace
}  // namespace cosmos
