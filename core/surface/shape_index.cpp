#include "core/surface/shape_index.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace cosmos {

namespace {

// atan(t) for |t| <= 1: a minimax polynomial (max error 1e-5 rad), branch-free so the
// per-pixel loops vectorize; libm's atan2 would be a call per pixel.
inline float atan_unit(float t) {
  const float t2 = t * t;
  return t *
         (0.99997726f +
          t2 * (-0.33262347f +
                t2 * (0.19354346f + t2 * (-0.11643287f + t2 * (0.05265332f + t2 * -0.01172120f)))));
}

// Eq. 3.2 is written for the thesis's sign convention, where convex surfaces have negative
// curvatures; with convex positive the same value is 1/2 + atan2(k1 + k2, k1 - k2)/pi, and
// k1 - k2 >= 0 keeps the angle in [-pi/2, pi/2]. Selects, no branches.
inline float shape_index_of(float kappa1, float kappa2) {
  const float y = kappa1 + kappa2, x = kappa1 - kappa2;
  const float ay = std::abs(y);
  const bool steep = ay > x;
  // One unconditional division: when x = 0 and not steep, y = 0 too.
  const float denominator = steep ? ay : x;
  const float ratio = (steep ? x : y) / (denominator > 0.0f ? denominator : 1.0f);
  const float angle = steep ? std::copysign(0.5f * std::numbers::pi_v<float> - atan_unit(ratio), y)
                            : atan_unit(ratio);
  return 0.5f + angle / std::numbers::pi_v<float>;
}

// Eq. 3.3.
inline float curvedness_of(float kappa1, float kappa2) {
  return std::sqrt(0.5f * (kappa1 * kappa1 + kappa2 * kappa2));
}

// |(dS/dk1, dS/dk2)| from Eqs. 3.21-3.22 = 1 / (pi sqrt(k1^2 + k2^2)); infinite at k = 0
// (IEEE division, no branch).
inline float shape_index_sensitivity_of(float kappa1, float kappa2) {
  return 1.0f / (std::numbers::pi_v<float> * std::sqrt(kappa1 * kappa1 + kappa2 * kappa2));
}

// One span of pixels, floats only (the caller widens and narrows the bytes), so that the
// loop vectorizes. label_code receives the SurfaceLabel value.
struct ClassifyConstants {
  float min_normal_z;
  float cell_area_mm2;
  float planar_sensitivity_mm;
};

void classify_span(int count, const ClassifyConstants& k, const float* __restrict usable_in,
                   const float* __restrict nz, const float* __restrict wxx,
                   const float* __restrict wxy, const float* __restrict wxz,
                   const float* __restrict wyy, const float* __restrict wyz,
                   const float* __restrict wzz, float* __restrict label_code,
                   float* __restrict shape, float* __restrict curved, float* __restrict area) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (int i = 0; i < count; ++i) {
    const float normal_z = nz[i];
    const bool usable = (usable_in[i] != 0.0f) & (normal_z >= k.min_normal_z);
    float kappa1, kappa2;
    principal_values(wxx[i], wxy[i], wxz[i], wyy[i], wyz[i], wzz[i], kappa1, kappa2);
    const bool planar = shape_index_sensitivity_of(kappa1, kappa2) > k.planar_sensitivity_mm;
    const float curved_shape_index = shape_index_of(kappa1, kappa2);
    label_code[i] = usable ? (planar ? 2.0f : 1.0f) : 0.0f;  // kPlanar, kCurved, kInvalid
    shape[i] = usable ? (planar ? kPlanarShapeIndex : curved_shape_index) : nan;
    curved[i] = usable ? curvedness_of(kappa1, kappa2) : 0.0f;
    // The cell's true surface area: its footprint divided by cos(tilt) = n_z.
    area[i] = usable ? k.cell_area_mm2 / normal_z : 0.0f;
  }
}

}  // namespace

float shape_index(float kappa1, float kappa2) { return shape_index_of(kappa1, kappa2); }

float curvedness(float kappa1, float kappa2) { return curvedness_of(kappa1, kappa2); }

float shape_index_sensitivity_mm(float kappa1, float kappa2) {
  return shape_index_sensitivity_of(kappa1, kappa2);
}

ShapeIndexField make_shape_index_field(int width, int height) {
  ShapeIndexField field;
  field.label = PixelGrid<SurfaceLabel>(width, height, SurfaceLabel::kInvalid);
  field.shape_index = PixelGrid<float>(width, height, std::numeric_limits<float>::quiet_NaN());
  field.curvedness_per_mm = PixelGrid<float>(width, height, 0.0f);
  field.area_mm2 = PixelGrid<float>(width, height, 0.0f);
  field.same_side = PixelGrid<std::uint8_t>(width, height, 0);
  return field;
}

void classify_row(const DarbouxFrameField& frames, int row, double pixel_size_x_mm,
                  double pixel_size_y_mm, const ShapeIndexParameters& parameters,
                  ShapeIndexField& out) {
  const ClassifyConstants constants{
      static_cast<float>(std::cos(parameters.max_tilt_deg * std::numbers::pi / 180.0)),
      static_cast<float>(pixel_size_x_mm * pixel_size_y_mm),
      static_cast<float>(parameters.planar_sensitivity_mm)};
  const std::size_t first = frames.valid.index(0, row);
  const int width = frames.width();
  // Chunks of the row: bytes are widened to floats first and the labels narrowed after.
  constexpr int kChunk = 256;
  float usable_chunk[kChunk];
  float label_chunk[kChunk];
  for (int chunk = 0; chunk < width; chunk += kChunk) {
    const int count = std::min(kChunk, width - chunk);
    const std::size_t at = first + static_cast<std::size_t>(chunk);
    for (int k = 0; k < count; ++k) usable_chunk[k] = frames.valid[at + k] != 0 ? 1.0f : 0.0f;
    classify_span(count, constants, usable_chunk, &frames.frame[kNz][at], &frames.frame[kWxx][at],
                  &frames.frame[kWxy][at], &frames.frame[kWxz][at], &frames.frame[kWyy][at],
                  &frames.frame[kWyz][at], &frames.frame[kWzz][at], label_chunk,
                  &out.shape_index[at], &out.curvedness_per_mm[at], &out.area_mm2[at]);
    for (int k = 0; k < count; ++k) {
      const auto code = static_cast<std::uint8_t>(label_chunk[k]);
      out.label[at + k] = static_cast<SurfaceLabel>(code);
      out.same_side[at + k] = static_cast<std::uint8_t>(frames.same_side[at + k] * (code != 0));
    }
  }
}

void classify_surface(const DarbouxFrameField& frames, double pixel_size_x_mm,
                      double pixel_size_y_mm, const ShapeIndexParameters& parameters,
                      ShapeIndexField& field) {
  for (int row = 0; row < frames.height(); ++row)
    classify_row(frames, row, pixel_size_x_mm, pixel_size_y_mm, parameters, field);
}

ShapeIndexField classify_surface(const DarbouxFrameField& frames, double pixel_size_x_mm,
                                 double pixel_size_y_mm, const ShapeIndexParameters& parameters) {
  ShapeIndexField field = make_shape_index_field(frames.width(), frames.height());
  classify_surface(frames, pixel_size_x_mm, pixel_size_y_mm, parameters, field);
  return field;
}

}  // namespace cosmos
