#pragma once
// Images of the chessboard (calibration/calibration_board.hpp) as the TRUE camera of a
// simulated cell sees it (scanner/simulated_mounting.hpp): every pixel's ray, undistorted
// through the true lens, meets the board's plane and takes the print's level there; pixels
// near an edge of the print average 4 × 4 rays over their area (a box filter), so corners
// land where a real sensor's would to a fraction of a pixel. The sensor's read and shot noise of
// CameraFrameParameters are added, seeded per image. Off the board lies the grey belt.
#include <cstdint>
#include <opencv2/core/mat.hpp>
#include <opencv2/core/types.hpp>
#include <vector>

#include "calibration/calibration_board.hpp"
#include "core/rigid_transform.hpp"
#include "scanner/scanner_model.hpp"
#include "scanner/triangulation_geometry.hpp"

namespace cosmos {

class BoardImageRenderer {
 public:
  BoardImageRenderer(const TriangulationGeometry& true_geometry,
                     const CameraFrameParameters& levels);

  // A full-sensor 8-bit image of `board` at T_camera_board (board frame → true camera frame).
  cv::Mat render(const CalibrationBoard& board, const RigidTransform& T_camera_board,
                 std::uint64_t seed) const;

  // Grey levels of the print (fractions of full scale under the calibration lighting).
  static constexpr double kWhiteLevel = 0.75;
  static constexpr double kBlackLevel = 0.08;
  static constexpr double kBeltLevel = 0.3;

 private:
  TriangulationGeometry geometry_;
  CameraFrameParameters levels_;
  std::vector<cv::Point2f> normalized_;  // per pixel, row-major
};

// The printed checker's reflectance at board point (x, y) mm: white, black, or the white
// margin one square wide around the pattern; negative off the board.
double board_reflectance(const CalibrationBoard& board, double x_mm, double y_mm);

}  // namespace cosmos
