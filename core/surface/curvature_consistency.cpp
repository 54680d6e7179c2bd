#include "core/surface/curvature_consistency.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <utility>

namespace cosmos {
namespace {

struct RobustScales {
  float inverse_normal_scale;  // 1 / (1 - cos(normal scale))
  float one_plus_inverse_normal_scale;
  float inverse_curvature_scale2;  // 1 / curvature_scale^2
  float self_weight;
  float curvature_floor2;  // curvature_floor_per_mm^2
};

RobustScales robust_scales(const SmoothingParameters& p) {
  const double normal_scale_rad = p.normal_scale_deg * std::numbers::pi / 180.0;
  const double inverse_normal_scale = 1.0 / (1.0 - std::cos(normal_scale_rad));
  return {static_cast<float>(inverse_normal_scale), static_cast<float>(1.0 + inverse_normal_scale),
          static_cast<float>(1.0 / (p.curvature_scale * p.curvature_scale)),
          static_cast<float>(p.self_weight),
          static_cast<float>(p.curvature_floor_per_mm * p.curvature_floor_per_mm)};
}

// |W|^2 (Frobenius) of a symmetric tensor stored as xx, xy, xz, yy, yz, zz.
inline float tensor_norm2(float xx, float xy, float xz, float yy, float yz, float zz) {
  return xx * xx + yy * yy + zz * zz + 2 * (xy * xy + xz * xz + yz * yz);
}

// Rows of one neighbour direction, shifted so that index c addresses the neighbour of c.
struct NeighborRows {
  const float* frame[kFrameComponents];
  const float* z_mm;
};

// One iteration for columns [begin, end): every pixel starts from its own frame and adds the
// predictions of its same-side neighbours, then takes the normalized mean normal and the mean
// tensor projected onto its tangent plane, W' = P W P with P = I - n n^T, i.e.
// W - n u^T - u n^T + a n n^T with u = W n, a = n.u. Steep pixels are sampled sparsely and fit
// poorly (near silhouettes), so every frame counts with the squared cosine of its tilt. The
// eight directions are unrolled at compile time and the loop body has no branches, so the
// compiler vectorizes across columns with all sums in registers.
template <int... K>
void smooth_columns(const SmoothingRowInput& in, const NeighborRows (&neighbors)[8],
                    float* const* out, int begin, int end, const RobustScales& s,
                    std::integer_sequence<int, K...>) {
  const float* const* f = in.frame[1];
  const float* piz = in.z_mm[1];
  const std::uint8_t* mask = in.same_side;
  const float step_x = in.pixel_size_x_mm, step_y = in.pixel_size_y_mm;
  const std::uint8_t* valid = in.valid;
  const float floor2 = s.curvature_floor2;
  float* o[kFrameComponents];
  const float* fi[kFrameComponents];
  for (int m = 0; m < kFrameComponents; ++m) o[m] = out[m], fi[m] = f[m];
  // The byte masks are widened per chunk first: with bytes in the loop the vectorizer would
  // process 32 columns at a time and spill its registers.
  constexpr int kChunk = 256;
  std::uint32_t chunk_bits[kChunk];
  float chunk_take[kChunk];
  for (int chunk = begin; chunk < end; chunk += kChunk) {
    const int chunk_end = std::min(end, chunk + kChunk);
    for (int c = chunk; c < chunk_end; ++c) {
      chunk_bits[c - chunk] = mask[c];
      chunk_take[c - chunk] = valid[c] ? 1.0f : 0.0f;
    }
#pragma GCC ivdep
    for (int c = chunk; c < chunk_end; ++c) {
      const float ni[3] = {fi[kNx][c], fi[kNy][c], fi[kNz][c]};
      const float wi[6] = {fi[kWxx][c], fi[kWxy][c], fi[kWxz][c],
                           fi[kWyy][c], fi[kWyz][c], fi[kWzz][c]};
      const float own_norm = tensor_norm2(wi[0], wi[1], wi[2], wi[3], wi[4], wi[5]);
      const float w0 = s.self_weight * ni[2] * ni[2];
      float sum_n[3] = {w0 * ni[0], w0 * ni[1], w0 * ni[2]};
      float sum_w[6] = {w0 * wi[0], w0 * wi[1], w0 * wi[2], w0 * wi[3], w0 * wi[4], w0 * wi[5]};
      float sum_weight = w0;
      const std::uint32_t bits = chunk_bits[c - chunk];
      auto add = [&](auto direction) {
        constexpr int k = decltype(direction)::value;
        // d = p_i - p_j: in the plane a constant of the direction (none along an axis).
        constexpr float dc = static_cast<float>(-kNeighborOffsets[k].column);
        constexpr float dr = static_cast<float>(-kNeighborOffsets[k].row);
        const NeighborRows& g = neighbors[k];
        const float nj[3] = {g.frame[kNx][c], g.frame[kNy][c], g.frame[kNz][c]};
        const float wj[6] = {g.frame[kWxx][c], g.frame[kWxy][c], g.frame[kWxz][c],
                             g.frame[kWyy][c], g.frame[kWyz][c], g.frame[kWzz][c]};
        const float dz = piz[c] - g.z_mm[c];
        // Transport: the neighbour's quadric predicts the normal n_j + W_j d at this pixel. W_j d
        // is tangent to the unit n_j, so the prediction's squared length is 1 + |W_j d|^2 and
        // its inverse length is 1 - e/2 + 3e^2/8 to third order in e = |W_j d|^2 (no sqrt).
        float tx = wj[2] * dz, ty = wj[4] * dz, tz = wj[5] * dz;
        if constexpr (dc != 0) {
          const float dx = dc * step_x;
          tx += wj[0] * dx, ty += wj[1] * dx, tz += wj[2] * dx;
        }
        if constexpr (dr != 0) {
          const float dy = dr * step_y;
          tx += wj[1] * dy, ty += wj[3] * dy, tz += wj[4] * dy;
        }
        const float e = tx * tx + ty * ty + tz * tz;
        const float inv_len = 1.0f - 0.5f * e + 0.375f * e * e;
        // The prediction is q inv_len, q = n_j + W_j d; inv_len is folded into the weight.
        const float qx = nj[0] + tx, qy = nj[1] + ty, qz = nj[2] + tz;
        // 1 + normal deviation = 1 + (1 - prediction . n_i) / (1 - cos(normal scale)).
        const float one_plus_deviation =
            s.one_plus_inverse_normal_scale -
            s.inverse_normal_scale * inv_len * (qx * ni[0] + qy * ni[1] + qz * ni[2]);
        // |W_j - W_i|^2 = |W_j|^2 + |W_i|^2 - 2 W_j : W_i: |W_j|^2 is needed for the scale
        // anyway, so the difference costs one inner product instead of six subtractions and a
        // norm (its rounding is far below the scale it is compared with).
        const float neighbor_norm = tensor_norm2(wj[0], wj[1], wj[2], wj[3], wj[4], wj[5]);
        const float inner = wj[0] * wi[0] + wj[3] * wi[3] + wj[5] * wi[5] +
                            2 * (wj[1] * wi[1] + wj[2] * wi[2] + wj[4] * wi[4]);
        const float difference2 = own_norm + neighbor_norm - 2 * inner;
        const float scale2 = own_norm + neighbor_norm + floor2;
        // linked * n_jz^2 / ((1 + normal deviation) (1 + difference2 / scale2 / c^2)), one
        // division.
        const float linked = static_cast<float>((bits >> k) & 1u);
        const float weight =
            linked * nj[2] * nj[2] * scale2 /
            (one_plus_deviation * (scale2 + difference2 * s.inverse_curvature_scale2));
        const float weight_per_length = weight * inv_len;
        sum_n[0] += weight_per_length * qx;
        sum_n[1] += weight_per_length * qy;
        sum_n[2] += weight_per_length * qz;
        for (int m = 0; m < 6; ++m) sum_w[m] += weight * wj[m];
        sum_weight += weight;
      };
      (add(std::integral_constant<int, K>{}), ...);
      const float inv_len =
          1.0f / std::sqrt(sum_n[0] * sum_n[0] + sum_n[1] * sum_n[1] + sum_n[2] * sum_n[2]);
      const float n0 = sum_n[0] * inv_len, n1 = sum_n[1] * inv_len, n2 = sum_n[2] * inv_len;
      const float inv_weight = 1.0f / sum_weight;
      float w[6];
      for (int m = 0; m < 6; ++m) w[m] = sum_w[m] * inv_weight;
      const float u0 = w[0] * n0 + w[1] * n1 + w[2] * n2, u1 = w[1] * n0 + w[3] * n1 + w[4] * n2,
                  u2 = w[2] * n0 + w[4] * n1 + w[5] * n2;
      const float a = n0 * u0 + n1 * u1 + n2 * u2;
      const float updated[kFrameComponents] = {n0,
                                               n1,
                                               n2,
                                               w[0] - 2 * n0 * u0 + a * n0 * n0,
                                               w[1] - n0 * u1 - u0 * n1 + a * n0 * n1,
                                               w[2] - n0 * u2 - u0 * n2 + a * n0 * n2,
                                               w[3] - 2 * n1 * u1 + a * n1 * n1,
                                               w[4] - n1 * u2 - u1 * n2 + a * n1 * n2,
                                               w[5] - 2 * n2 * u2 + a * n2 * n2};
      // Invalid pixels keep their (neutral, finite) frame: a blend instead of a branch.
      const float take = chunk_take[c - chunk];
      for (int m = 0; m < kFrameComponents; ++m)
        o[m][c] = fi[m][c] + take * (updated[m] - fi[m][c]);
    }
  }
}

}  // namespace

void smooth_frame_row(const SmoothingRowInput& in, float* const* out_frame,
                      const SmoothingParameters& parameters) {
  const RobustScales scales = robust_scales(parameters);
  // Neighbour k of column c is at c + dc. At an end column a neighbour that would lie
  // outside the row is read at the pixel itself instead (its same-side bit is 0, so it gets
  // no weight); the neighbours inside the row are read where they are, as for inner columns.
  NeighborRows shifted[8], first_column[8], last_column[8], only_column[8];
  for (int k = 0; k < 8; ++k) {
    const int r = kNeighborOffsets[k].row + 1, dc = kNeighborOffsets[k].column;
    NeighborRows in_place;
    for (int m = 0; m < kFrameComponents; ++m) {
      shifted[k].frame[m] = in.frame[r][m] + dc;
      in_place.frame[m] = in.frame[r][m];
    }
    shifted[k].z_mm = in.z_mm[r] + dc;
    in_place.z_mm = in.z_mm[r];
    first_column[k] = dc < 0 ? in_place : shifted[k];
    last_column[k] = dc > 0 ? in_place : shifted[k];
    only_column[k] = dc != 0 ? in_place : shifted[k];
  }
  const auto directions = std::make_integer_sequence<int, 8>{};
  const int begin = std::clamp(in.column_begin, 0, in.width);
  const int end = in.column_end < 0 ? in.width : std::clamp(in.column_end, begin, in.width);
  // Outside the range every pixel is invalid and keeps its frame, as inside: a copy.
  if (in.copy_outside_range) {
    for (int m = 0; m < kFrameComponents; ++m) {
      std::copy(in.frame[1][m], in.frame[1][m] + begin, out_frame[m]);
      std::copy(in.frame[1][m] + end, in.frame[1][m] + in.width, out_frame[m] + end);
    }
  }
  if (begin >= end) return;
  if (in.width == 1) {
    smooth_columns(in, only_column, out_frame, 0, 1, scales, directions);
    return;
  }
  if (begin == 0) smooth_columns(in, first_column, out_frame, 0, 1, scales, directions);
  const int inner_begin = std::max(begin, 1), inner_end = std::min(end, in.width - 1);
  if (inner_begin < inner_end)
    smooth_columns(in, shifted, out_frame, inner_begin, inner_end, scales, directions);
  if (end == in.width)
    smooth_columns(in, last_column, out_frame, in.width - 1, in.width, scales, directions);
}

std::array<int, 2> valid_column_extent(const std::uint8_t* valid, int width) {
  int begin = 0, end = width;
  while (begin < end && !valid[begin]) ++begin;
  while (end > begin && !valid[end - 1]) --end;
  return {begin, end};
}

namespace {

// The planes one smoothing pass reads and writes (two frame buffers and the positions) in one
// allocation, each offset by a few more cache lines than the last. Separately allocated planes
// of a size that is a multiple of 4 KB all start at the same offset in a page, so the same
// pixel of the 21 planes falls into one 8-way L1 set, and the pass evicts its own rows;
// staggered, the planes spread over the sets (BM_Smoothing15Iterations of
// bench/cosmos_pipeline_bench.cpp times the pass).
class StaggeredPlanes {
 public:
  static constexpr int kFramePlanes = 2 * kFrameComponents;
  explicit StaggeredPlanes(const DarbouxFrameField& field)
      : plane_floats_(field.frame[0].size()),
        stride_floats_(plane_floats_ + kStaggerFloats),
        storage_(new float[(kFramePlanes + 1) * stride_floats_]) {
    // Both buffers: the passes then leave the invalid ends of the rows alone.
    for (int buffer = 0; buffer < 2; ++buffer)
      for (int m = 0; m < kFrameComponents; ++m) copy_in(field.frame[m], frame(buffer, m));
    copy_in(field.position_mm[2], z_mm());
  }
  float* frame(int buffer, int component) { return plane(buffer * kFrameComponents + component); }
  float* z_mm() { return plane(kFramePlanes); }
  void copy_out(int buffer, DarbouxFrameField& field) {
    for (int m = 0; m < kFrameComponents; ++m) {
      const float* from = frame(buffer, m);
      std::copy(from, from + plane_floats_, field.frame[m].data());
    }
  }

