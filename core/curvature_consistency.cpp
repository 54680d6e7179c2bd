#include "core/curvature_consistency.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace cosmos {
namespace {

// Below this curvature (1/mm, a 1 m radius) tensor disagreement is measured absolutely, so
// near-planar pixels do not see noise as relative disagreement.
constexpr float kCurvatureFloorPerMm = 1e-3f;

struct RobustScales {
  float inverse_normal_scale;     // 1 / (1 - cos(normal scale))
  float inverse_curvature_scale2; // 1 / curvature_scale^2
  float self_weight;
};

// The smoothed frame of the pixel at `column`; `kClamp` keeps neighbour reads inside the row
// at its two ends (their same-side bits are 0 there, so they get no weight).
template <bool kClamp>
inline void smooth_pixel(const SmoothingRowInput& in, float* const* out, int column,
                         const RobustScales& s) {
  const float* const* f = in.frame[1];
  const float ni[3] = {f[kNx][column], f[kNy][column], f[kNz][column]};
  const float wi[6] = {f[kWxx][column], f[kWxy][column], f[kWxz][column],
                       f[kWyy][column], f[kWyz][column], f[kWzz][column]};
  const float wi_norm2 = wi[0] * wi[0] + wi[3] * wi[3] + wi[5] * wi[5] +
                         2 * (wi[1] * wi[1] + wi[2] * wi[2] + wi[4] * wi[4]);
  const float pi[3] = {in.position[1][0][column], in.position[1][1][column],
                       in.position[1][2][column]};
  const float self_weight = s.self_weight * ni[2] * ni[2];
  float sum_n[3] = {self_weight * ni[0], self_weight * ni[1], self_weight * ni[2]};
  float sum_w[6];
  for (int k = 0; k < 6; ++k) sum_w[k] = self_weight * wi[k];
  float sum_weight = self_weight;
  const unsigned mask = in.same_side[column];

  for (int k = 0; k < 8; ++k) {
    const int r = kNeighborOffsets[k].row + 1;
    int j = column + kNeighborOffsets[k].column;
    if constexpr (kClamp) j = std::clamp(j, 0, in.width - 1);
    const float* const* g = in.frame[r];
    const float nj[3] = {g[kNx][j], g[kNy][j], g[kNz][j]};
    const float wj[6] = {g[kWxx][j], g[kWxy][j], g[kWxz][j], g[kWyy][j], g[kWyz][j], g[kWzz][j]};
    const float d[3] = {pi[0] - in.position[r][0][j], pi[1] - in.position[r][1][j],
                        pi[2] - in.position[r][2][j]};
    // Transport: the neighbour's quadric predicts the normal n_j + W_j d at this pixel.
    float np[3] = {nj[0] + wj[0] * d[0] + wj[1] * d[1] + wj[2] * d[2],
                   nj[1] + wj[1] * d[0] + wj[3] * d[1] + wj[4] * d[2],
                   nj[2] + wj[2] * d[0] + wj[4] * d[1] + wj[5] * d[2]};
    const float inv_len = 1.0f / std::sqrt(np[0] * np[0] + np[1] * np[1] + np[2] * np[2]);
    for (float& v : np) v *= inv_len;
    const float normal_deviation =
        (1.0f - (np[0] * ni[0] + np[1] * ni[1] + np[2] * ni[2])) * s.inverse_normal_scale;
    float dw2 = 0, wj_norm2 = 0;
    for (int m = 0; m < 6; ++m) {
      const float multiplicity = (m == 0 || m == 3 || m == 5) ? 1.0f : 2.0f;
      dw2 += multiplicity * (wj[m] - wi[m]) * (wj[m] - wi[m]);
      wj_norm2 += multiplicity * wj[m] * wj[m];
    }
    const float curvature_disagreement =
        dw2 / (wi_norm2 + wj_norm2 + kCurvatureFloorPerMm * kCurvatureFloorPerMm) *
        s.inverse_curvature_scale2;
    // Steeply tilted neighbours are sampled sparsely and fit poorly (near silhouettes): their
    // predictions count with the squared cosine of their tilt.
    const float reliability = nj[2] * nj[2];
    const float weight = static_cast<float>((mask >> k) & 1u) * reliability /
                         ((1.0f + normal_deviation) * (1.0f + curvature_disagreement));
    for (int m = 0; m < 3; ++m) sum_n[m] += weight * np[m];
    for (int m = 0; m < 6; ++m) sum_w[m] += weight * wj[m];
    sum_weight += weight;
  }

  const float inv_len = 1.0f / std::sqrt(sum_n[0] * sum_n[0] + sum_n[1] * sum_n[1] +
                                         sum_n[2] * sum_n[2]);
  const float n[3] = {sum_n[0] * inv_len, sum_n[1] * inv_len, sum_n[2] * inv_len};
  const float inv_weight = 1.0f / sum_weight;
  const float w[6] = {sum_w[0] * inv_weight, sum_w[1] * inv_weight, sum_w[2] * inv_weight,
                      sum_w[3] * inv_weight, sum_w[4] * inv_weight, sum_w[5] * inv_weight};
  // Project the averaged tensor onto the new tangent plane: W' = P W P, P = I - n n^T,
  // i.e. W - n u^T - u n^T + a n n^T with u = W n, a = n.u.
  const float u[3] = {w[0] * n[0] + w[1] * n[1] + w[2] * n[2],
                      w[1] * n[0] + w[3] * n[1] + w[4] * n[2],
                      w[2] * n[0] + w[4] * n[1] + w[5] * n[2]};
  const float a = n[0] * u[0] + n[1] * u[1] + n[2] * u[2];
  const bool keep = in.valid[column] == 0;
  auto store = [&](int component, float value) {
    out[component][column] = keep ? f[component][column] : value;
  };
  store(kNx, n[0]);
  store(kNy, n[1]);
  store(kNz, n[2]);
  store(kWxx, w[0] - 2 * n[0] * u[0] + a * n[0] * n[0]);
  store(kWxy, w[1] - n[0] * u[1] - u[0] * n[1] + a * n[0] * n[1]);
  store(kWxz, w[2] - n[0] * u[2] - u[0] * n[2] + a * n[0] * n[2]);
  store(kWyy, w[3] - 2 * n[1] * u[1] + a * n[1] * n[1]);
  store(kWyz, w[4] - n[1] * u[2] - u[1] * n[2] + a * n[1] * n[2]);
  store(kWzz, w[5] - 2 * n[2] * u[2] + a * n[2] * n[2]);
}

RobustScales robust_scales(const SmoothingParameters& p) {
  const double normal_scale_rad = p.normal_scale_deg * std::numbers::pi / 180.0;
  return {static_cast<float>(1.0 / (1.0 - std::cos(normal_scale_rad))),
          static_cast<float>(1.0 / (p.curvature_scale * p.curvature_scale)),
          static_cast<float>(p.self_weight)};
}

}  // namespace

