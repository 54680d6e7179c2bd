#pragma once
// A noise-free range image of the plane z = tan(tilt) x + 5 mm, square, centred on the
// origin: the known surface the registration tests measure control points, d_s and its
// variance on.
#include <cmath>
#include <numbers>

#include "core/range_image.hpp"

namespace cosmos::testing {

inline RangeImage tilted_plane(double tilt_deg, int size, double pixel_mm) {
  RangeImage image(size, size, pixel_mm, pixel_mm);
  image.origin_x_mm = image.origin_y_mm = -0.5 * (size - 1) * pixel_mm;
  const double slope = std::tan(tilt_deg * std::numbers::pi / 180.0);
  for (int row = 0; row < size; ++row)
    for (int column = 0; column < size; ++column)
      image.z_mm(column, row) = static_cast<float>(slope * image.x_mm(column) + 5.0);
  return image;
}

}  // namespace cosmos::testing
