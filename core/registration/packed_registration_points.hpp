#pragma once
// The model base's compact form of a view's registration points (ch. 6 model surface): what
// the model-base file stores and what a loaded base keeps in memory. The recognizer needs the
// full form only for the few candidate views that survive spectral selection (§5.2), so the
// base keeps this form and unpacks a view on demand (BM_UnpackOneView of
// bench/model_base_file_bench.cpp times it; bench/model_base_bench.cpp sizes a whole base).
//
// What is kept is what the model side of registration reads (the tangent-plane search and
// Eq. 6.21's variance, tangent_plane_correspondence.hpp): the grid, which cells hold a point,
// the six fit coefficients per point, the fit's cofactor and the noise. What the grid implies
// is dropped: a point's x, y are its cell's centre, its height the fit's height coefficient.
// What the model side never reads is not kept: an unpacked point's normal is its fit's tangent
// plane normal (-a, -b, 1) / |.| (the normal the correspondence search uses), and its residual
// the view's noise sigma (only scene points are screened by their residual, §6.7.1).
//
// Each coefficient k is fixed-point, an integer multiple of step_k = kStepPerSigma * sigma_k,
// sigma_k = z_noise_sigma_mm * sqrt(fit_cofactor(k, k)) its standard deviation from the
// sensor noise (Eq. 6.21). Why this loses nothing that matters: the rounding error is
// uniform, of variance step_k^2 / 12 = sigma_k^2 / 48, 2 % of the variance the fit already
// has from the noise (1 % of its standard deviation), and unbiased. sigma_k has a floor
// (kMinNoiseSigmaMm) for noiseless views.
//
// The integers are coded in grid (row-major) order, one stream per coefficient, as prediction
// residuals (from the
// neighbouring cells already decoded; integer arithmetic only, so every reader decodes the
// same values) in Rice codes, one parameter per coefficient per view (rice_bit_stream.hpp);
// the occupied cells as run lengths (occupied_cell_runs.hpp). The spans are over `storage`,
// which keeps them alive: either the streams packed here, or the whole loaded model-base file.
#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <memory>
#include <span>

#include "core/registration/registration_points.hpp"

namespace cosmos {

inline constexpr double kStepPerSigma = 0.5;
inline constexpr double kMinNoiseSigmaMm = 1e-3;

// How a coefficient predicts its value from the cells left (L), above (U) and above-left (UL):
// the fallbacks, in order, when a neighbour is empty: L, U, 0.
enum class CoefficientPredictor : std::uint8_t {
  kPlanar,  // L + U - UL: exact for a linear field
  kMean,    // (L + U) / 2: less noise where the field is flat
  // Height and slopes: L's value + spacing x the mean derivative along x of L and this cell
  // (the slope for the height, the curvature for a slope; exact for a quadric), averaged
  // with the same from U along y.
  kDerivativeTrapezoid
};
inline constexpr int kCoefficientPredictors = 3;

struct CoefficientCoding {
  double step = 0.0;     // value = integer * step
  std::int32_t low = 0;  // every integer of the view is clamped into [low, high]
  std::int32_t high = 0;
  std::uint8_t predictor = 0;  // CoefficientPredictor
  std::uint8_t rice_bits = 0;  // Rice parameter k, <= kMaxRiceBits
  // kDerivativeTrapezoid's factors from the sum of two derivative integers to this one's:
  // d(value)/d(derivative) x spacing_mm x step_derivative / step / 2, fixed point with
  // kDerivativeRatioOne = 1 (0 for the curvatures, which have no stored derivative).
  std::int32_t ratio_x = 0;
  std::int32_t ratio_y = 0;
  // This coefficient's stream in coefficient_bits, after those of the coefficients before it:
  // six independent streams, so that decoding one does not wait for the others.
  std::uint32_t stream_bytes = 0;
};

struct PackedRegistrationPoints {
  int grid_width = 0;
  int grid_height = 0;
  double origin_x_mm = 0.0;
  double origin_y_mm = 0.0;
  double spacing_x_mm = 1.0;
  double spacing_y_mm = 1.0;
  int point_count = 0;
  std::span<const std::uint8_t> occupancy_runs;  // empty, occupied, empty, ... cells
  std::span<const std::uint8_t> coefficient_bits;
  std::array<CoefficientCoding, kSurfaceCoefficients> coefficients{};
  Eigen::Matrix<double, kSurfaceCoefficients, kSurfaceCoefficients> fit_cofactor =
      Eigen::Matrix<double, kSurfaceCoefficients, kSurfaceCoefficients>::Zero();
  double z_noise_sigma_mm = 0.0;
  std::shared_ptr<const void> storage;

  int size() const { return point_count; }
  std::size_t packed_bytes() const { return occupancy_runs.size() + coefficient_bits.size(); }
};

inline constexpr std::int32_t kDerivativeRatioOne = 1 << 16;

PackedRegistrationPoints pack_registration_points(const RegistrationPoints& points);

// Inverse of pack_registration_points up to the rounding above. Any streams decode (to values
// within each coefficient's [low, high]); packed_registration_points_consistent tells whether
// they are the ones their header describes, and the model-base reader checks that before.
RegistrationPoints unpack_registration_points(const PackedRegistrationPoints& packed);

// Is the header consistent (grid, steps, bounds, predictors, Rice parameters) and do the
// occupancy runs cover the grid exactly with point_count occupied cells?
bool packed_registration_points_consistent(const PackedRegistrationPoints& packed);

}  // namespace cosmos
