#pragma once
// A hand-made model view for the recognition tests: the control points of the plane
// z = 5 mm seen over x in [x0, x0 + 13] mm, y in [-10, 10] mm (0.5 mm pixels). Its control
// points cover x in [x0 + 1, x0 + 12] (the 5x5 windows stay inside), so every fraction a test
// asserts of it can be counted by hand.
#include "core/range_image.hpp"
#include "core/registration/registration_points.hpp"

namespace cosmos::testing {

inline constexpr double kPlaneHeightMm = 5.0;

inline RegistrationPoints plane_view_points(double x0_mm) {
  RangeImage image(27, 41, 0.5, 0.5);
  image.origin_x_mm = x0_mm;
  image.origin_y_mm = -10.0;
  for (float& z : image.z_mm.values()) z = static_cast<float>(kPlaneHeightMm);
  RegistrationPointParameters parameters;
  parameters.z_noise_sigma_mm = 0.02;
  return build_registration_points(image, parameters).points;
}

}  // namespace cosmos::testing
