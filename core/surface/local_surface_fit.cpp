#include "core/surface/local_surface_fit.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <stdexcept>
#include <utility>

#include "core/surface/window_monomials.hpp"

namespace cosmos {
namespace {

int half_window_of(const SurfaceFitParameters& parameters) {
  return std::clamp(parameters.window_size / 2, 1, LocalSurfaceFitter::kMaxWindowSize / 2);
}

// Derivatives at (u, v) of the monomials, as rows z, z_u, z_v, z_uu/2, z_uv, z_vv/2 (the
// quadric coefficients of the Taylor expansion at that point).
Eigen::Matrix<double, 6, kBicubicTerms> taylor_rows(double u, double v) {
  Eigen::Matrix<double, 6, kBicubicTerms> t;
  t << 1, u, v, u * u, u * v, v * v, u * u * u, u * u * v, u * v * v, v * v * v,  //
      0, 1, 0, 2 * u, v, 0, 3 * u * u, 2 * u * v, v * v, 0,                       //
      0, 0, 1, 0, u, 2 * v, 0, u * u, 2 * u * v, 3 * v * v,                       //
      0, 0, 0, 1, 0, 0, 3 * u, v, 0, 0,                                           //
      0, 0, 0, 0, 1, 0, 0, 2 * u, 2 * v, 0,                                       //
      0, 0, 0, 0, 0, 1, 0, 0, u, 3 * v;
  return t;
}

// The Darboux frame of the graph surface z(x, y) from its derivatives p = z_x, q = z_y and the
// second derivatives: normal (-p, -q, 1)/w; second fundamental form II with the sign flipped so
// that convex towards +z is positive; M = I^-1 II I^-1 and W = J M J^T with J = [X_u X_v] =
// [[1,0],[0,1],[p,q]], the shape operator as a 3D tensor. Branch-free, so loops over a row of
// pixels vectorize.
template <class Real>
inline FrameValues graph_surface_frame(Real p, Real q, Real zxx, Real zxy, Real zyy) {
  FrameValues f;
  const Real w2 = 1 + p * p + q * q;
  const Real inv_w = 1 / std::sqrt(w2);
  const Real inv_w2 = inv_w * inv_w;
  f[kNx] = static_cast<float>(-p * inv_w);
  f[kNy] = static_cast<float>(-q * inv_w);
  f[kNz] = static_cast<float>(inv_w);
  const Real l = -zxx * inv_w, m = -zxy * inv_w, n = -zyy * inv_w;
  const Real i11 = (1 + q * q) * inv_w2, i12 = -p * q * inv_w2, i22 = (1 + p * p) * inv_w2;
  const Real a11 = i11 * l + i12 * m, a12 = i11 * m + i12 * n;  // I^-1 II
  const Real a21 = i12 * l + i22 * m, a22 = i12 * m + i22 * n;
  const Real m11 = a11 * i11 + a12 * i12, m12 = a11 * i12 + a12 * i22;
  const Real m22 = a21 * i12 + a22 * i22;
  const Real wxz = m11 * p + m12 * q, wyz = m12 * p + m22 * q;
  f[kWxx] = static_cast<float>(m11);
  f[kWxy] = static_cast<float>(m12);
  f[kWxz] = static_cast<float>(wxz);
  f[kWyy] = static_cast<float>(m22);
  f[kWyz] = static_cast<float>(wyz);
  f[kWzz] = static_cast<float>(p * wxz + q * wyz);
  return f;
}

constexpr float kNeutralFrame[kFrameComponents] = {0, 0, 1, 0, 0, 0, 0, 0, 0};

// Frames of a row from the separable fit's quadric terms (pixel units) where fits[c] is 1,
// the neutral frame elsewhere. Every array is a restrict parameter: GCC 12 does not vectorize
// through restrict pointers loaded from an array.
void frames_from_quadrics(int width, float inv_dx, float inv_dy, const float* __restrict fits,
                          const float* __restrict q0, const float* __restrict q1,
                          const float* __restrict q2, const float* __restrict q3,
                          const float* __restrict q4, const float* __restrict q5,
                          float* __restrict nx, float* __restrict ny, float* __restrict nz,
                          float* __restrict wxx, float* __restrict wxy, float* __restrict wxz,
                          float* __restrict wyy, float* __restrict wyz, float* __restrict wzz,
                          float* __restrict z_row) {
  for (int c = 0; c < width; ++c) {
    const bool fit = fits[c] != 0.0f;
    const FrameValues f =
        graph_surface_frame(q1[c] * inv_dx, q2[c] * inv_dy, 2 * q3[c] * inv_dx * inv_dx,
                            q4[c] * inv_dx * inv_dy, 2 * q5[c] * inv_dy * inv_dy);
    nx[c] = fit ? f[kNx] : kNeutralFrame[kNx];
    ny[c] = fit ? f[kNy] : kNeutralFrame[kNy];
    nz[c] = fit ? f[kNz] : kNeutralFrame[kNz];
    wxx[c] = fit ? f[kWxx] : 0.0f;
    wxy[c] = fit ? f[kWxy] : 0.0f;
    wxz[c] = fit ? f[kWxz] : 0.0f;
    wyy[c] = fit ? f[kWyy] : 0.0f;
    wyz[c] = fit ? f[kWyz] : 0.0f;
    wzz[c] = fit ? f[kWzz] : 0.0f;
    z_row[c] = fit ? q0[c] : 0.0f;
  }
}

}  // namespace

void darboux_frame_from_derivatives(const SurfaceDerivatives& d, float* f) {
  const FrameValues values = graph_surface_frame(d.zx, d.zy, d.zxx, d.zxy, d.zyy);
  std::copy(values.begin(), values.end(), f);
}

int LocalSurfaceFitter::window_side(const SurfaceFitParameters& parameters) {
  return 2 * half_window_of(parameters) + 1;
}

PartialWindowKernels LocalSurfaceFitter::partial_window_kernels_for(
    const SurfaceFitParameters& parameters, int entries_log2) {
  return PartialWindowKernels(window_side(parameters), parameters.bicubic, entries_log2);
}

LocalSurfaceFitter::LocalSurfaceFitter(const SurfaceFitParameters& parameters,
                                       double pixel_size_x_mm, double pixel_size_y_mm,
                                       int max_width)
    : LocalSurfaceFitter(
          parameters, pixel_size_x_mm, pixel_size_y_mm, max_width,
          std::make_unique<PartialWindowKernels>(partial_window_kernels_for(parameters)), nullptr) {
}

LocalSurfaceFitter::LocalSurfaceFitter(const SurfaceFitParameters& parameters,
                                       double pixel_size_x_mm, double pixel_size_y_mm,
                                       int max_width, PartialWindowKernels& kernels)
    : LocalSurfaceFitter(parameters, pixel_size_x_mm, pixel_size_y_mm, max_width, nullptr,
                         &kernels) {}

LocalSurfaceFitter::LocalSurfaceFitter(const SurfaceFitParameters& parameters,
                                       double pixel_size_x_mm, double pixel_size_y_mm,
                                       int max_width,
                                       std::unique_ptr<PartialWindowKernels> own_kernels,
                                       PartialWindowKernels* shared_kernels)
    : parameters_(parameters),
      pixel_size_x_mm_(pixel_size_x_mm),
      pixel_size_y_mm_(pixel_size_y_mm),
      half_window_(half_window_of(parameters)),
      side_(2 * half_window_ + 1),
      basis_size_(parameters.bicubic ? kBicubicTerms : kBiquadraticTerms),
      separable_(half_window_, parameters.bicubic ? 3 : 2, max_width),
      own_kernels_(std::move(own_kernels)),
      partial_kernels_(own_kernels_ ? own_kernels_.get() : shared_kernels),
      fits_(static_cast<std::size_t>(std::max(max_width, 1)), 0.0f) {
  if (partial_kernels_->side() != side_ || partial_kernels_->bicubic() != parameters.bicubic)
    throw std::invalid_argument(
        "LocalSurfaceFitter: the shared kernel table is for another fit window");
  const int samples = side_ * side_;
  Eigen::MatrixXd design(samples, basis_size_);
  for (int dv = -half_window_, k = 0; dv <= half_window_; ++dv)
    for (int du = -half_window_; du <= half_window_; ++du, ++k)
      design.row(k) = window_monomials(du, dv).head(basis_size_).transpose();
  const Eigen::MatrixXd pseudo_inverse =
      (design.transpose() * design).ldlt().solve(design.transpose());
  for (int ov = -half_window_; ov <= half_window_; ++ov)
    for (int ou = -half_window_; ou <= half_window_; ++ou)
      offset_kernels_.emplace_back(taylor_rows(-ou, -ov).leftCols(basis_size_) * pseudo_inverse);
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(design);
  residual_basis_ =
      (qr.householderQ() * Eigen::MatrixXd::Identity(samples, basis_size_)).transpose();
}

SurfaceDerivatives LocalSurfaceFitter::to_metric(const QuadricCoefficients& c) const {
  const double dx = pixel_size_x_mm_, dy = pixel_size_y_mm_;
  SurfaceDerivatives d;
  d.z_mm = c[0];
  d.zx = c[1] / dx;
  d.zy = c[2] / dy;
  d.zxx = 2 * c[3] / (dx * dx);
  d.zxy = c[4] / (dx * dy);
  d.zyy = 2 * c[5] / (dy * dy);
  return d;
}

// Samples of the window centred at (window_column, window_row), relative to the depth of the
// pixel (column, row); false when one is missing or lies across a depth jump from the pixel.
bool LocalSurfaceFitter::gather_window(const RangeImage& image, int window_column, int window_row,
                                       int column, int row, WindowSamples& samples) const {
  const int h = half_window_;
  if (window_column < h || window_row < h || window_column + h >= image.width() ||
      window_row + h >= image.height())
    return false;
  const float center = image.z_mm(column, row);
  for (int dv = -h, k = 0; dv <= h; ++dv) {
    const float* z_row = image.z_mm.row(window_row + dv);
    for (int du = -h; du <= h; ++du, ++k) {
      const float z = z_row[window_column + du];
      const int steps =
          std::max(std::abs(window_column + du - column), std::abs(window_row + dv - row));
      if (!(std::abs(z - center) <= parameters_.depth_jump_mm * steps)) return false;
      samples[k] = static_cast<double>(z) - center;
    }
  }
  return true;
}

double LocalSurfaceFitter::residual_sum_of_squares(const WindowSamples& samples) const {
  const int n = side_ * side_;
  double total = 0;
  for (int k = 0; k < n; ++k) total += samples[k] * samples[k];
  // Sample-major over the column-major basis: the inner loop runs down a contiguous column
  // and vectorizes (basis-major order strides through it, several times slower).
  double projection[kBicubicTerms] = {};
  const double* column = residual_basis_.data();
  for (int k = 0; k < n; ++k, column += basis_size_)
    for (int b = 0; b < basis_size_; ++b) projection[b] += column[b] * samples[k];
  for (int b = 0; b < basis_size_; ++b) total -= projection[b] * projection[b];
  return std::max(total, 0.0);
}

LocalSurfaceFitter::QuadricCoefficients LocalSurfaceFitter::apply_kernel(
    int offset_index, const WindowSamples& samples) const {
  const auto& kernel = offset_kernels_[offset_index];
  QuadricCoefficients c = QuadricCoefficients::Zero();
  for (int k = 0; k < side_ * side_; ++k) c += kernel.col(k) * samples[k];
  return c;
}

bool LocalSurfaceFitter::fit_pixel(const RangeImage& image, int column, int row,
                                   SurfaceDerivatives& d) const {
  if (!std::isfinite(image.z_mm(column, row))) return false;
  return fit_crease_window(image, column, row, d) || fit_partial_window(image, column, row, d);
}

// The complete window of the pixel or, when its residual shows a crease, the best-fitting
// shifted complete window that still contains the pixel; false when no complete window fits.
bool LocalSurfaceFitter::fit_crease_window(const RangeImage& image, int column, int row,
                                           SurfaceDerivatives& d) const {
  const float center = image.z_mm(column, row);
  WindowSamples samples;
  const bool centered_complete = gather_window(image, column, row, column, row, samples);
  const int centered = half_window_ * side_ + half_window_;
  int best_offset = -1;
  double best_rss = std::numeric_limits<double>::infinity();
  if (centered_complete) {
    best_offset = centered;
    best_rss = residual_sum_of_squares(samples);
  }
  const double crease_rss =
      parameters_.crease_residual_mm * parameters_.crease_residual_mm * side_ * side_;
  // Only a complete window can reveal a crease by its residual; incomplete ones (borders,
  // holes, depth jumps) are fitted from their valid same-side samples instead.
  if (centered_complete && crease_rss > 0 && best_rss > crease_rss) {
    WindowSamples shifted;
    for (int ov = -half_window_, o = 0; ov <= half_window_; ++ov) {
      for (int ou = -half_window_; ou <= half_window_; ++ou, ++o) {
        if (o == centered || !gather_window(image, column + ou, row + ov, column, row, shifted))
          continue;
        const double rss = residual_sum_of_squares(shifted);
        if (rss < best_rss) {
          best_rss = rss;
          best_offset = o;
          samples = shifted;
        }
      }
    }
  }
  if (best_offset < 0) return false;
  QuadricCoefficients c = apply_kernel(best_offset, samples);
  c[0] += center;
  d = to_metric(c);
  return true;
}

bool LocalSurfaceFitter::fit_partial_window(const RangeImage& image, int column, int row,
                                            SurfaceDerivatives& d) const {
  const float center = image.z_mm(column, row);
  const int h = half_window_;
  WindowSamples samples;
  PartialWindowKernels::Mask valid{};
  int count = 0;
  for (int dv = -h, k = 0; dv <= h; ++dv) {
    for (int du = -h; du <= h; ++du, ++k) {
      samples[static_cast<std::size_t>(k)] = 0.0;
      if (!image.z_mm.contains(column + du, row + dv)) continue;
      const float z = image.z_mm(column + du, row + dv);
      const int steps = std::max(std::abs(du), std::abs(dv));
      if (!(std::abs(z - center) <= parameters_.depth_jump_mm * steps)) continue;
      samples[static_cast<std::size_t>(k)] = static_cast<double>(z) - center;
      valid[static_cast<std::size_t>(k / 64)] |= std::uint64_t{1} << (k % 64);
      ++count;
    }
  }
  if (count < parameters_.min_samples) return false;
  const PartialWindowKernels::Kernel* kernel = partial_kernels_->kernel(valid, count);
  if (kernel == nullptr) return false;
  QuadricCoefficients coefficients = QuadricCoefficients::Zero();
  for (int k = 0; k < side_ * side_; ++k)
    coefficients += kernel->col(k) * samples[static_cast<std::size_t>(k)];
  coefficients[0] += center;
  d = to_metric(coefficients);
  return true;
}

void LocalSurfaceFitter::fit_row(const RangeImage& image, int row, DarbouxFrameField& out) {
  separable_.fit_row(image, row, parameters_.depth_jump_mm);
  const double crease_rss =
      parameters_.crease_residual_mm * parameters_.crease_residual_mm * side_ * side_;
  const double* rss = separable_.residual_sum_of_squares();
  const std::uint8_t* complete = separable_.complete();
  auto separable_fits = [&](int column) {
    return complete[column] && (crease_rss <= 0 || rss[column] <= crease_rss);
  };
  const int width = image.width();
  float* frame_row[kFrameComponents];
  for (int m = 0; m < kFrameComponents; ++m) frame_row[m] = out.frame[m].row(row);
  float* z_row = out.position_mm[2].row(row);
  std::uint8_t* valid_row = out.valid.row(row);
  float* x_row = out.position_mm[0].row(row);
  for (int column = 0; column < width; ++column)
    x_row[column] = static_cast<float>(image.x_mm(column));
  std::fill(out.position_mm[1].row(row), out.position_mm[1].row(row) + width,
            static_cast<float>(image.y_mm(row)));
  // Complete, crease-free windows: the separable fit, in a vectorized kernel over the row.
  for (int column = 0; column < width; ++column)
    fits_[column] = separable_fits(column) ? 1.0f : 0.0f;
  const float* q[SeparableWindowFit::kQuadricTerms];
  for (int t = 0; t < SeparableWindowFit::kQuadricTerms; ++t) q[t] = separable_.quadric(t);
  frames_from_quadrics(width, static_cast<float>(1 / pixel_size_x_mm_),
                       static_cast<float>(1 / pixel_size_y_mm_), fits_.data(), q[0], q[1], q[2],
                       q[3], q[4], q[5], frame_row[kNx], frame_row[kNy], frame_row[kNz],
                       frame_row[kWxx], frame_row[kWxy], frame_row[kWxz], frame_row[kWyy],
                       frame_row[kWyz], frame_row[kWzz], z_row);
  for (int column = 0; column < width; ++column) valid_row[column] = fits_[column] != 0.0f ? 1 : 0;
  // The rest (borders, holes, depth jumps, creases) pixel by pixel.
  for (int column = 0; column < width; ++column) {
    if (fits_[column] != 0.0f) continue;
    SurfaceDerivatives d;
    if (!fit_pixel(image, column, row, d)) continue;
    float frame[kFrameComponents];
    darboux_frame_from_derivatives(d, frame);
    for (int m = 0; m < kFrameComponents; ++m) frame_row[m][column] = frame[m];
    z_row[column] = static_cast<float>(d.z_mm);
    valid_row[column] = 1;
  }
}

namespace {

// Bit `bit` of mask[c] for the columns [begin, end) whose neighbour at c + dc (in the row
// `z_neighbor`, `valid_neighbor`) is valid and within `jump` of the pixel. Plain restrict
// parameters and a column-inner loop, so it vectorizes.
void link_direction(int begin, int end, int dc, float jump, std::uint8_t bit,
                    const float* __restrict z_center, const std::uint8_t* __restrict valid_center,
                    const float* __restrict z_neighbor,
                    const std::uint8_t* __restrict valid_neighbor, std::uint8_t* __restrict mask) {
  for (int c = begin; c < end; ++c) {
    const bool linked = (valid_center[c] != 0) & (valid_neighbor[c + dc] != 0) &
                        (std::abs(z_neighbor[c + dc] - z_center[c]) <= jump);
    mask[c] = static_cast<std::uint8_t>(mask[c] | (linked ? bit : 0));
  }
}

}  // namespace

void LocalSurfaceFitter::link_row(const RangeImage& image, int row, DarbouxFrameField& out) const {
  const int width = image.width(), height = image.height();
  const float jump = static_cast<float>(parameters_.depth_jump_mm);
  std::uint8_t* mask_row = out.same_side.row(row);
  std::fill(mask_row, mask_row + width, 0);
  const float* z_center = image.z_mm.row(row);
  const std::uint8_t* valid_center = out.valid.row(row);
  for (int k = 0; k < 8; ++k) {
    const int neighbor_row = row + kNeighborOffsets[k].row, dc = kNeighborOffsets[k].column;
    if (neighbor_row < 0 || neighbor_row >= height) continue;
    // Columns whose neighbour in this direction lies inside the image.
    const int begin = std::max(0, -dc), end = std::min(width, width - dc);
    link_direction(begin, end, dc, jump, static_cast<std::uint8_t>(1u << k), z_center, valid_center,
                   image.z_mm.row(neighbor_row), out.valid.row(neighbor_row), mask_row);
  }
}

namespace {

void fit_rows(const RangeImage& image, LocalSurfaceFitter& fitter, DarbouxFrameField& field) {
  for (int row = 0; row < image.height(); ++row) fitter.fit_row(image, row, field);
  for (int row = 0; row < image.height(); ++row) fitter.link_row(image, row, field);
}

}  // namespace

void fit_local_surfaces(const RangeImage& image, const SurfaceFitParameters& parameters,
                        DarbouxFrameField& field) {
  LocalSurfaceFitter fitter(parameters, image.pixel_size_x_mm, image.pixel_size_y_mm,
                            image.width());
  fit_rows(image, fitter, field);
}

void fit_local_surfaces(const RangeImage& image, const SurfaceFitParameters& parameters,
                        DarbouxFrameField& field, PartialWindowKernels& kernels) {
  LocalSurfaceFitter fitter(parameters, image.pixel_size_x_mm, image.pixel_size_y_mm, image.width(),
                            kernels);
  fit_rows(image, fitter, field);
}

DarbouxFrameField fit_local_surfaces(const RangeImage& image,
                                     const SurfaceFitParameters& parameters) {
  DarbouxFrameField field(image.width(), image.height());
  fit_local_surfaces(image, parameters, field);
  return field;
}

}  // namespace cosmos
