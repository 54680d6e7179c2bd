#include "core/registration/packed_registration_points.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <vector>

namespace cosmos {
namespace {

constexpr int kPlaneValues = 3;      // kHeight, kSlopeX, kSlopeY
constexpr int kCurvatureValues = 3;  // kCurveXX, kCurveXY, kCurveYY
constexpr double kOnePerNormalUnit = 1.0 / kNormalUnitsPerOne;
static_assert(kHeight == 0 && kSlopeX == 1 && kSlopeY == 2 && kCurveXX == 3 &&
              kSurfaceCoefficients == 6);

// One allocation holding every array of a packed view, so a built base keeps one block per
// view like a loaded one keeps one block for all views.
struct PackedArrays {
  std::vector<std::uint8_t> occupied_cells;
  std::vector<float> plane;
  std::vector<std::int16_t> curvature;
  std::vector<std::int16_t> normal_xy;
  std::vector<std::uint16_t> residual;
};

template <class Integer>
Integer quantize(double value, double step) {
  if (!(step > 0)) return 0;
  const double units = std::round(value / step);
  return static_cast<Integer>(
      std::clamp(units, static_cast<double>(std::numeric_limits<Integer>::lowest()),
                 static_cast<double>(std::numeric_limits<Integer>::max())));
}

}  // namespace

PackedRegistrationPoints pack_registration_points(const RegistrationPoints& points) {
  PackedRegistrationPoints packed;
  packed.grid_width = points.grid_width;
  packed.grid_height = points.grid_height;
  packed.origin_x_mm = points.origin_x_mm;
  packed.origin_y_mm = points.origin_y_mm;
  packed.spacing_x_mm = points.spacing_x_mm;
  packed.spacing_y_mm = points.spacing_y_mm;
  packed.fit_cofactor = points.fit_cofactor;
  packed.z_noise_sigma_mm = points.z_noise_sigma_mm;

  const int n = points.size();
  const std::size_t count = static_cast<std::size_t>(n);
  if (n > 0) {
    packed.curvature_step =
        points.surface.bottomRows<kCurvatureValues>().cwiseAbs().maxCoeff() / 32767.0;
    packed.residual_step_mm = points.residual_rms_mm.maxCoeff() / 65535.0;
  }
  auto arrays = std::make_shared<PackedArrays>();
  arrays->occupied_cells.assign(packed.occupied_bytes(), 0);
  for (std::size_t cell = 0; cell < points.cell_point.size(); ++cell) {
    if (points.cell_point[cell] >= 0)
      arrays->occupied_cells[cell / 8] |= static_cast<std::uint8_t>(1u << (cell % 8));
  }
  arrays->plane.resize(count * kPlaneValues);
  arrays->curvature.resize(count * kCurvatureValues);
  arrays->normal_xy.resize(count * 2);
  arrays->residual.resize(count);
  for (int i = 0; i < n; ++i) {
    const std::size_t k = static_cast<std::size_t>(i);
    for (int c = 0; c < kPlaneValues; ++c)
      arrays->plane[k * kPlaneValues + static_cast<std::size_t>(c)] =
          static_cast<float>(points.surface(c, i));
    for (int c = 0; c < kCurvatureValues; ++c)
      arrays->curvature[k * kCurvatureValues + static_cast<std::size_t>(c)] =
          quantize<std::int16_t>(points.surface(kCurveXX + c, i), packed.curvature_step);
    for (int c = 0; c < 2; ++c)
      arrays->normal_xy[2 * k + static_cast<std::size_t>(c)] =
          quantize<std::int16_t>(points.normal(c, i), 1.0 / kNormalUnitsPerOne);
    arrays->residual[k] =
        quantize<std::uint16_t>(points.residual_rms_mm(i), packed.residual_step_mm);
  }
  packed.occupied_cells = arrays->occupied_cells;
  packed.plane = arrays->plane;
  packed.curvature = arrays->curvature;
  packed.normal_xy = arrays->normal_xy;
  packed.residual = arrays->residual;
  packed.storage = std::move(arrays);
  return packed;
}

bool packed_registration_points_consistent(const PackedRegistrationPoints& packed) {
  if (packed.grid_width < 0 || packed.grid_height < 0) return false;
  if (packed.occupied_cells.size() != packed.occupied_bytes()) return false;
  const std::size_t n = packed.residual.size();
  if (packed.plane.size() != n * kPlaneValues || packed.curvature.size() != n * kCurvatureValues ||
      packed.normal_xy.size() != 2 * n)
    return false;
  std::size_t set_bits = 0;
  for (std::uint8_t byte : packed.occupied_cells)
    set_bits += static_cast<std::size_t>(std::popcount(byte));
  // Bits past the last cell must be clear, or a point would have no cell.
  const std::size_t cells =
      static_cast<std::size_t>(packed.grid_width) * static_cast<std::size_t>(packed.grid_height);
  if (cells % 8 != 0 && !packed.occupied_cells.empty() &&
      (packed.occupied_cells.back() >> (cells % 8)) != 0)
    return false;
  return set_bits == n;
}

RegistrationPoints unpack_registration_points(const PackedRegistrationPoints& packed) {
  RegistrationPoints points;
  points.grid_width = packed.grid_width;
  points.grid_height = packed.grid_height;
  points.origin_x_mm = packed.origin_x_mm;
  points.origin_y_mm = packed.origin_y_mm;
  points.spacing_x_mm = packed.spacing_x_mm;
  points.spacing_y_mm = packed.spacing_y_mm;
  points.fit_cofactor = packed.fit_cofactor;
  points.z_noise_sigma_mm = packed.z_noise_sigma_mm;

  const int n = packed.size();
  points.position_mm.resize(3, n);
  points.normal.resize(3, n);
  points.surface.resize(kSurfaceCoefficients, n);
  points.residual_rms_mm.resize(n);
  const std::size_t cells =
      static_cast<std::size_t>(packed.grid_width) * static_cast<std::size_t>(packed.grid_height);
  points.cell_point.assign(cells, -1);
  // The occupied cells are sparse in the grid: whole empty bytes are skipped, and the set bits
  // of the others visited in increasing order.
  int i = 0;
  for (std::size_t byte = 0; byte < packed.occupied_cells.size() && i < n; ++byte) {
    for (unsigned bits = packed.occupied_cells[byte]; bits != 0 && i < n; bits &= bits - 1) {
      const std::size_t cell = byte * 8 + static_cast<std::size_t>(std::countr_zero(bits));
      if (cell >= cells) break;
      const std::size_t k = static_cast<std::size_t>(i);
      points.cell_point[cell] = i;
      for (int c = 0; c < kPlaneValues; ++c)
        points.surface(c, i) = packed.plane[k * kPlaneValues + static_cast<std::size_t>(c)];
      for (int c = 0; c < kCurvatureValues; ++c)
        points.surface(kCurveXX + c, i) =
            packed.curvature_step *
            packed.curvature[k * kCurvatureValues + static_cast<std::size_t>(c)];
      const int u = static_cast<int>(cell % static_cast<std::size_t>(packed.grid_width));
      const int v = static_cast<int>(cell / static_cast<std::size_t>(packed.grid_width));
      points.position_mm.col(i) << packed.origin_x_mm + u * packed.spacing_x_mm,
          packed.origin_y_mm + v * packed.spacing_y_mm, points.surface(kHeight, i);
      // Multiplications, not divisions: the loop runs over every point of every view unpacked.
      const double nx = packed.normal_xy[2 * k] * kOnePerNormalUnit;
      const double ny = packed.normal_xy[2 * k + 1] * kOnePerNormalUnit;
      const double nz2 = 1.0 - nx * nx - ny * ny;
      if (nz2 > 0) {
        points.normal.col(i) << nx, ny, std::sqrt(nz2);  // unit by construction
      } else {
        points.normal.col(i) = Eigen::Vector3d(nx, ny, 0.0).normalized();
      }
      points.residual_rms_mm(i) = packed.residual_step_mm * packed.residual[k];
      ++i;
    }
  }
  return points;
}

}  // namespace cosmos
