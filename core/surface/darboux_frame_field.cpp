#include "core/surface/darboux_frame_field.hpp"

#include <algorithm>
#include <cmath>

namespace cosmos {

DarbouxFrameField::DarbouxFrameField(int width, int height)
    : valid(width, height, 0), same_side(width, height, 0) {
  for (auto& grid : position_mm) grid = PixelGrid<float>(width, height, 0.0f);
  for (auto& grid : frame) grid = PixelGrid<float>(width, height, 0.0f);
  frame[kNz] = PixelGrid<float>(width, height, 1.0f);
}

FrameValues frame_at(const DarbouxFrameField& field, std::size_t pixel) {
  FrameValues values;
  for (int c = 0; c < kFrameComponents; ++c) values[c] = field.frame[c][pixel];
  return values;
}

PrincipalCurvatures principal_curvatures(const FrameValues& f) {
  const float nx = f[kNx], ny = f[kNy], nz = f[kNz];
  // Tangent basis: t1 is the x axis projected onto the tangent plane; |t1|^2 = 1 - nx^2 > 0
  // for any surface seen by the sensor (nz > 0).
  float t1[3] = {1.0f - nx * nx, -nx * ny, -nx * nz};
  const float t1_norm = std::sqrt(t1[0] * t1[0] + t1[1] * t1[1] + t1[2] * t1[2]);
  for (float& v : t1) v /= t1_norm;
  const float t2[3] = {ny * t1[2] - nz * t1[1], nz * t1[0] - nx * t1[2], nx * t1[1] - ny * t1[0]};
  auto quadratic_form = [&](const float* a, const float* b) {
    const float wa[3] = {f[kWxx] * a[0] + f[kWxy] * a[1] + f[kWxz] * a[2],
                         f[kWxy] * a[0] + f[kWyy] * a[1] + f[kWyz] * a[2],
                         f[kWxz] * a[0] + f[kWyz] * a[1] + f[kWzz] * a[2]};
    return wa[0] * b[0] + wa[1] * b[1] + wa[2] * b[2];
  };
  const float a = quadratic_form(t1, t1), b = quadratic_form(t1, t2), c = quadratic_form(t2, t2);
  const float mean = 0.5f * (a + c);
  const float radius = std::sqrt(0.25f * (a - c) * (a - c) + b * b);
  PrincipalCurvatures result;
  result.kappa1 = mean + radius;
  result.kappa2 = mean - radius;
  const float angle = 0.5f * std::atan2(2.0f * b, a - c);
  const float ca = std::cos(angle), sa = std::sin(angle);
  for (int i = 0; i < 3; ++i) result.direction1[i] = ca * t1[i] + sa * t2[i];
  return result;
}

PrincipalCurvatures principal_curvatures(const DarbouxFrameField& field, std::size_t pixel) {
  return principal_curvatures(frame_at(field, pixel));
}

}  // namespace cosmos
