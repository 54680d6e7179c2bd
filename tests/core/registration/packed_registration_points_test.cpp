// The model base's compact form of a view's registration points: pack, unpack, and the
// rounding the header states (float heights and slopes, int16 curvatures in steps of the
// view's largest |coefficient| / 32767, int16 normals in 1/32767, uint16 residuals).
#include "core/registration/packed_registration_points.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "core/registration/registration_points.hpp"
#include "sim/analytic_surface.hpp"

namespace cosmos::testing {
namespace {

// A sphere cap 80 mm above the belt seen at stride 1 and 3, with a hole: curved (every
// coefficient in use), with empty cells inside the grid as well as around it.
RegistrationPoints sphere_points(int stride_px) {
  AnalyticSurfaceSpec spec;
  spec.shape = AnalyticShape::kSphere;
  spec.radius_mm = 20.0;
  spec.noise_mm = 0.02;
  spec.seed = 3;
  AnalyticSurface sphere = make_analytic_surface(spec);
  for (float& z : sphere.range.z_mm.values()) z += 80.0f;
  for (int row = 30; row < 34; ++row)
    for (int column = 40; column < 45; ++column)
      sphere.range.z_mm(column, row) = std::numeric_limits<float>::quiet_NaN();
  RegistrationPointParameters parameters;
  parameters.stride_px = stride_px;
  return build_registration_points(sphere.range, parameters).points;
}

TEST(PackedRegistrationPoints, RoundTripKeepsTheGridAndRoundsWithinTheStatedSteps) {
  for (int stride : {1, 3}) {
    const RegistrationPoints points = sphere_points(stride);
    ASSERT_GT(points.size(), 400) << stride;
    const PackedRegistrationPoints packed = pack_registration_points(points);
    ASSERT_TRUE(packed_registration_points_consistent(packed));
    EXPECT_EQ(packed.size(), points.size());
    EXPECT_EQ(packed.occupied_bytes(),
              (static_cast<std::size_t>(points.grid_width) * points.grid_height + 7) / 8);
    const RegistrationPoints unpacked = unpack_registration_points(packed);

    // Kept exactly: the grid, which cells hold which point, the fit's covariance, the noise.
    EXPECT_EQ(unpacked.grid_width, points.grid_width);
    EXPECT_EQ(unpacked.grid_height, points.grid_height);
    EXPECT_EQ(unpacked.origin_x_mm, points.origin_x_mm);
    EXPECT_EQ(unpacked.spacing_y_mm, points.spacing_y_mm);
    EXPECT_EQ(unpacked.cell_point, points.cell_point);
    EXPECT_EQ(unpacked.fit_cofactor, points.fit_cofactor);
    EXPECT_EQ(unpacked.z_noise_sigma_mm, points.z_noise_sigma_mm);
    ASSERT_EQ(unpacked.size(), points.size());

    const double curvature_step = points.surface.bottomRows<3>().cwiseAbs().maxCoeff() / 32767.0;
    const double residual_step_mm = points.residual_rms_mm.maxCoeff() / 65535.0;
    EXPECT_DOUBLE_EQ(packed.curvature_step, curvature_step);
    EXPECT_DOUBLE_EQ(packed.residual_step_mm, residual_step_mm);
    // Within a cell (|dx|, |dy| <= 1.2 mm at stride 3) the rounded quadratic terms move the
    // height by at most 0.5 step * 3 * 1.44 mm^2 = 2.16 steps.
    const double in_cell_mm = 1.2;
    double worst_normal_deg = 0, worst_height_mm = 0, worst_in_cell_steps = 0;
    for (int i = 0; i < points.size(); ++i) {
      // x, y are the cell centre; the height is the fit's, as a float.
      EXPECT_NEAR(unpacked.position_mm(0, i), points.position_mm(0, i), 1e-12);
      EXPECT_NEAR(unpacked.position_mm(1, i), points.position_mm(1, i), 1e-12);
      worst_height_mm = std::max(worst_height_mm,
                                 std::abs(unpacked.position_mm(2, i) - points.position_mm(2, i)));
      for (int c : {kSlopeX, kSlopeY})
        ASSERT_NEAR(unpacked.surface(c, i), points.surface(c, i),
                    1e-6 * std::abs(points.surface(c, i)) + 1e-12);
      for (int c : {kCurveXX, kCurveXY, kCurveYY})
        ASSERT_LE(std::abs(unpacked.surface(c, i) - points.surface(c, i)),
                  0.5 * curvature_step * (1 + 1e-9));
      const SurfaceVector difference = unpacked.surface.col(i) - points.surface.col(i);
      worst_in_cell_steps = std::max(
          worst_in_cell_steps,
          std::abs(surface_basis(in_cell_mm, in_cell_mm).tail<3>().dot(difference.tail<3>())) /
              curvature_step);
      ASSERT_NEAR(unpacked.normal(0, i), points.normal(0, i), 0.5 / kNormalUnitsPerOne + 1e-15);
      ASSERT_NEAR(unpacked.normal(1, i), points.normal(1, i), 0.5 / kNormalUnitsPerOne + 1e-15);
      ASSERT_NEAR(unpacked.normal.col(i).norm(), 1.0, 1e-12);
      worst_normal_deg =
          std::max(worst_normal_deg,
                   std::acos(std::min(1.0, unpacked.normal.col(i).dot(points.normal.col(i)))) *
                       180 / std::numbers::pi);
      ASSERT_LE(std::abs(unpacked.residual_rms_mm(i) - points.residual_rms_mm(i)),
                0.5 * residual_step_mm * (1 + 1e-9));
    }
    EXPECT_LT(worst_height_mm, 1e-5);  // a float of ~100 mm
    EXPECT_LE(worst_in_cell_steps, 2.16 + 1e-9);
    EXPECT_LT(worst_normal_deg, 0.003);
  }
}

TEST(PackedRegistrationPoints, PackedArraysOutliveThePointsTheyCameFrom) {
  PackedRegistrationPoints packed;
  int cells = 0;
  {
    const RegistrationPoints points = sphere_points(3);
    packed = pack_registration_points(points);
    cells = points.grid_width * points.grid_height;
  }
  const PackedRegistrationPoints copy = packed;
  packed = PackedRegistrationPoints{};
  ASSERT_TRUE(packed_registration_points_consistent(copy));
  const RegistrationPoints unpacked = unpack_registration_points(copy);
  EXPECT_EQ(static_cast<int>(unpacked.cell_point.size()), cells);
  EXPECT_EQ(unpacked.size(), copy.size());
  EXPECT_GT(unpacked.position_mm.row(2).minCoeff(), 70.0);
}

TEST(PackedRegistrationPoints, InconsistentSpansAreDetected) {
  const PackedRegistrationPoints packed = pack_registration_points(sphere_points(3));
  ASSERT_TRUE(packed_registration_points_consistent(packed));
  const std::size_t n = static_cast<std::size_t>(packed.size());

  PackedRegistrationPoints short_residuals = packed;
  short_residuals.residual = packed.residual.first(n - 1);
  EXPECT_FALSE(packed_registration_points_consistent(short_residuals));

  PackedRegistrationPoints short_normals = packed;
  short_normals.normal_xy = packed.normal_xy.first(2 * n - 2);
  EXPECT_FALSE(packed_registration_points_consistent(short_normals));

  PackedRegistrationPoints short_occupancy = packed;
  short_occupancy.occupied_cells = packed.occupied_cells.first(packed.occupied_cells.size() - 1);
  EXPECT_FALSE(packed_registration_points_consistent(short_occupancy));

  PackedRegistrationPoints negative = packed;
  negative.grid_width = -1;
  EXPECT_FALSE(packed_registration_points_consistent(negative));

  // One more occupied cell than there are points.
  std::vector<std::uint8_t> occupancy(packed.occupied_cells.begin(), packed.occupied_cells.end());
  const auto empty_byte = std::find(occupancy.begin(), occupancy.end(), std::uint8_t{0});
  ASSERT_NE(empty_byte, occupancy.end());
  *empty_byte = 1;
  PackedRegistrationPoints extra_bit = packed;
  extra_bit.occupied_cells = occupancy;
  EXPECT_FALSE(packed_registration_points_consistent(extra_bit));
}

// A bit past the last cell of a grid whose cell count is not a multiple of 8.
TEST(PackedRegistrationPoints, AnOccupancyBitPastTheLastCellIsInconsistent) {
  RegistrationPoints points;
  points.grid_width = 3;
  points.grid_height = 3;  // 9 cells: 2 bytes, 7 spare bits
  points.cell_point = {-1, 0, -1, -1, -1, -1, -1, -1, 1};
  points.position_mm = Eigen::Matrix3Xd::Zero(3, 2);
  points.normal = Eigen::Matrix3Xd::Zero(3, 2);
  points.normal.row(2).setOnes();
  points.surface =
      Eigen::Matrix<double, kSurfaceCoefficients, Eigen::Dynamic>::Zero(kSurfaceCoefficients, 2);
  points.surface(kHeight, 0) = 4.0;
  points.surface(kHeight, 1) = 6.0;
  points.residual_rms_mm = Eigen::VectorXd::Constant(2, 0.01);
  const PackedRegistrationPoints packed = pack_registration_points(points);
  ASSERT_EQ(packed.occupied_cells.size(), 2u);
  EXPECT_EQ(packed.occupied_cells[0], 0b00000010);  // cell 1
  EXPECT_EQ(packed.occupied_cells[1], 0b00000001);  // cell 8
  EXPECT_TRUE(packed_registration_points_consistent(packed));
  const RegistrationPoints unpacked = unpack_registration_points(packed);
  EXPECT_EQ(unpacked.cell_point, points.cell_point);
  EXPECT_EQ(unpacked.position_mm.col(1), Eigen::Vector3d(2.0, 2.0, 6.0));  // cell (2, 2)

  // Moving cell 8's bit to bit 9 keeps the count but leaves a point without a cell.
  std::vector<std::uint8_t> occupancy = {0b00000010, 0b00000010};
  PackedRegistrationPoints past_end = packed;
  past_end.occupied_cells = occupancy;
  EXPECT_FALSE(packed_registration_points_consistent(past_end));
}

TEST(PackedRegistrationPoints, HorizontalNormalsAndEmptyViewsSurvive) {
  RegistrationPoints edge;
  edge.grid_width = 1;
  edge.grid_height = 1;
  edge.cell_point = {0};
  edge.position_mm = Eigen::Matrix3Xd::Zero(3, 1);
  edge.normal = Eigen::Matrix3Xd(3, 1);
  edge.normal.col(0) << 1.0, 0.0, 0.0;  // n_z = 0: not recoverable from sqrt(1 - n_x^2 - n_y^2) > 0
  edge.surface =
      Eigen::Matrix<double, kSurfaceCoefficients, Eigen::Dynamic>::Zero(kSurfaceCoefficients, 1);
  edge.residual_rms_mm = Eigen::VectorXd::Zero(1);
  const RegistrationPoints unpacked = unpack_registration_points(pack_registration_points(edge));
  EXPECT_EQ(unpacked.normal.col(0), Eigen::Vector3d(1.0, 0.0, 0.0));
  EXPECT_EQ(unpacked.residual_rms_mm(0), 0.0);  // a zero step leaves zeros, not NaN

  const PackedRegistrationPoints empty = pack_registration_points(RegistrationPoints{});
  EXPECT_EQ(empty.size(), 0);
  EXPECT_TRUE(packed_registration_points_consistent(empty));
  EXPECT_EQ(unpack_registration_points(empty).size(), 0);
}

}  // namespace
}  // namespace cosmos::testing
