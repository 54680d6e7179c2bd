#pragma once
// Per-pixel Darboux frames of a range image, stored as structure-of-arrays rows so that the
// curvature-consistency iterations vectorize across a row and can run row by row.
//
// Curvature is stored as the 3D Weingarten tensor W (symmetric, tangent to the normal):
// W = k1 e1 e1^T + k2 e2 e2^T, with the sign convention "bulging towards the sensor is
// convex and positive", so that moving by a tangent step d turns the normal by W d.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "core/pixel_grid.hpp"

namespace cosmos {

// The 8-neighbourhood; bit k of a same-side mask refers to kNeighborOffsets[k].
struct PixelOffset {
  int column;
  int row;
};
inline constexpr std::array<PixelOffset, 8> kNeighborOffsets{
    {{-1, -1}, {0, -1}, {1, -1}, {-1, 0}, {1, 0}, {-1, 1}, {0, 1}, {1, 1}}};

enum FrameComponent : int { kNx, kNy, kNz, kWxx, kWxy, kWxz, kWyy, kWyz, kWzz, kFrameComponents };

struct DarbouxFrameField {
  DarbouxFrameField() = default;
  DarbouxFrameField(int width, int height);

  int width() const { return valid.width(); }
  int height() const { return valid.height(); }

  PixelGrid<std::uint8_t> valid;      // 1 where the local fit succeeded
  PixelGrid<std::uint8_t> same_side;  // bit k: neighbour k valid and not across a depth jump
  std::array<PixelGrid<float>, 3> position_mm;           // fitted surface point
  std::array<PixelGrid<float>, kFrameComponents> frame;  // normal, then W
};

struct PrincipalCurvatures {
  float kappa1 = 0;  // kappa1 >= kappa2, 1/mm
  float kappa2 = 0;
  float direction1[3] = {0, 0, 0};  // unit principal direction of kappa1
};

// Eigen-decomposition of W restricted to the tangent plane of the normal.
using FrameValues = std::array<float, kFrameComponents>;
PrincipalCurvatures principal_curvatures(const FrameValues& frame);
FrameValues frame_at(const DarbouxFrameField& field, std::size_t pixel);

// The principal curvatures alone (no directions): cheaper, for per-pixel classification.
// W is tangent to n, so its eigenvalues are k1, k2 and 0: from its trace and the sum of its
// principal 2x2 minors, k1 + k2 and k1 k2. Inline and branch-free so per-pixel loops vectorize.
inline void principal_values(float wxx, float wxy, float wxz, float wyy, float wyz, float wzz,
                             float& kappa1, float& kappa2) {
  const float trace = wxx + wyy + wzz;
  const float minors = wxx * wyy - wxy * wxy + wxx * wzz - wxz * wxz + wyy * wzz - wyz * wyz;
  const float mean = 0.5f * trace;
  const float radius = std::sqrt(std::max(0.0f, mean * mean - minors));
  kappa1 = mean + radius;
  kappa2 = mean - radius;
}
inline void principal_values(const FrameValues& f, float& kappa1, float& kappa2) {
  principal_values(f[kWxx], f[kWxy], f[kWxz], f[kWyy], f[kWyz], f[kWzz], kappa1, kappa2);
}

PrincipalCurvatures principal_curvatures(const DarbouxFrameField& field, std::size_t pixel);

}  // namespace cosmos
