#pragma once
// Drawing helpers shared by the render/*.cpp files: the bridge between BgrPicture and cv::Mat,
// text, tick placement and field painting. Only render sources include this (it needs OpenCV).
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <string>
#include <vector>

#include "core/render/bgr_picture.hpp"
#include "core/render/field_layout.hpp"

namespace cosmos::render {

inline constexpr BgrColor kBackground = rgb(255, 255, 255);
inline constexpr BgrColor kInk = rgb(20, 20, 20);
inline constexpr BgrColor kFaintInk = rgb(200, 200, 200);
inline constexpr int kFont = cv::FONT_HERSHEY_SIMPLEX;

inline cv::Scalar scalar(BgrColor color) {
  return {double(color.blue), double(color.green), double(color.red)};
}

cv::Mat blank_canvas(int width_px, int height_px);
BgrPicture to_picture(const cv::Mat& bgr);

// Text with its baseline starting at origin; the anchored variants centre or right-align it.
void draw_text(cv::Mat& canvas, const std::string& text, cv::Point origin, double font_scale,
               BgrColor color = kInk, int thickness = 1);
void draw_text_centred(cv::Mat& canvas, const std::string& text, cv::Point centre,
                       double font_scale, BgrColor color = kInk, int thickness = 1);
void draw_text_right(cv::Mat& canvas, const std::string& text, cv::Point right_baseline,
                     double font_scale, BgrColor color = kInk, int thickness = 1);
// Light text on a dark halo: readable on any patch colour.
void draw_haloed_text(cv::Mat& canvas, const std::string& text, cv::Point centre,
                      double font_scale);
cv::Size text_extent(const std::string& text, double font_scale, int thickness = 1);

// Round tick values (steps of 1, 2 or 5 times a power of ten) inside [lo, hi].
std::vector<double> nice_ticks(double lo, double hi, int target_count);
// Fixed-point text with as few decimals as the tick step needs.
std::string format_tick(double value, double step);
std::string format_fixed(double value, int decimals);

// Paints every image pixel of the layout as its block of picture pixels.
template <class ColorOf>
void paint_field(cv::Mat& canvas, const FieldLayout& layout, ColorOf color_of) {
  for (int row = 0; row < layout.height; ++row) {
    for (int column = 0; column < layout.width; ++column) {
      const BgrColor color = color_of(column, row);
      const cv::Vec3b pixel{color.blue, color.green, color.red};
      const int x0 = layout.origin_x_px + column * layout.scale_x;
      const int y0 = layout.origin_y_px + row * layout.scale_y;
      for (int y = y0; y < y0 + layout.scale_y; ++y) {
        auto* line = canvas.ptr<cv::Vec3b>(y);
        for (int x = x0; x < x0 + layout.scale_x; ++x) line[x] = pixel;
      }
    }
  }
}

// A picture for a field of zero size: says so instead of failing.
cv::Mat empty_field_canvas(const std::string& title);

}  // namespace cosmos::render
