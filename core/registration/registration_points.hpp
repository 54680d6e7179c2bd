#pragma once
// What registration needs from a view (§6.5.1, §6.7.1): control points on a regular grid of
// the range image, each with a local least-squares ("linear regression", Eq. 6.7) fit of z
// over a window around it, the fit's covariance factor, which with the z noise variance
// gives the uncertainty of the point-to-plane distance d_s (Eqs. 6.21-6.22), and its unit
// normal. The same structure serves as the scene's control points (coarse stride) and as the
// model's surface (stride 1 or 2: its grid makes the line-surface intersection of
// Chen-Medioni a constant-time lookup). Plain Eigen arrays, so it can be written to the
// model-base file as is.
//
// The fit is the thesis's plane z = a dx + b dy + c, or (the default) that plane plus the
// quadratic terms. Why: the plane's height at the pixel is the window mean, biased by
// (curvature) * (window second moment) — 0.025 mm for a laplacian of 0.1/mm over 5x5 pixels
// of 0.5 mm, as large as the sensor noise — and the bias differs between two views that see
// the surface from different directions, so it does not cancel in registration. The quadric
// removes it, and its tangent plane has the same slopes (the quadratic terms are orthogonal to
// the linear ones over a full symmetric window); it is still linear regression, so Eq. 6.21
// applies unchanged with the larger parameter vector.
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "core/parameter_visitor.hpp"
#include "core/range_image.hpp"
#include "core/surface/darboux_frame_field.hpp"

namespace cosmos {

struct RegistrationPointParameters {
  int stride_px = 1;    // §6.7.1 uniform subsampling: one control point per stride^2 px
  int window_size = 5;  // odd; the fit neighbourhood (5x5 as in §6.5.1)
  // Samples of the window differing by more between 4-neighbours lie across a depth jump:
  // the point is not taken (same default as SurfaceFitParameters::depth_jump_mm).
  double depth_jump_mm = 3.0;
  bool quadric_fit = true;  // false: the thesis's plane (Eq. 6.7)
  // §6.7.1 local smoothness: a window whose fit residual standard deviation exceeds this
  // many times the view's noise (below) is too rough or straddles a crease.
  double max_residual_noise_ratio = 3.0;
  // Steeper surface is seen at grazing incidence: too few, too noisy samples.
  double max_tilt_deg = 75.0;
  // The sensor's z noise standard deviation; 0 = estimate it as the median fit residual of
  // the candidate windows (§6.6: only second-order statistics of the noise are needed).
  double z_noise_sigma_mm = 0.0;

  template <class Visitor>
  void visit(Visitor& v) {
    v("stride_px", stride_px, "one control point per stride^2 pixels (§6.7.1)", Range{1, 64});
    v("window_size", window_size, "fit window, pixels (odd; §6.5.1: 5)", Range{3, 15});
    v("depth_jump_mm", depth_jump_mm, "a window across a larger 4-neighbour |dz| is not taken, mm",
      Range::above(0, 1e4));
    v("quadric_fit", quadric_fit, "quadric fit; false: the thesis's plane (Eq. 6.7)");
    v("max_residual_noise_ratio", max_residual_noise_ratio,
      "rougher windows (fit residual over noise) are not taken (§6.7.1)", Range::above(0, 1e3));
    v("max_tilt_deg", max_tilt_deg, "steeper surface is not taken, deg", Range::above(0, 90));
    v("z_noise_sigma_mm", z_noise_sigma_mm, "sensor z noise sigma, mm; 0: estimated per view",
      Range{0, 10});
  }
};

// The local fit z(dx, dy) = sum_k coefficient_k * basis_k(dx, dy), offsets in mm from the
// control pixel; the plane fit leaves the quadratic coefficients 0.
enum SurfaceCoefficient : int {
  kHeight,
  kSlopeX,
  kSlopeY,
  kCurveXX,
  kCurveXY,
  kCurveYY,
  kSurfaceCoefficients
};
using SurfaceVector = Eigen::Matrix<double, kSurfaceCoefficients, 1>;

// (1, dx, dy, dx^2, dx dy, dy^2): the row of A in Eq. 6.7 (extended), and the gradient of the
// fitted height with respect to the coefficients.
inline SurfaceVector surface_basis(double dx_mm, double dy_mm) {
  SurfaceVector b;
  b << 1.0, dx_mm, dy_mm, dx_mm * dx_mm, dx_mm * dy_mm, dy_mm * dy_mm;
  return b;
}

struct RegistrationPoints {
  // Control-point grid: cell (u, v) is image pixel (u * stride, v * stride), at
  // x = origin_x_mm + u * spacing_x_mm, y = origin_y_mm + v * spacing_y_mm.
  int grid_width = 0;
  int grid_height = 0;
  double origin_x_mm = 0.0;
  double origin_y_mm = 0.0;
  double spacing_x_mm = 1.0;
  double spacing_y_mm = 1.0;
  std::vector<std::int32_t> cell_point;  // grid_width * grid_height; point index, -1 = none

