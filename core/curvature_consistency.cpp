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
  float inverse_normal_scale;      // 1 / (1 - cos(normal scale))
  float inverse_curvature_scale2;  // 1 / curvature_scale^2
  float self_weight;
};

RobustScales robust_scales(const SmoothingParameters& p) {
  const double normal_scale_rad = p.normal_scale_deg * std::numbers::pi / 180.0;
  return {static_cast<float>(1.0 / (1.0 - std::cos(normal_scale_rad))),
          static_cast<float>(1.0 / (p.curvature_scale * p.curvature_scale)),
          static_cast<float>(p.self_weight)};
}

// |W|^2 (Frobenius) of a symmetric tensor stored as xx, xy, xz, yy, yz, zz.
inline float tensor_norm2(float xx, float xy, float xz, float yy, float yz, float zz) {
  return xx * xx + yy * yy + zz * zz + 2 * (xy * xy + xz * xz + yz * yz);
}

// Starts the sums with the pixel's own frame; steep pixels are sampled sparsely and fit
// poorly (near silhouettes), so every frame counts with the squared cosine of its tilt.
void start_sums(const SmoothingRowInput& in, SmoothingWorkspace& ws, const RobustScales& s) {
  const float* const* f = in.frame[1];
  float* own_norm = ws.sum(SmoothingWorkspace::kOwnNorm);
  float* weight = ws.sum(SmoothingWorkspace::kWeight);
  for (int c = 0; c < in.width; ++c) {
    weight[c] = s.self_weight * f[kNz][c] * f[kNz][c];
    own_norm[c] = tensor_norm2(f[kWxx][c], f[kWxy][c], f[kWxz][c], f[kWyy][c], f[kWyz][c], f[kWzz][c]);
  }
  for (int m = 0; m < kFrameComponents; ++m) {
    float* sum = ws.sum(m);
    const float* component = f[m];
#pragma GCC ivdep
    for (int c = 0; c < in.width; ++c) sum[c] = weight[c] * component[c];
  }
}

// Adds the predictions of the neighbour in direction k for columns [begin, end).
void add_neighbor_predictions(const SmoothingRowInput& in, SmoothingWorkspace& ws, int k,
                              int begin, int end, const RobustScales& s) {
  const int r = kNeighborOffsets[k].row + 1, dc = kNeighborOffsets[k].column;
  const float* const* f = in.frame[1];
  const float* const* g = in.frame[r];
  const float *nix = f[kNx], *niy = f[kNy], *niz = f[kNz];
  const float *wixx = f[kWxx], *wixy = f[kWxy], *wixz = f[kWxz], *wiyy = f[kWyy], *wiyz = f[kWyz], *wizz = f[kWzz];
  const float *njx = g[kNx] + dc, *njy = g[kNy] + dc, *njz = g[kNz] + dc;
  const float *wjxx = g[kWxx] + dc, *wjxy = g[kWxy] + dc, *wjxz = g[kWxz] + dc;
  const float *wjyy = g[kWyy] + dc, *wjyz = g[kWyz] + dc, *wjzz = g[kWzz] + dc;
  const float *pix = in.position[1][0], *piy = in.position[1][1], *piz = in.position[1][2];
  const float *pjx = in.position[r][0] + dc, *pjy = in.position[r][1] + dc, *pjz = in.position[r][2] + dc;
  const std::uint8_t* mask = in.same_side;
  const float* own_norm = ws.sum(SmoothingWorkspace::kOwnNorm);
  float *snx = ws.sum(kNx), *sny = ws.sum(kNy), *snz = ws.sum(kNz);
  float *swxx = ws.sum(kWxx), *swxy = ws.sum(kWxy), *swxz = ws.sum(kWxz);
  float *swyy = ws.sum(kWyy), *swyz = ws.sum(kWyz), *swzz = ws.sum(kWzz);
  float* sweight = ws.sum(SmoothingWorkspace::kWeight);
  const float floor2 = kCurvatureFloorPerMm * kCurvatureFloorPerMm;
#pragma GCC ivdep
  for (int c = begin; c < end; ++c) {
    const float dx = pix[c] - pjx[c], dy = piy[c] - pjy[c], dz = piz[c] - pjz[c];
    // Transport: the neighbour's quadric predicts the normal n_j + W_j d at this pixel.
    float px = njx[c] + wjxx[c] * dx + wjxy[c] * dy + wjxz[c] * dz;
    float py = njy[c] + wjxy[c] * dx + wjyy[c] * dy + wjyz[c] * dz;
    float pz = njz[c] + wjxz[c] * dx + wjyz[c] * dy + wjzz[c] * dz;
    const float inv_len = 1.0f / std::sqrt(px * px + py * py + pz * pz);
    px *= inv_len;
    py *= inv_len;
    pz *= inv_len;
    const float normal_deviation = (1.0f - (px * nix[c] + py * niy[c] + pz * niz[c])) * s.inverse_normal_scale;
    const float difference2 = tensor_norm2(wjxx[c] - wixx[c], wjxy[c] - wixy[c], wjxz[c] - wixz[c],
                                           wjyy[c] - wiyy[c], wjyz[c] - wiyz[c], wjzz[c] - wizz[c]);
    const float neighbor_norm2 = tensor_norm2(wjxx[c], wjxy[c], wjxz[c], wjyy[c], wjyz[c], wjzz[c]);
    const float disagreement = difference2 / (own_norm[c] + neighbor_norm2 + floor2) * s.inverse_curvature_scale2;
    const float linked = static_cast<float>((mask[c] >> k) & 1u);
    const float weight = linked * njz[c] * njz[c] / ((1.0f + normal_deviation) * (1.0f + disagreement));
    snx[c] += weight * px;
    sny[c] += weight * py;
    snz[c] += weight * pz;
    swxx[c] += weight * wjxx[c];
    swxy[c] += weight * wjxy[c];
    swxz[c] += weight * wjxz[c];
    swyy[c] += weight * wjyy[c];
    swyz[c] += weight * wjyz[c];
    swzz[c] += weight * wjzz[c];
    sweight[c] += weight;
  }
}

