#include "sim/evaluation/plot_frame.hpp"

#include <cmath>
#include <cstdio>
#include <opencv2/imgproc.hpp>

namespace cosmos::plot {

std::string format(const char* pattern, double value) {
  char text[64];
  std::snprintf(text, sizeof text, pattern, value);
  return text;
}

cv::Size text_size(const std::string& text) {
  int baseline = 0;
  return cv::getTextSize(text, kFont, kFontScale, 1, &baseline);
}

// Text whose left end of the baseline is at `origin`; anti-aliased.
void put_text(cv::Mat& image, const std::string& text, cv::Point origin, const cv::Scalar& color) {
  cv::putText(image, text, origin, kFont, kFontScale, color, 1, cv::LINE_AA);
}

// Text reading bottom to top, centred horizontally on `center_x`, its start at `bottom_y`.
void put_vertical_text(cv::Mat& image, const std::string& text, int center_x, int bottom_y) {
  const cv::Size size = text_size(text);
  cv::Mat strip(size.height + 6, size.width + 2, image.type(), kWhite);
  put_text(strip, text, {1, size.height + 2});
  cv::rotate(strip, strip, cv::ROTATE_90_COUNTERCLOCKWISE);
  const cv::Rect target(center_x - strip.cols / 2, bottom_y - strip.rows, strip.cols, strip.rows);
  const cv::Rect clipped = target & cv::Rect(0, 0, image.cols, image.rows);
  strip(cv::Rect(clipped.tl() - target.tl(), clipped.size())).copyTo(image(clipped));
}

// Ticks at round steps (1, 2 or 5 times a power of ten) covering [low, high].
std::vector<double> nice_ticks(double low, double high, int target_count) {
  const double raw_step = (high - low) / target_count;
  const double magnitude = std::pow(10, std::floor(std::log10(raw_step)));
  const double ratio = raw_step / magnitude;
  const double step = (ratio <= 1 ? 1 : ratio <= 2 ? 2 : ratio <= 5 ? 5 : 10) * magnitude;
  std::vector<double> ticks;
  for (double tick = std::ceil(low / step - 1e-9) * step; tick <= high + 1e-9 * step; tick += step)
    ticks.push_back(std::abs(tick) < 1e-12 * step ? 0 : tick);
  return ticks;
}

// The smallest of 1, 2 or 5 times a power of ten that is >= value (> 0).
double nice_ceiling(double value) {
  const double magnitude = std::pow(10, std::floor(std::log10(value)));
  for (double factor : {1.0, 2.0, 5.0})
    if (factor * magnitude >= value * (1 - 1e-12)) return factor * magnitude;
  return 10 * magnitude;
}

PlotFrame draw_frame(const std::string& title, const std::string& x_title,
                     const std::string& y_title, double x_low, double x_high, double y_low,
                     double y_high) {
  PlotFrame frame{cv::Mat(kPlotHeightPx, kPlotWidthPx, CV_8UC3, kWhite),
                  cv::Rect(75, 40, kPlotWidthPx - 100, kPlotHeightPx - 100),
                  x_low,
                  x_high,
                  y_low,
                  y_high};
  cv::Mat& image = frame.image;
  for (double x : nice_ticks(x_low, x_high, 10)) {
    const cv::Point bottom = frame.to_px(x, y_low), top = frame.to_px(x, y_high);
    cv::line(image, bottom, top, kGridGray);
    const std::string label = format("%g", x);
    put_text(image, label, {bottom.x - text_size(label).width / 2, bottom.y + 18});
  }
  for (double y : nice_ticks(y_low, y_high, 5)) {
    const cv::Point left = frame.to_px(x_low, y), right = frame.to_px(x_high, y);
    cv::line(image, left, right, kGridGray);
    const std::string label = format("%g", y);
    put_text(image, label, {left.x - text_size(label).width - 6, left.y + 5});
  }
  cv::rectangle(image, frame.area, kBlack);
  put_text(image, title, {frame.area.x, 25});
  put_text(image, x_title,
           {frame.area.x + (frame.area.width - text_size(x_title).width) / 2, kPlotHeightPx - 18});
  put_vertical_text(image, y_title, 20,
                    frame.area.y + (frame.area.height + text_size(y_title).width) / 2);
  return frame;
}

}  // namespace cosmos::plot
