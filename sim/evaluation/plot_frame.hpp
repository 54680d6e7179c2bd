#pragma once
// The small plotting kit of the report pictures (OpenCV drawing): a framed plot with round
// ticks, grid and axis titles, and the text helpers it needs. Colours are BGR.
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <string>
#include <vector>

namespace cosmos::plot {

inline const cv::Scalar kBlack(0, 0, 0), kWhite(255, 255, 255), kGridGray(225, 225, 225);
inline const cv::Scalar kPlotBlue(180, 100, 30), kCellDark(120, 50, 10);  // BGR
constexpr int kFont = cv::FONT_HERSHEY_SIMPLEX;
constexpr double kFontScale = 0.45;
constexpr int kPlotWidthPx = 640, kPlotHeightPx = 420, kCellPx = 40;

// snprintf of one number.
std::string format(const char* pattern, double value);
cv::Size text_size(const std::string& text);
// Text whose left end of the baseline is at `origin`; anti-aliased.
void put_text(cv::Mat& image, const std::string& text, cv::Point origin,
              const cv::Scalar& color = kBlack);
// Text reading bottom to top, centred horizontally on `center_x`, its start at `bottom_y`.
void put_vertical_text(cv::Mat& image, const std::string& text, int center_x, int bottom_y);
// Ticks at round steps (1, 2 or 5 times a power of ten) covering [low, high].
std::vector<double> nice_ticks(double low, double high, int target_count);
// The smallest of 1, 2 or 5 times a power of ten that is >= value (> 0).
double nice_ceiling(double value);

// A blank plot with a frame, grid lines, tick labels and axis titles; to_px maps data to pixels.
struct PlotFrame {
  cv::Mat image;
  cv::Rect area;
  double x_low, x_high, y_low, y_high;

  cv::Point to_px(double x, double y) const {
    return {
        area.x + static_cast<int>(std::lround((x - x_low) / (x_high - x_low) * area.width)),
        area.br().y - static_cast<int>(std::lround((y - y_low) / (y_high - y_low) * area.height))};
  }
};

PlotFrame draw_frame(const std::string& title, const std::string& x_title,
                     const std::string& y_title, double x_low, double x_high, double y_low,
                     double y_high);

}  // namespace cosmos::plot