  // One column per control point, in grid (row-major) order.
  Eigen::Matrix3Xd position_mm;  // (x, y, fitted height) at the pixel, not the raw z
  Eigen::Matrix3Xd normal;       // unit, towards the sensor (+z)
  Eigen::Matrix<double, kSurfaceCoefficients, Eigen::Dynamic> surface;  // the local fit
  Eigen::VectorXd residual_rms_mm;  // sqrt(RSS / (n - p)) of the fit

  // Every window is complete, so (A^T A)^-1 is the same for all points: Cov(coefficients) =
  // z_noise_sigma_mm^2 * fit_cofactor (zero rows and columns for unused coefficients).
  Eigen::Matrix<double, kSurfaceCoefficients, kSurfaceCoefficients> fit_cofactor =
      Eigen::Matrix<double, kSurfaceCoefficients, kSurfaceCoefficients>::Zero();
  double z_noise_sigma_mm = 0.0;  // the view's z noise (given or estimated)

  int size() const { return static_cast<int>(position_mm.cols()); }
  // Point index at grid cell (u, v), -1 when outside the grid or not a control point.
  int point_at_cell(int u, int v) const {
    if (u < 0 || v < 0 || u >= grid_width || v >= grid_height) return -1;
    return cell_point[static_cast<std::size_t>(v) * grid_width + u];
  }
};

enum class RegistrationPointsStatus { kOk, kInvalidParameters, kTooFewPoints };

struct RegistrationPointsResult {
  RegistrationPointsStatus status = RegistrationPointsStatus::kOk;
  RegistrationPoints points;
};

// The points at `indices` (in that order), as scene points: positions, normals, fits and
// residuals, without the model-side grid lookup.
RegistrationPoints select_points(const RegistrationPoints& points, const std::vector<int>& indices);
// Every `step`-th point, so that about `count` remain (all of them when fewer): an evenly
// spread subset, since points are in grid order.
RegistrationPoints spread_subset(const RegistrationPoints& points, int count);
std::vector<int> spread_indices(int size, int count);  // the indices spread_subset keeps
// The indices of `count` points (all of them when fewer), ascending, chosen one after another
// as the point farthest from those chosen before, the first the farthest from the points'
// centroid: a subset that reaches the scene's ends and its small features. An even subset of
// a scene most of which is one large face lies nearly all on that face, and every pose that
// puts the face on some flat face of a part scores alike on it.
std::vector<int> farthest_point_indices(const RegistrationPoints& points, int count);

// Fits every stride-th pixel whose full window has data and no depth jump, and keeps the
// smooth, not-grazing ones (§6.7.1). With `frames`, the normal of a control point
// is the Darboux-frame normal of the (bicubic) local fit where that fit is valid, which is
// more accurate on curved surfaces than the plane's; the fit still gives d_s's variance.
RegistrationPointsResult build_registration_points(const RangeImage& image,
                                                   const RegistrationPointParameters& parameters,
                                                   const DarbouxFrameField* frames = nullptr);

}  // namespace cosmos
