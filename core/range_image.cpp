#include "core/range_image.hpp"

#include <cmath>
#include <limits>

namespace cosmos {

RangeImage::RangeImage(int width, int height, double pixel_size_x_mm_, double pixel_size_y_mm_)
    : z_mm(width, height, std::numeric_limits<float>::quiet_NaN()),
      pixel_size_x_mm(pixel_size_x_mm_),
      pixel_size_y_mm(pixel_size_y_mm_) {}

bool RangeImage::has_data(int column, int row) const {
  return z_mm.contains(column, row) && std::isfinite(z_mm(column, row));
}

Eigen::Vector3d RangeImage::point_mm(int column, int row) const {
  return {x_mm(column), y_mm(row), static_cast<double>(z_mm(column, row))};
}

std::size_t RangeImage::count_valid() const {
  std::size_t count = 0;
  for (float z : z_mm.values()) count += std::isfinite(z) ? 1 : 0;
  return count;
}

}  // namespace cosmos
