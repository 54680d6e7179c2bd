// The drawing helpers the render sources share: the cv::Mat bridge, field painting, and the
// tick values and labels of the axes and colour bars.
#include "core/render/picture_drawing.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace cosmos::render {
namespace {

TEST(PictureDrawing, BlankCanvasIsWhiteAndConvertsPixelForPixel) {
  cv::Mat canvas = blank_canvas(7, 4);
  ASSERT_EQ(canvas.type(), CV_8UC3);
  EXPECT_EQ(canvas.cols, 7);
  EXPECT_EQ(canvas.rows, 4);
  canvas.at<cv::Vec3b>(3, 6) = cv::Vec3b(1, 2, 3);  // blue 1, green 2, red 3
  const BgrPicture picture = to_picture(canvas);
  ASSERT_EQ(picture.width(), 7);
  ASSERT_EQ(picture.height(), 4);
  EXPECT_EQ(picture(0, 0), kBackground);
  EXPECT_EQ(picture(6, 3), rgb(3, 2, 1));
  EXPECT_EQ(picture(5, 3), kBackground);
}

// Each image pixel becomes its scale_x by scale_y block, offset by the layout's origin.
TEST(PictureDrawing, PaintFieldFillsEachPixelsBlock) {
  FieldLayout layout;
  layout.width = 2;
  layout.height = 2;
  layout.scale_x = 3;
  layout.scale_y = 2;
  layout.origin_x_px = 1;
  layout.origin_y_px = 1;
  cv::Mat canvas = blank_canvas(8, 6);
  paint_field(canvas, layout, [](int column, int row) {
    return rgb(static_cast<std::uint8_t>(10 * column + 1), static_cast<std::uint8_t>(10 * row + 1),
               0);
  });
  const BgrPicture picture = to_picture(canvas);
  EXPECT_EQ(picture(0, 0), kBackground);
  EXPECT_EQ(picture(1, 1), rgb(1, 1, 0));
  EXPECT_EQ(picture(3, 2), rgb(1, 1, 0));   // last picture pixel of image pixel (0, 0)
  EXPECT_EQ(picture(4, 2), rgb(11, 1, 0));  // image pixel (1, 0) starts at x = 1 + 3
  EXPECT_EQ(picture(6, 4), rgb(11, 11, 0));
  EXPECT_EQ(picture(7, 4), kBackground);
  EXPECT_EQ(picture(6, 5), kBackground);
}

TEST(PictureDrawing, NiceTicksAreRoundStepsInsideTheRange) {
  // (10 - 0) / 5 = 2: steps of 2.
  EXPECT_EQ(nice_ticks(0, 10, 5), (std::vector<double>{0, 2, 4, 6, 8, 10}));
  // 36.4 / 5 = 7.3: the next of 1, 2, 5, 10 times 10^0 is 10.
  EXPECT_EQ(nice_ticks(0, 36.4, 5), (std::vector<double>{0, 10, 20, 30}));
  // 0.84 / 4 = 0.21: steps of 0.5, only 0.5 lies in [0.13, 0.97].
  EXPECT_EQ(nice_ticks(0.13, 0.97, 4), (std::vector<double>{0.5}));
  // Multiples of the step, not sums: 0.3 is 3 * 0.1 exactly as written.
  const std::vector<double> tenths = nice_ticks(0.0, 0.5, 5);
  ASSERT_EQ(tenths.size(), 6u);
  EXPECT_EQ(tenths[3], 3 * 0.1);
  EXPECT_EQ(nice_ticks(101, 111, 6), (std::vector<double>{102, 104, 106, 108, 110}));
  EXPECT_EQ(nice_ticks(4, 4, 5), (std::vector<double>{4}));
  EXPECT_TRUE(nice_ticks(5, 4, 5).empty());
  EXPECT_TRUE(nice_ticks(0, std::numeric_limits<double>::infinity(), 5).empty());
}

TEST(PictureDrawing, TickLabelsHaveTheDecimalsTheirStepNeeds) {
  EXPECT_EQ(format_tick(20, 10), "20");
  EXPECT_EQ(format_tick(0.5, 0.5), "0.5");
  EXPECT_EQ(format_tick(0.25, 0.05), "0.25");
  EXPECT_EQ(format_tick(0.3, 0.1), "0.3");
  EXPECT_EQ(format_fixed(3.14159, 2), "3.14");
  EXPECT_EQ(format_fixed(-0.0004, 2), "0.00");  // no "-0.00"
  EXPECT_EQ(format_fixed(std::nan(""), 2), "n/a");
}

TEST(PictureDrawing, TextIsDrawnWhereItIsAnchored) {
  const cv::Size size = text_extent("88", 0.5);
  EXPECT_GT(size.width, 10);
  EXPECT_GT(size.height, 5);
  EXPECT_GT(text_extent("8888", 0.5).width, size.width);
  // Right-aligned text ends at its anchor: ink left of x = 100, none right of it.
  cv::Mat canvas = blank_canvas(200, 60);
  draw_text_right(canvas, "88", {100, 40}, 0.5);
  const BgrPicture picture = to_picture(canvas);
  int ink_left = 0, ink_right = 0;
  for (int y = 0; y < 60; ++y)
    for (int x = 0; x < 200; ++x) {
      if (picture(x, y) == kBackground) continue;
      (x < 102 ? ink_left : ink_right) += 1;
    }
  EXPECT_GT(ink_left, 20);
  EXPECT_EQ(ink_right, 0);
  // The empty-field canvas says so, on the minimum field size.
  const cv::Mat empty = empty_field_canvas("range");
  EXPECT_EQ(empty.cols, kMinFieldSidePx);
  EXPECT_EQ(empty.rows, kMinFieldSidePx);
}

}  // namespace
}  // namespace cosmos::render
