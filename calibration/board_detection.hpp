#pragma once
// The chessboard's inner corners in one image: OpenCV's sector-based detector
// (findChessboardCornersSB, sub-pixel by itself and robust to noise and blur), with the
// board's sharpness (estimateChessboardSharpness: the edge width in pixels) so that a
// blurred view can be refused rather than weaken the calibration.
#include <opencv2/core/mat.hpp>
#include <string>
#include <vector>

#include "calibration/calibration_board.hpp"

namespace cosmos {

struct BoardDetection {
  bool found = false;
  std::vector<cv::Point2f> corners;  // row-major, CalibrationBoard::object_points() order
  double edge_width_px = 0.0;        // mean 10-90 % edge rise; sharp prints ≈ 2
  std::string reason;                // why not found or refused
};

struct BoardDetectionSettings {
  // A view whose edges rise over more pixels is blurred (out of focus or moving).
  double max_edge_width_px = 5.0;
};

// `image`: 8-bit grey, or 16-bit (scaled to 8 bits first).
BoardDetection detect_board(const cv::Mat& image, const CalibrationBoard& board,
                            const BoardDetectionSettings& settings = {});

}  // namespace cosmos
