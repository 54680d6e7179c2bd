#include "calibration/calibration_board.hpp"

namespace cosmos {

std::vector<cv::Point3f> CalibrationBoard::object_points() const {
  std::vector<cv::Point3f> points;
  points.reserve(static_cast<std::size_t>(corner_count()));
  for (int j = 0; j < inner_rows; ++j)
    for (int i = 0; i < inner_columns; ++i)
      points.emplace_back(static_cast<float>(i * square_mm), static_cast<float>(j * square_mm),
                          0.0f);
  return points;
}

}  // namespace cosmos
