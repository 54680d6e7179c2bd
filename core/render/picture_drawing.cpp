#include "core/render/picture_drawing.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <opencv2/imgproc.hpp>
#include <sstream>

namespace cosmos::render {

cv::Mat blank_canvas(int width_px, int height_px) {
  return cv::Mat(height_px, width_px, CV_8UC3, scalar(kBackground));
}

BgrPicture to_picture(const cv::Mat& bgr) {
  BgrPicture picture(bgr.cols, bgr.rows);
  for (int row = 0; row < bgr.rows; ++row) {
    std::memcpy(static_cast<void*>(picture.row(row)), bgr.ptr<cv::Vec3b>(row),
                sizeof(BgrColor) * bgr.cols);
  }
  return picture;
}

cv::Size text_extent(const std::string& text, double font_scale, int thickness) {
  int baseline = 0;
  return cv::getTextSize(text, kFont, font_scale, thickness, &baseline);
}

void draw_text(cv::Mat& canvas, const std::string& text, cv::Point origin, double font_scale,
               BgrColor color, int thickness) {
  cv::putText(canvas, text, origin, kFont, font_scale, scalar(color), thickness, cv::LINE_AA);
}

void draw_text_centred(cv::Mat& canvas, const std::string& text, cv::Point centre,
                       double font_scale, BgrColor color, int thickness) {
  const cv::Size size = text_extent(text, font_scale, thickness);
  draw_text(canvas, text, {centre.x - size.width / 2, centre.y + size.height / 2}, font_scale,
            color, thickness);
}

void draw_text_right(cv::Mat& canvas, const std::string& text, cv::Point right_baseline,
                     double font_scale, BgrColor color, int thickness) {
  const cv::Size size = text_extent(text, font_scale, thickness);
  draw_text(canvas, text, {right_baseline.x - size.width, right_baseline.y}, font_scale, color,
            thickness);
}

void draw_haloed_text(cv::Mat& canvas, const std::string& text, cv::Point centre,
                      double font_scale) {
  draw_text_centred(canvas, text, centre, font_scale, rgb(0, 0, 0), 5);
  draw_text_centred(canvas, text, centre, font_scale, rgb(255, 255, 255), 2);
}

std::vector<double> nice_ticks(double lo, double hi, int target_count) {
  if (!std::isfinite(lo) || !std::isfinite(hi) || hi < lo) return {};
  if (hi == lo) return {lo};
  const double raw_step = (hi - lo) / std::max(target_count, 1);
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw_step)));
  double step = magnitude;
  for (double factor : {1.0, 2.0, 5.0, 10.0}) {
    step = factor * magnitude;
    if (step >= raw_step) break;
  }
  std::vector<double> ticks;
  // Integer multiples of the step keep the values exact-looking (no 0.30000000004).
  for (double k = std::ceil(lo / step - 1e-9); k * step <= hi + step * 1e-9; k += 1.0) {
    ticks.push_back(k * step);
  }
  return ticks;
}

std::string format_fixed(double value, int decimals) {
  if (!std::isfinite(value)) return "n/a";
  std::ostringstream text;
  text.setf(std::ios::fixed);
  text.precision(std::max(decimals, 0));
  text << (std::abs(value) < 0.5 * std::pow(10.0, -decimals) ? 0.0 : value);
  return text.str();
}

std::string format_tick(double value, double step) {
  const int decimals = step >= 1 ? 0 : static_cast<int>(std::ceil(-std::log10(step) - 1e-9));
  return format_fixed(value, decimals);
}

cv::Mat empty_field_canvas(const std::string& title) {
  cv::Mat canvas = blank_canvas(kMinFieldSidePx, kMinFieldSidePx);
  draw_text(canvas, title, {16, 32}, 0.6);
  draw_text_centred(canvas, "empty image", {kMinFieldSidePx / 2, kMinFieldSidePx / 2}, 0.7);
  return canvas;
}

}  // namespace cosmos::render