 private:
  static constexpr std::size_t kStaggerFloats = 16 * 5;  // 5 cache lines
  float* plane(int index) { return storage_.get() + index * stride_floats_; }
  void copy_in(const PixelGrid<float>& grid, float* to) {
    std::copy(grid.data(), grid.data() + plane_floats_, to);
  }
  std::size_t plane_floats_, stride_floats_;
  std::unique_ptr<float[]> storage_;  // uninitialized: filled by copy_in and the passes
};

}  // namespace

void smooth_curvatures(DarbouxFrameField& field, double pixel_size_x_mm, double pixel_size_y_mm,
                       const SmoothingParameters& parameters) {
  if (parameters.iterations <= 0) return;
  const int width = field.width(), height = field.height();
  // A part rarely fills its image's rows: each pass computes only the valid span of a row.
  std::vector<std::array<int, 2>> extents(static_cast<std::size_t>(height));
  for (int row = 0; row < height; ++row)
    extents[static_cast<std::size_t>(row)] = valid_column_extent(field.valid.row(row), width);
  StaggeredPlanes planes(field);
  const auto at_row = [width](float* plane, int row) {
    return plane + static_cast<std::size_t>(row) * width;
  };
  int previous = 0;
  for (int iteration = 0; iteration < parameters.iterations; ++iteration) {
    for (int row = 0; row < height; ++row) {
      SmoothingRowInput in;
      in.width = width;
      in.valid = field.valid.row(row);
      in.same_side = field.same_side.row(row);
      in.column_begin = extents[static_cast<std::size_t>(row)][0];
      in.column_end = extents[static_cast<std::size_t>(row)][1];
      in.copy_outside_range = false;
      in.pixel_size_x_mm = static_cast<float>(pixel_size_x_mm);
      in.pixel_size_y_mm = static_cast<float>(pixel_size_y_mm);
      const int rows[3] = {std::max(row - 1, 0), row, std::min(row + 1, height - 1)};
      for (int r = 0; r < 3; ++r) {
        in.z_mm[r] = at_row(planes.z_mm(), rows[r]);
        for (int c = 0; c < kFrameComponents; ++c)
          in.frame[r][c] = at_row(planes.frame(previous, c), rows[r]);
      }
      float* out[kFrameComponents];
      for (int c = 0; c < kFrameComponents; ++c)
        out[c] = at_row(planes.frame(1 - previous, c), row);
      smooth_frame_row(in, out, parameters);
    }
    previous = 1 - previous;
  }
  planes.copy_out(previous, field);
}

}  // namespace cosmos