// The new frame: the normalized mean normal, and the mean tensor projected onto its tangent
// plane, W' = P W P with P = I - n n^T, i.e. W - n u^T - u n^T + a n n^T, u = W n, a = n.u.
void finish_row(const SmoothingRowInput& in, SmoothingWorkspace& ws, float* const* out) {
  const float* const* f = in.frame[1];
  const float *sx = ws.sum(kNx), *sy = ws.sum(kNy), *sz = ws.sum(kNz);
  const float *sxx = ws.sum(kWxx), *sxy = ws.sum(kWxy), *sxz = ws.sum(kWxz);
  const float *syy = ws.sum(kWyy), *syz = ws.sum(kWyz), *szz = ws.sum(kWzz);
  const float* sweight = ws.sum(SmoothingWorkspace::kWeight);
  const std::uint8_t* valid = in.valid;
  float* out_rows[kFrameComponents];
  const float* f_rows[kFrameComponents];
  for (int m = 0; m < kFrameComponents; ++m) out_rows[m] = out[m], f_rows[m] = f[m];
#pragma GCC ivdep
  for (int c = 0; c < in.width; ++c) {
    const float inv_len = 1.0f / std::sqrt(sx[c] * sx[c] + sy[c] * sy[c] + sz[c] * sz[c]);
    const float n0 = sx[c] * inv_len, n1 = sy[c] * inv_len, n2 = sz[c] * inv_len;
    const float inv_weight = 1.0f / sweight[c];
    const float w0 = sxx[c] * inv_weight, w1 = sxy[c] * inv_weight, w2 = sxz[c] * inv_weight;
    const float w3 = syy[c] * inv_weight, w4 = syz[c] * inv_weight, w5 = szz[c] * inv_weight;
    const float u0 = w0 * n0 + w1 * n1 + w2 * n2, u1 = w1 * n0 + w3 * n1 + w4 * n2,
                u2 = w2 * n0 + w4 * n1 + w5 * n2;
    const float a = n0 * u0 + n1 * u1 + n2 * u2;
    const float updated[kFrameComponents] = {n0, n1, n2,
                                             w0 - 2 * n0 * u0 + a * n0 * n0,
                                             w1 - n0 * u1 - u0 * n1 + a * n0 * n1,
                                             w2 - n0 * u2 - u0 * n2 + a * n0 * n2,
                                             w3 - 2 * n1 * u1 + a * n1 * n1,
                                             w4 - n1 * u2 - u1 * n2 + a * n1 * n2,
                                             w5 - 2 * n2 * u2 + a * n2 * n2};
    // Invalid pixels keep their (neutral, finite) frame: a blend instead of a branch.
    const float take = valid[c] ? 1.0f : 0.0f;
    for (int m = 0; m < kFrameComponents; ++m) out_rows[m][c] = f_rows[m][c] + take * (updated[m] - f_rows[m][c]);
  }
}

}  // namespace

SmoothingWorkspace::SmoothingWorkspace(int width) : width_(width) {
  for (auto& sum : sums_) sum.assign(static_cast<std::size_t>(std::max(width, 1)), 0.0f);
}

void smooth_frame_row(const SmoothingRowInput& in, float* const* out_frame,
                      const SmoothingParameters& parameters, SmoothingWorkspace& workspace) {
  const RobustScales scales = robust_scales(parameters);
  start_sums(in, workspace, scales);
  for (int k = 0; k < 8; ++k) {
    // Columns whose neighbour in direction k exists (the others have no same-side bit).
    const int dc = kNeighborOffsets[k].column;
    add_neighbor_predictions(in, workspace, k, dc < 0 ? 1 : 0, dc > 0 ? in.width - 1 : in.width, scales);
  }
  finish_row(in, workspace, out_frame);
}

void smooth_curvatures(DarbouxFrameField& field, const SmoothingParameters& parameters) {
  if (parameters.iterations <= 0) return;
  const int width = field.width(), height = field.height();
  std::array<PixelGrid<float>, kFrameComponents> scratch = field.frame;
  SmoothingWorkspace workspace(width);
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
      smooth_frame_row(in, out, parameters, workspace);
    }
    std::swap(previous, next);
  }
  if (previous != &field.frame) field.frame = std::move(*previous);
}

}  // namespace cosmos
