#include "calibration/calibration_report.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "core/input_error.hpp"

namespace cosmos {
namespace {

constexpr int kMaxWidthPx = 640;

double scale_of(const cv::Mat& image) {
  return std::min(1.0, static_cast<double>(kMaxWidthPx) / std::max(1, image.cols));
}

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", value);
  return text;
}

}  // namespace

cv::Mat report_picture(const cv::Mat& image) {
  cv::Mat grey = image;
  if (image.depth() != CV_8U) {
    double max_value = 0.0;
    cv::minMaxLoc(image, nullptr, &max_value);
    image.convertTo(grey, CV_8U, max_value > 0 ? 255.0 / max_value : 1.0);
  }
  cv::Mat small;
  cv::resize(grey, small, cv::Size(), scale_of(image), scale_of(image), cv::INTER_AREA);
  cv::Mat colour;
  cv::cvtColor(small, colour, cv::COLOR_GRAY2BGR);
  return colour;
}

cv::Mat corners_picture(const cv::Mat& image, const std::vector<cv::Point2f>& corners,
                        cv::Size pattern) {
  cv::Mat picture = report_picture(image);
  std::vector<cv::Point2f> scaled = corners;
  for (cv::Point2f& c : scaled) c *= static_cast<float>(scale_of(image));
  cv::drawChessboardCorners(picture, pattern, scaled, !corners.empty());
  return picture;
}

cv::Mat points_picture(const cv::Mat& image, const std::vector<cv::Point2f>& points) {
  cv::Mat picture = report_picture(image);
  const double scale = scale_of(image);
  for (const cv::Point2f& p : points)
    cv::circle(picture,
               cv::Point2f(p.x * static_cast<float>(scale), p.y * static_cast<float>(scale)), 1,
               cv::Scalar(0, 200, 255), cv::FILLED);
  return picture;
}

cv::Mat plot_picture(const std::string& title, const std::string& x_label,
                     const std::string& y_label, const std::vector<PlotSeries>& series) {
  const int width = 560;
  const int height = 320;
  const int left = 70, right = 20, top = 30, bottom = 45;
  cv::Mat plot(height, width, CV_8UC3, cv::Scalar(255, 255, 255));
  Eigen::Vector2d low(1e300, 1e300);
  Eigen::Vector2d high(-1e300, -1e300);
  for (const PlotSeries& s : series)
    for (const Eigen::Vector2d& p : s.points) {
      low = low.cwiseMin(p);
      high = high.cwiseMax(p);
    }
  if (!(high.x() > low.x())) high.x() = low.x() + 1.0;
  if (!(high.y() > low.y())) high.y() = low.y() + 1.0;
  const auto to_pixel = [&](const Eigen::Vector2d& p) {
    return cv::Point(
        left + static_cast<int>((p.x() - low.x()) / (high.x() - low.x()) * (width - left - right)),
        height - bottom -
            static_cast<int>((p.y() - low.y()) / (high.y() - low.y()) * (height - top - bottom)));
  };
  cv::rectangle(plot, cv::Point(left, top), cv::Point(width - right, height - bottom),
                cv::Scalar(120, 120, 120));
  for (const PlotSeries& s : series) {
    for (std::size_t i = 0; i < s.points.size(); ++i) {
      if (s.line && i > 0)
        cv::line(plot, to_pixel(s.points[i - 1]), to_pixel(s.points[i]), s.colour, 1, cv::LINE_AA);
      else if (!s.line)
        cv::circle(plot, to_pixel(s.points[i]), 2, s.colour, cv::FILLED, cv::LINE_AA);
    }
  }
  const cv::Scalar ink(30, 30, 30);
  const int font = cv::FONT_HERSHEY_SIMPLEX;
  cv::putText(plot, title, cv::Point(left, 20), font, 0.5, ink, 1, cv::LINE_AA);
  cv::putText(plot, x_label, cv::Point(width / 2 - 40, height - 10), font, 0.45, ink, 1,
              cv::LINE_AA);
  cv::putText(plot, number(low.x()), cv::Point(left, height - bottom + 15), font, 0.4, ink);
  cv::putText(plot, number(high.x()), cv::Point(width - right - 50, height - bottom + 15), font,
              0.4, ink);
  cv::putText(plot, number(high.y()), cv::Point(2, top + 10), font, 0.4, ink);
  cv::putText(plot, number(low.y()), cv::Point(2, height - bottom), font, 0.4, ink);
  cv::putText(plot, y_label, cv::Point(2, height / 2), font, 0.4, ink);
  return plot;
}

cv::Mat bars_picture(const std::string& title, const std::string& y_label,
                     const std::vector<double>& values) {
  std::vector<Eigen::Vector2d> tops;
  PlotSeries bars{{}, cv::Scalar(200, 120, 40), true};
  for (std::size_t i = 0; i < values.size(); ++i) {
    const double x = static_cast<double>(i + 1);
    bars.points.insert(
        bars.points.end(),
        {{x - 0.3, 0.0}, {x - 0.3, values[i]}, {x + 0.3, values[i]}, {x + 0.3, 0.0}});
  }
  return plot_picture(title, "view / feature", y_label, {bars});
}

void CalibrationReport::write() const {
  std::error_code error;
  std::filesystem::create_directories(directory_, error);
  if (error) throw InputError(directory_.string() + ": cannot create (" + error.message() + ")");
  std::ofstream out(directory_ / "report.txt");
  out << text_;
  if (!out) throw InputError((directory_ / "report.txt").string() + ": cannot write");
  for (const auto& [name, image] : pictures_) {
    const std::filesystem::path file = directory_ / (name + ".png");
    if (!cv::imwrite(file.string(), image, {cv::IMWRITE_PNG_COMPRESSION, 9}))
      throw InputError(file.string() + ": cannot write");
  }
}

}  // namespace cosmos
