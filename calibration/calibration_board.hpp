#pragma once
// The chessboard target: inner_columns × inner_rows inner corners square_mm apart, corner
// (i, j) at (i · square_mm, j · square_mm, 0) of the board frame (x along the columns, y along
// the rows, z out of the board's back so that the frame is right-handed with the printed
// side facing −z). OpenCV's detector returns the corners in this row-major order.
#include <opencv2/core/types.hpp>
#include <vector>

namespace cosmos {

struct CalibrationBoard {
  int inner_columns = 9;
  int inner_rows = 6;
  double square_mm = 16.0;

  int corner_count() const { return inner_columns * inner_rows; }
  cv::Size pattern_size() const { return {inner_columns, inner_rows}; }
  std::vector<cv::Point3f> object_points() const;
};

}  // namespace cosmos
