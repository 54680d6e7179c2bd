#pragma once
// What a laser sheet pitched by p about x measures, worked out from the geometry alone (not
// from the de-shear under test): the sheet of the profile whose foot is at belt position
// y_foot holds the points y = y_foot − s·sin p, z = s·cos p at in-sheet height s ≥ 0, and the
// laser, coming down the sheet, lights the highest of them that lies on or under the surface.
#include <algorithm>
#include <cmath>
#include <numbers>

namespace cosmos::testing {

inline double radians(double degrees) { return degrees * std::numbers::pi / 180; }

// The in-sheet height of that point for one column whose surface height along the belt is
// `height(y_mm)` (0: bare belt), no higher than `top_mm`: s where height(y_foot − s·sin p)
// − s·cos p turns non-negative, coming down from above the top. Marched in steps of
// 0.05 mm (a chord of the surface shorter than that is missed: only a tangent's), then
// bisected to the double's resolution.
template <class Height>
double pitched_sheet_hit(const Height& height, double y_foot_mm, double pitch_deg, double top_mm) {
  const double sin_p = std::sin(radians(pitch_deg)), cos_p = std::cos(radians(pitch_deg));
  const auto inside = [&](double s) { return height(y_foot_mm - s * sin_p) >= s * cos_p; };
  constexpr double kStep = 0.05;
  for (double above = top_mm / cos_p + kStep; above > 0; above -= kStep) {
    double below = std::max(above - kStep, 0.0);
    if (!inside(below)) continue;
    double outside = above;
    for (int k = 0; k < 64; ++k) {
      const double mid = 0.5 * (below + outside);
      (inside(mid) ? below : outside) = mid;
    }
    return below;
  }
  return 0;
}

}  // namespace cosmos::testing
