#pragma once
// A hand-made scene for the tests of where a placed part's surface falls: a 20 x 20 mm plate
// 5 mm above the belt in a 40 x 40 mm image of 0.5 mm pixels, no data elsewhere.
#include <cmath>
#include <cstdint>
#include <limits>

#include "core/range_image.hpp"

namespace cosmos::testing {

inline constexpr double kPlateHeightMm = 5.0;

// Pixels over x, y in [0, 40) mm; the plate covers [10, 30) x [10, 30) mm.
inline RangeImage plate_scene() {
  RangeImage scene(80, 80, 0.5, 0.5);
  for (int row = 0; row < scene.height(); ++row)
    for (int column = 0; column < scene.width(); ++column) {
      const bool on_plate = scene.x_mm(column) >= 10 && scene.x_mm(column) < 30 &&
                            scene.y_mm(row) >= 10 && scene.y_mm(row) < 30;
      scene.z_mm(column, row) =
          on_plate ? static_cast<float>(kPlateHeightMm) : std::numeric_limits<float>::quiet_NaN();
    }
  return scene;
}

// The same with the belt measured wherever there is no plate and x < shadow_from_mm (beyond
// it: the scanner's shadow, neither surface nor belt).
inline RangeImage plate_scene_on_belt(double shadow_from_mm = 1e9) {
  RangeImage scene = plate_scene();
  scene.belt_seen = PixelGrid<std::uint8_t>(scene.width(), scene.height(), 0);
  for (int row = 0; row < scene.height(); ++row)
    for (int column = 0; column < scene.width(); ++column)
      scene.belt_seen(column, row) =
          std::isnan(scene.z_mm(column, row)) && scene.x_mm(column) < shadow_from_mm;
  return scene;
}

}  // namespace cosmos::testing
