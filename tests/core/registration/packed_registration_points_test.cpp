// The model base's compact form of a view's registration points: pack, unpack, the rounding
// the header states (each fit coefficient within half a step of kStepPerSigma times its noise
// standard deviation), the size it reaches on a noisy surface, and streams that are damaged
// or crafted: they are told from consistent ones, and whatever their bits they decode to
// values within their view's bounds.
#include "core/registration/packed_registration_points.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "core/registration/registration_points.hpp"
#include "core/registration/rice_bit_stream.hpp"
#include "sim/analytic_surface.hpp"

namespace cosmos::testing {
namespace {

// A sphere cap 80 mm above the belt seen at stride 1 and 3, with a hole: curved (every
// coefficient in use), with empty cells inside the grid as well as around it.
RegistrationPoints sphere_points(int stride_px, bool quadric_fit = true) {
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
  parameters.quadric_fit = quadric_fit;
  return build_registration_points(sphere.range, parameters).points;
}

double noise_step(const RegistrationPoints& points, int coefficient) {
  return kStepPerSigma * std::max(points.z_noise_sigma_mm, kMinNoiseSigmaMm) *
         std::sqrt(points.fit_cofactor(coefficient, coefficient));
}

TEST(PackedRegistrationPoints, RoundTripKeepsTheGridAndRoundsWithinHalfANoiseStep) {
  for (int stride : {1, 3}) {
    SCOPED_TRACE("stride " + std::to_string(stride));
    const RegistrationPoints points = sphere_points(stride);
    ASSERT_GT(points.size(), 400);
    const PackedRegistrationPoints packed = pack_registration_points(points);
    ASSERT_TRUE(packed_registration_points_consistent(packed));
    EXPECT_EQ(packed.size(), points.size());
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

    for (int c = 0; c < kSurfaceCoefficients; ++c) {
      const double step = noise_step(points, c);
      ASSERT_GT(step, 0.0) << c;
      EXPECT_DOUBLE_EQ(packed.coefficients[static_cast<std::size_t>(c)].step, step) << c;
      double worst = 0;
      for (int i = 0; i < points.size(); ++i)
        worst = std::max(worst, std::abs(unpacked.surface(c, i) - points.surface(c, i)));
      EXPECT_LE(worst, 0.5 * step * (1 + 1e-9)) << c;
      EXPECT_GT(worst, 0.25 * step) << c << ": the values were rounded, not kept";
    }
    // The height's step is a small fraction of the 0.02 mm noise.
    EXPECT_LT(noise_step(points, kHeight), 0.01);
    for (int i = 0; i < points.size(); ++i) {
      // x, y are the cell centre, z the fit's height; the normal is the fit's tangent plane's,
      // the residual the view's noise.
      ASSERT_NEAR(unpacked.position_mm(0, i), points.position_mm(0, i), 1e-12);
      ASSERT_NEAR(unpacked.position_mm(1, i), points.position_mm(1, i), 1e-12);
      ASSERT_EQ(unpacked.position_mm(2, i), unpacked.surface(kHeight, i));
      const Eigen::Vector3d tangent_normal =
          Eigen::Vector3d(-unpacked.surface(kSlopeX, i), -unpacked.surface(kSlopeY, i), 1.0)
              .normalized();
      ASSERT_NEAR((unpacked.normal.col(i) - tangent_normal).norm(), 0.0, 1e-12);
      ASSERT_EQ(unpacked.residual_rms_mm(i), points.z_noise_sigma_mm);
    }
  }
}

// The coding is what makes the base small: on this noisy sphere well under the 24 bytes per
// point of float heights and slopes with 16-bit curvatures, normals and residuals.
TEST(PackedRegistrationPoints, ANoisyCurvedViewTakesAFewBytesPerPoint) {
  const RegistrationPoints points = sphere_points(3);
  const PackedRegistrationPoints packed = pack_registration_points(points);
  const double bytes_per_point =
      static_cast<double>(packed.packed_bytes()) / static_cast<double>(points.size());
  EXPECT_LT(bytes_per_point, 5.0);
  EXPECT_GT(bytes_per_point, 1.0);  // the noise itself cannot be coded away
}

TEST(PackedRegistrationPoints, ThePlaneFitsUnusedCoefficientsStayZeroAtNoCost) {
  const RegistrationPoints points = sphere_points(3, false);
  const PackedRegistrationPoints packed = pack_registration_points(points);
  for (int c : {kCurveXX, kCurveXY, kCurveYY})
    EXPECT_EQ(packed.coefficients[static_cast<std::size_t>(c)].step, 0.0) << c;
  const RegistrationPoints unpacked = unpack_registration_points(packed);
  ASSERT_EQ(unpacked.size(), points.size());
  EXPECT_EQ(unpacked.surface.bottomRows<3>().cwiseAbs().maxCoeff(), 0.0);
  for (int c : {kHeight, kSlopeX, kSlopeY})
    EXPECT_LE((unpacked.surface.row(c) - points.surface.row(c)).cwiseAbs().maxCoeff(),
              0.5 * noise_step(points, c) * (1 + 1e-9));
}

TEST(PackedRegistrationPoints, PackedStreamsOutliveThePointsTheyCameFrom) {
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

TEST(PackedRegistrationPoints, InconsistentHeadersAndRunsAreDetected) {
  const PackedRegistrationPoints packed = pack_registration_points(sphere_points(3));
  ASSERT_TRUE(packed_registration_points_consistent(packed));

  PackedRegistrationPoints more_points = packed;
  ++more_points.point_count;
  EXPECT_FALSE(packed_registration_points_consistent(more_points));
  PackedRegistrationPoints fewer_points = packed;
  --fewer_points.point_count;
  EXPECT_FALSE(packed_registration_points_consistent(fewer_points));

  PackedRegistrationPoints short_runs = packed;
  short_runs.occupancy_runs = packed.occupancy_runs.first(packed.occupancy_runs.size() / 2);
  EXPECT_FALSE(packed_registration_points_consistent(short_runs));

  PackedRegistrationPoints wider = packed;
  ++wider.grid_width;
  EXPECT_FALSE(packed_registration_points_consistent(wider));
  PackedRegistrationPoints negative = packed;
  negative.grid_width = -1;
  EXPECT_FALSE(packed_registration_points_consistent(negative));

  const auto with_coding = [&](auto change) {
    PackedRegistrationPoints changed = packed;
    change(changed.coefficients[kSlopeX]);
    return packed_registration_points_consistent(changed);
  };
  EXPECT_FALSE(with_coding([](CoefficientCoding& c) { c.low = c.high + 1; }));
  EXPECT_FALSE(with_coding([](CoefficientCoding& c) { c.predictor = kCoefficientPredictors; }));
  EXPECT_FALSE(with_coding([](CoefficientCoding& c) { c.rice_bits = kMaxRiceBits + 1; }));
  EXPECT_FALSE(with_coding([](CoefficientCoding& c) { c.step = -1; }));
  EXPECT_FALSE(with_coding([](CoefficientCoding& c) { c.step = std::nan(""); }));
  EXPECT_FALSE(with_coding([](CoefficientCoding& c) { c.high = 1 << 29; }));
  EXPECT_FALSE(with_coding([](CoefficientCoding& c) { c.ratio_x = -(1 << 30) - 1; }));
  EXPECT_FALSE(with_coding([](CoefficientCoding& c) { ++c.stream_bytes; }));
}

// Coefficient bits are not checked on loading (a stream cut short or crafted still decodes):
// every decoded value is clamped into its coefficient's [low, high] steps, which the
// model-base range checks bound.
TEST(PackedRegistrationPoints, AnyCoefficientBitsDecodeWithinTheViewsBounds) {
  const PackedRegistrationPoints packed = pack_registration_points(sphere_points(3));
  std::mt19937 generator(5);
  std::vector<std::uint8_t> noise(packed.coefficient_bits.size());
  for (std::uint8_t& byte : noise) byte = static_cast<std::uint8_t>(generator());
  for (std::size_t length : {noise.size(), noise.size() / 3, std::size_t{0}}) {
    PackedRegistrationPoints crafted = packed;
    crafted.coefficient_bits = std::span<const std::uint8_t>(noise).first(length);
    const RegistrationPoints unpacked = unpack_registration_points(crafted);
    ASSERT_EQ(unpacked.size(), packed.size());
    ASSERT_TRUE(unpacked.surface.allFinite());
    for (int c = 0; c < kSurfaceCoefficients; ++c) {
      const CoefficientCoding& coding = packed.coefficients[static_cast<std::size_t>(c)];
      const double low = coding.low * coding.step, high = coding.high * coding.step;
      EXPECT_GE(unpacked.surface.row(c).minCoeff(), low - 1e-12 * std::abs(low)) << c;
      EXPECT_LE(unpacked.surface.row(c).maxCoeff(), high + 1e-12 * std::abs(high)) << c;
    }
  }
}

// Two points in a 3 x 3 grid: the runs are empty 1, occupied 1, empty 6, occupied 1.
TEST(PackedRegistrationPoints, SparseGridsKeepTheirCells) {
  RegistrationPoints points;
  points.grid_width = 3;
  points.grid_height = 3;
  points.cell_point = {-1, 0, -1, -1, -1, -1, -1, -1, 1};
  points.position_mm = Eigen::Matrix3Xd::Zero(3, 2);
  points.normal = Eigen::Matrix3Xd::Zero(3, 2);
  points.normal.row(2).setOnes();
  points.surface =
      Eigen::Matrix<double, kSurfaceCoefficients, Eigen::Dynamic>::Zero(kSurfaceCoefficients, 2);
  points.surface(kHeight, 0) = 4.0;
  points.surface(kHeight, 1) = 6.0;
  points.residual_rms_mm = Eigen::VectorXd::Constant(2, 0.01);
  points.fit_cofactor.diagonal().setConstant(0.25);
  points.z_noise_sigma_mm = 0.02;
  const PackedRegistrationPoints packed = pack_registration_points(points);
  EXPECT_TRUE(packed_registration_points_consistent(packed));
  const RegistrationPoints unpacked = unpack_registration_points(packed);
  EXPECT_EQ(unpacked.cell_point, points.cell_point);
  EXPECT_EQ(unpacked.position_mm.col(0), Eigen::Vector3d(1.0, 0.0, 4.0));  // cell (1, 0)
  EXPECT_EQ(unpacked.position_mm.col(1), Eigen::Vector3d(2.0, 2.0, 6.0));  // cell (2, 2)
  EXPECT_EQ(unpacked.normal.col(1), Eigen::Vector3d(0.0, 0.0, 1.0));
}

TEST(PackedRegistrationPoints, NoiselessAndEmptyViewsSurvive) {
  // No noise and no cofactor: the step falls back to a fraction of the largest value.
  RegistrationPoints flat;
  flat.grid_width = 2;
  flat.grid_height = 1;
  flat.cell_point = {0, 1};
  flat.position_mm = Eigen::Matrix3Xd::Zero(3, 2);
  flat.normal = Eigen::Matrix3Xd::Zero(3, 2);
  flat.surface =
      Eigen::Matrix<double, kSurfaceCoefficients, Eigen::Dynamic>::Zero(kSurfaceCoefficients, 2);
  flat.surface(kHeight, 0) = 100.0;
  flat.surface(kHeight, 1) = -3.0;
  flat.surface(kSlopeX, 1) = 0.5;
  flat.residual_rms_mm = Eigen::VectorXd::Zero(2);
  const RegistrationPoints unpacked = unpack_registration_points(pack_registration_points(flat));
  ASSERT_EQ(unpacked.size(), 2);
  EXPECT_NEAR(unpacked.surface(kHeight, 0), 100.0, 100.0 / (1 << 20));
  EXPECT_NEAR(unpacked.surface(kHeight, 1), -3.0, 100.0 / (1 << 20));
  EXPECT_NEAR(unpacked.surface(kSlopeX, 1), 0.5, 0.5 / (1 << 20));
  EXPECT_EQ(unpacked.residual_rms_mm(0), 0.0);

  const PackedRegistrationPoints empty = pack_registration_points(RegistrationPoints{});
  EXPECT_EQ(empty.size(), 0);
  EXPECT_TRUE(packed_registration_points_consistent(empty));
  EXPECT_EQ(unpack_registration_points(empty).size(), 0);
}

}  // namespace
}  // namespace cosmos::testing
