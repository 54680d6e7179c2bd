#pragma once
// What `cosmos calibrate` leaves beside the YAML it writes: report.txt (the measured values
// and every residual) and small PNG pictures (detected corners, stripe points, residual
// plots), all in one report directory. Pictures are drawn at most 640 px wide so that a
// report stays small enough to mail or to keep with the cell's records.
#include <Eigen/Core>
#include <filesystem>
#include <opencv2/core/mat.hpp>
#include <string>
#include <vector>

namespace cosmos {

// `image` (any grey depth) scaled to at most 640 px wide, as 8-bit colour.
cv::Mat report_picture(const cv::Mat& image);
cv::Mat corners_picture(const cv::Mat& image, const std::vector<cv::Point2f>& corners,
                        cv::Size pattern);
cv::Mat points_picture(const cv::Mat& image, const std::vector<cv::Point2f>& points);

struct PlotSeries {
  std::vector<Eigen::Vector2d> points;
  cv::Scalar colour{40, 40, 200};
  bool line = false;  // joined, not dots
};
// A plot with axes, their ranges written at the ends, the title above.
cv::Mat plot_picture(const std::string& title, const std::string& x_label,
                     const std::string& y_label, const std::vector<PlotSeries>& series);
// One bar per value (a residual per view or feature).
cv::Mat bars_picture(const std::string& title, const std::string& y_label,
                     const std::vector<double>& values);

class CalibrationReport {
 public:
  explicit CalibrationReport(std::filesystem::path directory) : directory_(std::move(directory)) {}

  void line(const std::string& text) { text_.append(text).append("\n"); }
  void picture(const std::string& name, const cv::Mat& image) {
    pictures_.emplace_back(name, image);
  }
  const std::string& text() const { return text_; }
  // Writes report.txt and the pictures; InputError naming the directory when it cannot.
  void write() const;

 private:
  std::filesystem::path directory_;
  std::string text_;
  std::vector<std::pair<std::string, cv::Mat>> pictures_;
};

}  // namespace cosmos
