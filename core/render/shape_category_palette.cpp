#include "core/render/shape_category_palette.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace cosmos {

int shape_category_index(double shape_index) {
  // The category boundaries are the odd sixteenths, so the category is the nearest eighth.
  // The sixteenths are exact in binary, hence a value on a boundary falls into the upper one.
  const double eighths = std::floor((shape_index + 1.0 / 16) * 8);
  if (!(eighths > 0)) return 0;  // also NaN
  return static_cast<int>(std::min(eighths, static_cast<double>(kShapeCategories - 1)));
}

BgrColor shape_category_color(double shape_index) {
  return kShapeCategoryTable[static_cast<std::size_t>(shape_category_index(shape_index))].color;
}

BgrColor patch_color(int patch_id) {
  constexpr double kGoldenRatioConjugate = 0.6180339887498949;
  const int id = std::abs(patch_id);
  const double hue = std::fmod(0.13 + id * kGoldenRatioConjugate, 1.0);
  // Alternating saturation and value separates neighbours whose hues happen to be close.
  const double saturation = id % 2 == 0 ? 0.75 : 0.55;
  const double value = id % 3 == 1 ? 0.80 : 0.97;

  const double h6 = hue * 6.0;
  const int sector = static_cast<int>(h6) % 6;
  const double f = h6 - std::floor(h6);
  const double p = value * (1 - saturation);
  const double q = value * (1 - saturation * f);
  const double t = value * (1 - saturation * (1 - f));
  // HSV to RGB: each sixth of the hue circle has its own order of the three levels.
  const std::array<std::array<double, 3>, 6> rgb_of_sector{
      {{value, t, p}, {q, value, p}, {p, value, t}, {p, q, value}, {t, p, value}, {value, p, q}}};
  const auto& [r, g, b] = rgb_of_sector[static_cast<std::size_t>(sector)];
  const auto byte = [](double unit) {
    return static_cast<std::uint8_t>(std::lround(std::clamp(unit, 0.0, 1.0) * 255));
  };
  return rgb(byte(r), byte(g), byte(b));
}

}  // namespace cosmos
