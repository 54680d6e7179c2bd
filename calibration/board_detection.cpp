#include "calibration/board_detection.hpp"

#include <cstdio>
#include <opencv2/calib3d.hpp>
#include <opencv2/core.hpp>

namespace cosmos {

BoardDetection detect_board(const cv::Mat& image, const CalibrationBoard& board,
                            const BoardDetectionSettings& settings) {
  BoardDetection detection;
  if (image.empty() || image.channels() != 1) {
    detection.reason = "not a single-channel grey image";
    return detection;
  }
  cv::Mat grey = image;
  if (image.depth() != CV_8U) {
    double max_value = 0.0;
    cv::minMaxLoc(image, nullptr, &max_value);
    image.convertTo(grey, CV_8U, max_value > 0 ? 255.0 / max_value : 1.0);
  }
  std::vector<cv::Point2f> corners;
  const int flags = cv::CALIB_CB_NORMALIZE_IMAGE | cv::CALIB_CB_ACCURACY;
  // The exhaustive search finds very oblique boards the quick one misses, at many times the
  // cost: only when the quick one failed.
  if (!cv::findChessboardCornersSB(grey, board.pattern_size(), corners, flags) &&
      !cv::findChessboardCornersSB(grey, board.pattern_size(), corners,
                                   flags | cv::CALIB_CB_EXHAUSTIVE)) {
    char reason[160];
    std::snprintf(reason, sizeof reason, "no %dx%d chessboard found", board.inner_columns,
                  board.inner_rows);
    detection.reason = reason;
    return detection;
  }
  const cv::Scalar sharpness = cv::estimateChessboardSharpness(grey, board.pattern_size(), corners);
  detection.edge_width_px = sharpness[0];
  if (detection.edge_width_px > settings.max_edge_width_px) {
    char reason[160];
    std::snprintf(reason, sizeof reason, "blurred: edges %.1f px wide (at most %.1f)",
                  detection.edge_width_px, settings.max_edge_width_px);
    detection.reason = reason;
    return detection;
  }
  detection.found = true;
  detection.corners = std::move(corners);
  return detection;
}

}  // namespace cosmos