void smooth_frame_row(const SmoothingRowInput& in, float* const* out_frame,
                      const SmoothingParameters& parameters) {
  const RobustScales scales = robust_scales(parameters);
  if (in.width <= 0) return;
  smooth_pixel<true>(in, out_frame, 0, scales);
  for (int column = 1; column + 1 < in.width; ++column)
    smooth_pixel<false>(in, out_frame, column, scales);
  if (in.width > 1) smooth_pixel<true>(in, out_frame, in.width - 1, scales);
}

void smooth_curvatures(DarbouxFrameField& field, const SmoothingParameters& parameters) {
  if (parameters.iterations <= 0) return;
  const int width = field.width(), height = field.height();
  std::array<PixelGrid<float>, kFrameComponents> scratch = field.frame;
  auto* previous = &field.frame;
  auto* next = &scratch;
  for (int iteration = 0; iteration < parameters.iterations; ++iteration) {
    for (int row = 0; row < height; ++row) {
      SmoothingRowInput in;
      in.width = width;
      in.valid = field.valid.row(row);
      in.same_side = field.same_side.row(row);
      const int rows[3] = {std::max(row - 1, 0), row, std::min(row + 1, height - 1)};
      for (int r = 0; r < 3; ++r) {
        for (int axis = 0; axis < 3; ++axis) in.position[r][axis] = field.position_mm[axis].row(rows[r]);
        for (int c = 0; c < kFrameComponents; ++c) in.frame[r][c] = (*previous)[c].row(rows[r]);
      }
      float* out[kFrameComponents];
      for (int c = 0; c < kFrameComponents; ++c) out[c] = (*next)[c].row(row);
      smooth_frame_row(in, out, parameters);
    }
    std::swap(previous, next);
  }
  if (previous != &field.frame) field.frame = std::move(*previous);
}

}  // namespace cosmos
