// BgrPicture: the project's 8-bit BGR picture, laid out exactly as an OpenCV CV_8UC3 image so
// render code and callers can share it without copying.
#include "core/render/bgr_picture.hpp"

#include <gtest/gtest.h>

#include <opencv2/core.hpp>

namespace cosmos {
namespace {

TEST(BgrPicture, RgbStoresItsChannelsBlueFirst) {
  constexpr BgrColor c = rgb(10, 20, 30);
  EXPECT_EQ(c.red, 10);
  EXPECT_EQ(c.green, 20);
  EXPECT_EQ(c.blue, 30);
  EXPECT_EQ(c, (BgrColor{30, 20, 10}));
  EXPECT_NE(c, rgb(10, 20, 31));
  EXPECT_EQ(BgrColor{}, rgb(0, 0, 0));
}

TEST(BgrPicture, ItsStorageIsACv8uc3ImageRowByRow) {
  BgrPicture picture(5, 3, rgb(1, 2, 3));
  picture(4, 2) = rgb(200, 100, 50);
  picture(0, 1) = rgb(7, 8, 9);
  const cv::Mat view(picture.height(), picture.width(), CV_8UC3, picture.data());
  EXPECT_EQ(view.step[0], 5u * 3u);  // rows packed, 3 bytes per pixel
  EXPECT_EQ(view.at<cv::Vec3b>(2, 4), cv::Vec3b(50, 100, 200));
  EXPECT_EQ(view.at<cv::Vec3b>(1, 0), cv::Vec3b(9, 8, 7));
  EXPECT_EQ(view.at<cv::Vec3b>(0, 3), cv::Vec3b(3, 2, 1));
  // Row r starts 3 * width * r bytes in.
  const auto* bytes = reinterpret_cast<const unsigned char*>(picture.data());
  EXPECT_EQ(bytes[3 * (5 * 1 + 0) + 0], 9);
  EXPECT_EQ(bytes[3 * (5 * 2 + 4) + 2], 200);
}

}  // namespace
}  // namespace cosmos
