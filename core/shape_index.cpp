#include "core/shape_index.hpp"

#include <cmath>
#include <limits>
#include <numbers>

namespace cosmos {

namespace {

// atan(t) for |t| <= 1: a minimax polynomial (max error 1e-5 rad), branch-free so the
// per-pixel loops vectorize; libm's atan2 would be a call per pixel.
inline float atan_unit(float t) {
  const float t2 = t * t;
  return t * (0.99997726f + t2 * (-0.33262347f + t2 * (0.19354346f + t2 * (-0.11643287f +
              t2 * (0.05265332f + t2 * -0.01172120f)))));
}

}  // namespace

float shape_index(float kappa1, float kappa2) {
  // Eq. 3.2 is written for the thesis's sign convention, where convex surfaces have negative
  // curvatures; with convex positive the same value is 1/2 + atan2(k1 + k2, k1 - k2)/pi, and
  // k1 - k2 >= 0 keeps the angle in [-pi/2, pi/2].
  const float y = kappa1 + kappa2, x = kappa1 - kappa2;
  const float ay = std::abs(y);
  const bool steep = ay > x;
  const float ratio = steep ? x / ay : (x > 0 ? y / x : 0.0f);
  const float angle = steep ? std::copysign(0.5f * std::numbers::pi_v<float> - atan_unit(ratio), y)
                            : atan_unit(ratio);
  return 0.5f + angle / std::numbers::pi_v<float>;
}

float curvedness(float kappa1, float kappa2) {
  return std::sqrt(0.5f * (kappa1 * kappa1 + kappa2 * kappa2));  // Eq. 3.3
}

float shape_index_sensitivity_mm(float kappa1, float kappa2) {
  // |(dS/dk1, dS/dk2)| from Eqs. 3.21-3.22 = 1 / (pi sqrt(k1^2 + k2^2)).
  const float magnitude = std::sqrt(kappa1 * kappa1 + kappa2 * kappa2);
  if (magnitude == 0.0f) return std::numeric_limits<float>::infinity();
  return 1.0f / (std::numbers::pi_v<float> * magnitude);
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
  const float min_normal_z =
      static_cast<float>(std::cos(parameters.max_tilt_deg * std::numbers::pi / 180.0));
  const float cell_area_mm2 = static_cast<float>(pixel_size_x_mm * pixel_size_y_mm);
  const float planar_sensitivity = static_cast<float>(parameters.planar_sensitivity_mm);
  for (int column = 0; column < frames.width(); ++column) {
    const std::size_t i = frames.valid.index(column, row);
    const float normal_z = frames.frame[kNz][i];
    if (!frames.valid[i] || !(normal_z >= min_normal_z)) {
      out.label[i] = SurfaceLabel::kInvalid;
      out.shape_index[i] = std::numeric_limits<float>::quiet_NaN();
      out.curvedness_per_mm[i] = 0;
      out.area_mm2[i] = 0;
      out.same_side[i] = 0;
      continue;
    }
    float kappa1, kappa2;
    principal_values(frame_at(frames, i), kappa1, kappa2);
    const bool planar = shape_index_sensitivity_mm(kappa1, kappa2) > planar_sensitivity;
    out.label[i] = planar ? SurfaceLabel::kPlanar : SurfaceLabel::kCurved;
    out.shape_index[i] = planar ? kPlanarShapeIndex : shape_index(kappa1, kappa2);
    out.curvedness_per_mm[i] = curvedness(kappa1, kappa2);
    // The cell's true surface area: its footprint divided by cos(tilt) = n_z.
    out.area_mm2[i] = cell_area_mm2 / normal_z;
    out.same_side[i] = frames.same_side[i];
  }
}

ShapeIndexField classify_surface(const DarbouxFrameField& frames, double pixel_size_x_mm,
                                 double pixel_size_y_mm, const ShapeIndexParameters& parameters) {
  ShapeIndexField field = make_shape_index_field(frames.width(), frames.height());
  for (int row = 0; row < frames.height(); ++row)
    classify_row(frames, row, pixel_size_x_mm, pixel_size_y_mm, parameters, field);
  return field;
}

}  // namespace cosmos
