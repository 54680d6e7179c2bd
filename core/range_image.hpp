#pragma once
// A range image: z in mm per pixel, NaN where the sensor saw nothing.
// Frame convention used by every tool: pixel (column i, row j) is the point
//   x = x0 + i*dx,  y = y0 + j*dy,  z = value   (mm, scanner frame, z towards the sensor).
#include <Eigen/Core>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>

#include "core/pixel_grid.hpp"

namespace cosmos {

// T_scanner_part of a simulated scan: where the part really is.
struct GroundTruthPose {
  std::string part;
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d translation_mm = Eigen::Vector3d::Zero();
};

struct RangeImage {
  PixelGrid<float> z_mm;
  double pixel_size_x_mm = 1.0;
  double pixel_size_y_mm = 1.0;
  double origin_x_mm = 0.0;
  double origin_y_mm = 0.0;
  std::optional<GroundTruthPose> ground_truth;
  // 1 where the scanner measured the belt (a sample below the background threshold), 0
  // where it measured a surface or nothing at all (a camera or laser shadow, off the
  // sensor); empty when not known (a range image file). Both kinds of background are NaN in
  // z_mm, but only the first says the scanner would have seen a surface there
  // (core/recognition/surface_seen.hpp).
  PixelGrid<std::uint8_t> belt_seen;
  bool belt_known() const { return belt_seen.size() > 0; }

  RangeImage() = default;
  RangeImage(int width, int height, double pixel_size_x_mm_, double pixel_size_y_mm_);

  int width() const { return z_mm.width(); }
  int height() const { return z_mm.height(); }
  bool has_data(int column, int row) const;
  double x_mm(int column) const { return origin_x_mm + column * pixel_size_x_mm; }
  double y_mm(int row) const { return origin_y_mm + row * pixel_size_y_mm; }
  // The nearest column and row of a position, their inverses (beyond the image when it is).
  long column_at(double x) const { return std::lround((x - origin_x_mm) / pixel_size_x_mm); }
  long row_at(double y) const { return std::lround((y - origin_y_mm) / pixel_size_y_mm); }
  Eigen::Vector3d point_mm(int column, int row) const;
  std::size_t count_valid() const;
};

}  // namespace cosmos
