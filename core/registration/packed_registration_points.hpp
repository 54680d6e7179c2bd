#pragma once
// The model base's compact form of a view's registration points (ch. 6 model surface): what
// the model-base file stores and what a loaded base keeps in memory. 20 parts x 320 views
// (§4.5) of RegistrationPoints in doubles would take several GB; the recognizer needs the
// full form only for the few candidate views that survive spectral selection (§5.2), so the
// base keeps this form and unpacks a view on demand (BM_UnpackOneView of
// bench/model_base_file_bench.cpp times it).
//
// What is dropped is what the grid already implies: a point's x, y are its cell's centre and
// its height is the fit's height coefficient; n_z of the unit normal (always towards the
// sensor, n_z > 0) follows from n_x, n_y; cell_point is one occupancy bit per cell, since
// points are stored in grid (row-major) order. Per point 24 bytes (instead of 104):
//   - height and slopes: float, ~1e-5 mm on parts of 200 mm, far below the 0.02 mm noise;
//   - the three quadratic coefficients: int16 in units (steps) of the view's largest
//     |coefficient| / 32767; evaluated within a cell (|dx|, |dy| <= 1.2 mm at stride 3) the
//     rounding moves the height by at most 2.2 steps, 7e-5 mm per 1/mm of that coefficient;
//   - n_x, n_y: int16 in units of 1/32767 (the normal within 0.003 degrees);
//   - the fit residual: uint16 in units of the view's largest residual / 65535.
//
// The arrays are spans over `storage`, which keeps them alive: either the arrays packed
// here, or the whole loaded model-base file (zero-copy: the file's bytes are the base).
#include <Eigen/Core>
#include <cstdint>
#include <memory>
#include <span>

#include "core/registration/registration_points.hpp"

namespace cosmos {

struct PackedRegistrationPoints {
  int grid_width = 0;
  int grid_height = 0;
  double origin_x_mm = 0.0;
  double origin_y_mm = 0.0;
  double spacing_x_mm = 1.0;
  double spacing_y_mm = 1.0;
  std::span<const std::uint8_t> occupied_cells;  // bit (cell % 8) of byte cell / 8, row-major
  std::span<const float> plane;                  // per point: height (mm), slope x, slope y
  std::span<const std::int16_t> curvature;       // per point: xx, xy, yy in curvature_step
  double curvature_step = 0.0;                   // 1/mm per unit
  std::span<const std::int16_t> normal_xy;       // per point: n_x, n_y in 1/32767
  std::span<const std::uint16_t> residual;       // per point, in residual_step_mm
  double residual_step_mm = 0.0;
  Eigen::Matrix<double, kSurfaceCoefficients, kSurfaceCoefficients> fit_cofactor =
      Eigen::Matrix<double, kSurfaceCoefficients, kSurfaceCoefficients>::Zero();
  double z_noise_sigma_mm = 0.0;
  std::shared_ptr<const void> storage;

  int size() const { return static_cast<int>(residual.size()); }
  std::size_t occupied_bytes() const {
    return (static_cast<std::size_t>(grid_width) * static_cast<std::size_t>(grid_height) + 7) / 8;
  }
};

inline constexpr double kNormalUnitsPerOne = 32767.0;

PackedRegistrationPoints pack_registration_points(const RegistrationPoints& points);

// Inverse of pack_registration_points up to the rounding above. The spans must be consistent
// (packed_registration_points_consistent); the model-base reader checks that before.
RegistrationPoints unpack_registration_points(const PackedRegistrationPoints& packed);

// Are the spans consistent with each other and with the grid (sizes per point, one set
// occupancy bit per point, none past the last cell)?
bool packed_registration_points_consistent(const PackedRegistrationPoints& packed);

}  // namespace cosmos
