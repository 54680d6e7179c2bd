#pragma once
// The widths of a point set (a part's hull corners, a scan's control points) along directions,
// and directions spread evenly over the sphere to take them along: what the size bounds compare
// a part with a scan by (view_extent.hpp, core/recognition/part_size_gate.hpp).
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>

namespace cosmos {

// `points`: a range of 3-vectors (a vector of them, or a matrix's columns). 0 for none.
template <class Points>
double width_along(const Points& points, const Eigen::Vector3d& direction) {
  double low = std::numeric_limits<double>::infinity();
  double high = -low;
  for (const auto& point : points) {
    const double along = direction.dot(point);
    low = std::min(low, along);
    high = std::max(high, along);
  }
  return high > low ? high - low : 0.0;
}

struct WidthsAcross {
  double widest_mm = 0;
  double narrowest_mm = 0;
};

// The widest and narrowest widths along `turns` directions square to the unit vector
// `direction`, over half a circle (a width is the same along a direction and its opposite).
template <class Points>
WidthsAcross widths_across(const Points& points, const Eigen::Vector3d& direction, int turns) {
  const Eigen::Vector3d across = direction.unitOrthogonal();
  const Eigen::Vector3d across_too = direction.cross(across);
  WidthsAcross widths{0, std::numeric_limits<double>::infinity()};
  for (int turn = 0; turn < turns; ++turn) {
    const double angle = M_PI * turn / turns;
    const double width =
        width_along(points, std::cos(angle) * across + std::sin(angle) * across_too);
    widths.widest_mm = std::max(widths.widest_mm, width);
    widths.narrowest_mm = std::min(widths.narrowest_mm, width);
  }
  if (turns <= 0) widths.narrowest_mm = 0;
  return widths;
}

// Direction k of n spread evenly (a Fibonacci spiral) over the whole unit sphere, or over its
// upper half: enough for widths, the same along a direction and its opposite.
enum class SphereCover { kWhole, kUpperHalf };
inline Eigen::Vector3d spread_direction(int k, int n, SphereCover cover) {
  const double spread = cover == SphereCover::kWhole ? 2.0 : 1.0;
  const double z = 1.0 - spread * (k + 0.5) / n;
  const double radius = std::sqrt(std::max(0.0, 1.0 - z * z));
  constexpr double kGoldenAngle = 2.399963229728653;
  const double phi = kGoldenAngle * k;
  return {radius * std::cos(phi), radius * std::sin(phi), z};
}

}  // namespace cosmos
