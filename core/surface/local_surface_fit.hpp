#pragma once
// Local surface fit (§3.5.1): per pixel, a least-squares bicubic (or biquadratic) z(x, y) over
// a window; from its derivatives the Darboux frame (normal and Weingarten tensor) with the
// graph-surface formulas. Complete windows use precomputed fixed kernels; windows with
// missing samples or depth jumps fit only the valid same-side samples. A window whose fit
// residual shows it straddles a crease is replaced by the best-fitting shifted window that
// still contains the pixel, so creases do not smear into strips of false curvature (the
// edge-awareness the thesis asks for in §3.5.2 and §7.2.1).
#include <Eigen/Core>
#include <array>
#include <memory>
#include <vector>

#include "core/cosmos_parameters.hpp"
#include "core/range_image.hpp"
#include "core/surface/darboux_frame_field.hpp"
#include "core/surface/partial_window_kernels.hpp"
#include "core/surface/separable_window_fit.hpp"

namespace cosmos {

// First and second derivatives of z(x, y) at a pixel, mm and 1/mm.
struct SurfaceDerivatives {
  double z_mm = 0;
  double zx = 0, zy = 0;
  double zxx = 0, zxy = 0, zyy = 0;
};

// The normal (towards +z) and Weingarten tensor of the graph surface z(x, y), written into
// the nine frame components. Convex towards the sensor is positive.
void darboux_frame_from_derivatives(const SurfaceDerivatives& d, float* frame_components);

class LocalSurfaceFitter {
 public:
  static constexpr int kMaxWindowSize = 11;

  LocalSurfaceFitter(const SurfaceFitParameters& parameters, double pixel_size_x_mm,
                     double pixel_size_y_mm, int max_width);
  // With a kernel table that outlives the fitter and is shared by the fitters of a stream of
  // images, one after another: each image's silhouettes and holes repeat the last one's
  // validity patterns, whose kernels are then solved once, not once per image. Its window must
  // be partial_window_kernels_for(parameters)'s (std::invalid_argument otherwise).
  LocalSurfaceFitter(const SurfaceFitParameters& parameters, double pixel_size_x_mm,
                     double pixel_size_y_mm, int max_width, PartialWindowKernels& kernels);

  // The side of the windows a fitter with `parameters` fits, and a kernel table for them.
  static int window_side(const SurfaceFitParameters& parameters);
  static PartialWindowKernels partial_window_kernels_for(
      const SurfaceFitParameters& parameters,
      int entries_log2 = PartialWindowKernels::kImageEntriesLog2);

  // Fits row `row` of the image into `out` (needs image rows row +- window size). Fitting
  // rows in increasing order reuses the separable row filters.
  void fit_row(const RangeImage& image, int row, DarbouxFrameField& out);
  // Before fitting another image with the same fitter.
  void reset() { separable_.reset(); }
  // Same-side masks of row `row`; needs the fits of rows row-1 .. row+1.
  void link_row(const RangeImage& image, int row, DarbouxFrameField& out) const;

 private:
  LocalSurfaceFitter(const SurfaceFitParameters& parameters, double pixel_size_x_mm,
                     double pixel_size_y_mm, int max_width,
                     std::unique_ptr<PartialWindowKernels> own_kernels,
                     PartialWindowKernels* shared_kernels);

  using WindowSamples = std::array<double, kMaxWindowSize * kMaxWindowSize>;
  using QuadricCoefficients = Eigen::Matrix<double, 6, 1>;

  bool fit_pixel(const RangeImage& image, int column, int row, SurfaceDerivatives& d) const;
  bool fit_crease_window(const RangeImage& image, int column, int row, SurfaceDerivatives& d) const;
  bool gather_window(const RangeImage& image, int window_column, int window_row, int column,
                     int row, WindowSamples& samples) const;
  double residual_sum_of_squares(const WindowSamples& samples) const;
  QuadricCoefficients apply_kernel(int offset_index, const WindowSamples& samples) const;
  bool fit_partial_window(const RangeImage& image, int column, int row,
                          SurfaceDerivatives& d) const;
  SurfaceDerivatives to_metric(const QuadricCoefficients& pixel_unit_coefficients) const;

  SurfaceFitParameters parameters_;
  double pixel_size_x_mm_;
  double pixel_size_y_mm_;
  int half_window_;
  int side_;
  int basis_size_;
  // Per window offset (window centre - pixel): rows give z, z_u, z_v, z_uu/2, z_uv, z_vv/2
  // at the pixel (u, v in pixel steps); columns are the window samples.
  std::vector<Eigen::Matrix<double, 6, Eigen::Dynamic>> offset_kernels_;
  // Orthonormal basis of the polynomial space over the window (rows): residual = |z|^2 - |Q z|^2.
  Eigen::MatrixXd residual_basis_;
  SeparableWindowFit separable_;
  // A cache whose contents never change a result: the fitter's own, or a shared one.
  std::unique_ptr<PartialWindowKernels> own_kernels_;
  PartialWindowKernels* partial_kernels_;
  std::vector<float> fits_;  // per column of the current row: 1 where the separable fit holds
};

DarbouxFrameField fit_local_surfaces(const RangeImage& image,
                                     const SurfaceFitParameters& parameters);
// Into a field of the image's size (every pixel is written): no allocation of the field.
void fit_local_surfaces(const RangeImage& image, const SurfaceFitParameters& parameters,
                        DarbouxFrameField& field);
// The same with a shared kernel table (the fitter's constructor above).
void fit_local_surfaces(const RangeImage& image, const SurfaceFitParameters& parameters,
                        DarbouxFrameField& field, PartialWindowKernels& kernels);

}  // namespace cosmos
