#include "core/render/field_layout.hpp"

#include <algorithm>
#include <cmath>

namespace cosmos {
namespace {

// Aspect ratios beyond this are drawn capped: a picture 40 times taller than wide helps no one.
constexpr double kMaxAspect = 8.0;

double display_aspect(double pixel_size_x_mm, double pixel_size_y_mm) {
  if (!(pixel_size_x_mm > 0) || !(pixel_size_y_mm > 0)) return 1.0;
  return std::clamp(pixel_size_y_mm / pixel_size_x_mm, 1.0 / kMaxAspect, kMaxAspect);
}

}  // namespace

FieldLayout field_layout(int width, int height, double pixel_size_x_mm, double pixel_size_y_mm) {
  FieldLayout layout;
  layout.width = std::max(width, 0);
  layout.height = std::max(height, 0);
  if (layout.width == 0 || layout.height == 0) return layout;

  const double aspect = display_aspect(pixel_size_x_mm, pixel_size_y_mm);
  // The finer axis gets the integer step k; the other follows the aspect, rounded.
  const auto scales_for = [aspect](int k) {
    if (aspect >= 1.0) return std::pair{k, std::max(1, static_cast<int>(std::lround(k * aspect)))};
    return std::pair{std::max(1, static_cast<int>(std::lround(k / aspect))), k};
  };
  for (int k = 1;; ++k) {
    const auto [scale_x, scale_y] = scales_for(k);
    const long long w = static_cast<long long>(layout.width) * scale_x;
    const long long h = static_cast<long long>(layout.height) * scale_y;
    if (k > 1 && std::max(w, h) > kMaxFieldSidePx) break;
    layout.scale_x = scale_x;
    layout.scale_y = scale_y;
    if (std::min(w, h) >= kMinFieldSidePx) break;
  }
  return layout;
}

}  // namespace cosmos
