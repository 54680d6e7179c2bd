// Curvature-consistency smoothing (§3.5.1, core/surface/curvature_consistency.hpp): the
// robust weights of one iteration computed by hand; what is left alone (pixels without
// same-side neighbours, invalid pixels, pixels two steps from any change); on analytic
// surfaces under seeded noise the shape index moves towards the closed-form value, a
// noise-free sphere keeps its curvature, and neither a crease nor a depth jump is smoothed
// across.
#include "core/surface/curvature_consistency.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "core/surface/local_surface_fit.hpp"
#include "tests/core/analytic_fixture.hpp"

namespace cosmos::testing {
namespace {

// A flat field of 1 mm pixels (normals +z, W = 0), every pixel valid and linked to every
// neighbour inside the image.
DarbouxFrameField flat_field(int width, int height) {
  DarbouxFrameField field(width, height);
  for (int row = 0; row < height; ++row)
    for (int column = 0; column < width; ++column) {
      field.valid(column, row) = 1;
      std::uint8_t mask = 0;
      for (int k = 0; k < 8; ++k)
        if (field.valid.contains(column + kNeighborOffsets[k].column,
                                 row + kNeighborOffsets[k].row))
          mask |= static_cast<std::uint8_t>(1u << k);
      field.same_side(column, row) = mask;
    }
  return field;
}

SmoothingParameters iterations(int count) {
  SmoothingParameters parameters;
  parameters.iterations = count;
  return parameters;
}

// Equal up to the rounding of renormalizing a unit normal in float.
void expect_same_frame(const DarbouxFrameField& field, const DarbouxFrameField& before,
                       std::size_t i) {
  for (int c = 0; c < kFrameComponents; ++c)
    EXPECT_NEAR(field.frame[c][i], before.frame[c][i], 1e-6) << "pixel " << i << ", " << c;
}

double normal_angle_deg(const DarbouxFrameField& field, std::size_t i, Eigen::Vector3d expected) {
  const Eigen::Vector3d n(field.frame[kNx][i], field.frame[kNy][i], field.frame[kNz][i]);
  return std::acos(std::clamp(n.normalized().dot(expected.normalized()), -1.0, 1.0)) * 180.0 /
         std::numbers::pi;
}

TEST(CurvatureConsistency, OneIterationWeighsFlatNeighboursByTheirTensorDisagreement) {
  // The centre of a flat 5x5 field curves with k = 0.04/mm along x. Each flat neighbour
  // predicts the centre's normal exactly (W_j = 0), so only the tensor term weighs it:
  // |W_i - W_j|^2 = 0.04^2, relative to |W_i|^2 + |W_j|^2 + floor^2 = 2 * 0.04^2 (the default
  // floor is 0.04/mm), over curvature_scale^2 = 0.25: weight 1 / (1 + 0.5 / 0.25) = 1/3.
  // Mean tensor: 0.04 * 1 / (1 + 8/3) = 0.12 / 11.
  DarbouxFrameField field = flat_field(5, 5);
  const std::size_t centre = field.valid.index(2, 2);
  field.frame[kWxx][centre] = 0.04f;
  const DarbouxFrameField before = field;
  smooth_curvatures(field, 1.0, 1.0, iterations(1));
  EXPECT_NEAR(field.frame[kWxx][centre], 0.12 / 11, 1e-6);
  for (int c : {kNx, kNy, kWxy, kWxz, kWyy, kWyz, kWzz})
    EXPECT_NEAR(field.frame[c][centre], 0.0f, 1e-7) << c;
  EXPECT_NEAR(field.frame[kNz][centre], 1.0f, 1e-7);
  // One iteration reads only the 8-neighbourhood: pixels two steps away are untouched, the
  // ring around the centre has taken some of its curvature.
  for (int row = 0; row < 5; ++row)
    for (int column = 0; column < 5; ++column) {
      const std::size_t i = field.valid.index(column, row);
      const bool ring = std::max(std::abs(column - 2), std::abs(row - 2)) == 1;
      if (i == centre) continue;
      if (ring) {
        EXPECT_GT(field.frame[kWxx][i], 1e-3f) << column << "," << row;
      } else {
        expect_same_frame(field, before, i);
      }
    }
  // A second iteration reaches them.
  smooth_curvatures(field, 1.0, 1.0, iterations(1));
  EXPECT_GT(field.frame[kWxx][field.valid.index(2, 0)], 1e-4f);
  EXPECT_GT(field.frame[kWxx][field.valid.index(1, 4)], 1e-4f);
}

TEST(CurvatureConsistency, WithoutSameSideNeighboursEveryFrameIsKept) {
  DarbouxFrameField field = flat_field(5, 5);
  for (auto& mask : field.same_side.values()) mask = 0;
  const std::size_t centre = field.valid.index(2, 2);
  field.frame[kWxx][centre] = 0.04f;
  field.frame[kWyy][centre] = -0.01f;
  const DarbouxFrameField before = field;
  smooth_curvatures(field, 1.0, 1.0, iterations(15));
  for (int c = 0; c < kFrameComponents; ++c)
    EXPECT_EQ(field.frame[c].values(), before.frame[c].values()) << c;
}

TEST(CurvatureConsistency, InvalidPixelsKeepTheirFrame) {
  // An invalid pixel in the middle, with a frame unlike its neighbours' and links of its own;
  // its neighbours are not linked to it, as the fit's linking leaves them.
  DarbouxFrameField field = flat_field(5, 5);
  const std::size_t centre = field.valid.index(2, 2);
  field.valid[centre] = 0;
  for (int k = 0; k < 8; ++k)
    field.same_side(2 - kNeighborOffsets[k].column, 2 - kNeighborOffsets[k].row) &=
        static_cast<std::uint8_t>(~(1u << k));
  const float tilted[kFrameComponents] = {0.6f,     0.0f,  0.8f, 0.05f,    0.0f,
                                          -0.0375f, 0.02f, 0.0f, 0.028125f};
  for (int c = 0; c < kFrameComponents; ++c) field.frame[c][centre] = tilted[c];
  const DarbouxFrameField before = field;
  smooth_curvatures(field, 1.0, 1.0, iterations(15));
  for (int c = 0; c < kFrameComponents; ++c) EXPECT_EQ(field.frame[c][centre], tilted[c]) << c;
  for (std::size_t i = 0; i < field.valid.size(); ++i) expect_same_frame(field, before, i);
}

// A 4x4 flat field with three curved pixels, one of them on the left border column.
DarbouxFrameField field_with_curved_pixels() {
  DarbouxFrameField field = flat_field(4, 4);
  field.frame[kWxx][field.valid.index(1, 1)] = 0.04f;
  field.frame[kWyy][field.valid.index(0, 2)] = 0.03f;
  field.frame[kWxx][field.valid.index(3, 3)] = -0.02f;
  field.frame[kWyy][field.valid.index(3, 3)] = -0.01f;
  return field;
}

// `field` inside a margin of invalid, unlinked pixels, `columns` wide left and right and
// `rows` high above and below: the border pixels of `field` become inner ones.
DarbouxFrameField with_invalid_margin(const DarbouxFrameField& field, int columns, int rows) {
  DarbouxFrameField padded(field.width() + 2 * columns, field.height() + 2 * rows);
  for (int row = 0; row < field.height(); ++row)
    for (int column = 0; column < field.width(); ++column) {
      const std::size_t from = field.valid.index(column, row);
      const std::size_t to = padded.valid.index(column + columns, row + rows);
      padded.valid[to] = field.valid[from];
      padded.same_side[to] = field.same_side[from];
      for (int c = 0; c < kFrameComponents; ++c) padded.frame[c][to] = field.frame[c][from];
      for (int c = 0; c < 3; ++c) padded.position_mm[c][to] = field.position_mm[c][from];
    }
  return padded;
}

void expect_smooths_like_inner_pixels(int margin_columns, int margin_rows) {
  DarbouxFrameField field = field_with_curved_pixels();
  DarbouxFrameField padded = with_invalid_margin(field, margin_columns, margin_rows);
  smooth_curvatures(field, 1.0, 1.0, iterations(3));
  smooth_curvatures(padded, 1.0, 1.0, iterations(3));
  for (int row = 0; row < field.height(); ++row)
    for (int column = 0; column < field.width(); ++column)
      for (int c = 0; c < kFrameComponents; ++c)
        EXPECT_NEAR(field.frame[c](column, row),
                    padded.frame[c](column + margin_columns, row + margin_rows), 1e-7)
            << "pixel " << column << "," << row << ", component " << c;
}

TEST(CurvatureConsistency, BorderRowsSmoothLikeInnerRows) {
  expect_smooths_like_inner_pixels(0, 1);
}

// At the first and last columns only the neighbours outside the row may be read in place:
// a kernel that read every neighbour of an end column at its own column fails this.
TEST(CurvatureConsistency, BorderColumnsSmoothLikeInnerColumns) {
  expect_smooths_like_inner_pixels(1, 0);
}

TEST(CurvatureConsistency, ValidColumnExtentSpansTheFirstToTheLastValidPixel) {
  const std::uint8_t row[7] = {0, 0, 1, 1, 0, 1, 0};
  EXPECT_EQ(valid_column_extent(row, 7), (std::array<int, 2>{2, 6}));
  const std::uint8_t full[3] = {1, 1, 1};
  EXPECT_EQ(valid_column_extent(full, 3), (std::array<int, 2>{0, 3}));
  const std::uint8_t none[4] = {0, 0, 0, 0};
  EXPECT_EQ(valid_column_extent(none, 4), (std::array<int, 2>{4, 4}));
}

TEST(CurvatureConsistency, NoisyTorusShapeIndexMovesTowardsTheAnalyticValue) {
  // The torus's shape index varies over the whole scale (cap outside, saddle inside).
  const auto surface = analytic(AnalyticShape::kTorus, 0.02);
  const auto smoothed = analyze(surface, 15);
  const auto raw = analyze(surface, 0);
  double smoothed_error = 0, raw_error = 0;
  int compared = 0;
  for_each_interior(surface, [&](std::size_t i, const AnalyticTruth& truth) {
    if (truth.shape_index > 1 || smoothed.field.label[i] != SurfaceLabel::kCurved ||
        raw.field.label[i] != SurfaceLabel::kCurved)
      return;
    smoothed_error += std::abs(smoothed.field.shape_index[i] - truth.shape_index);
    raw_error += std::abs(raw.field.shape_index[i] - truth.shape_index);
    ++compared;
  });
  ASSERT_GT(compared, 10000);
  EXPECT_LT(smoothed_error / compared, 0.01);
  EXPECT_LT(smoothed_error, 0.25 * raw_error);
}

TEST(CurvatureConsistency, NoisySphereSmoothingHelps) {
  const auto surface = analytic(AnalyticShape::kSphere, 0.02);
  const auto smoothed = analyze(surface, 15);
  const auto raw = analyze(surface, 0);
  std::vector<double> smoothed_values, raw_values;
  for_each_interior(surface, [&](std::size_t i, const AnalyticTruth&) {
    if (smoothed.field.label[i] == SurfaceLabel::kCurved)
      smoothed_values.push_back(smoothed.field.shape_index[i]);
    if (raw.field.label[i] == SurfaceLabel::kCurved) raw_values.push_back(raw.field.shape_index[i]);
  });
  ASSERT_GT(smoothed_values.size(), 4000u);
  EXPECT_GE(median(smoothed_values), 0.97);
  auto spread = [](const std::vector<double>& v) {
    double mean = 0, square = 0;
    for (double s : v) mean += s / v.size();
    for (double s : v) square += (s - mean) * (s - mean) / v.size();
    return std::sqrt(square);
  };
  EXPECT_LT(spread(smoothed_values), 0.5 * spread(raw_values));
}

// A gently curved part under the cell's scanner: a cylinder of 100 mm radius on the 0.4 mm grid
// with 0.02 mm noise. Its curvature (0.01/mm) is a quarter of what that noise alone gives the
// 5x5 fit, so smoothing must not take noise for curvature edges: with a curvature floor far
// below the noise (1e-3/mm) 73 % of these pixels were within 0.05 of the ridge's S_I.
TEST(CurvatureConsistency, GentleNoisyCylinderSmoothsToARidge) {
  AnalyticSurfaceSpec spec;
  spec.shape = AnalyticShape::kCylinder;
  spec.radius_mm = 100.0;
  spec.cylinder_length_mm = 80.0;
  spec.pixel_size_mm = 0.4;
  spec.noise_mm = 0.02;
  spec.seed = 11;
  const AnalyticSurface surface = make_analytic_surface(spec);
  const auto analysis = analyze(surface);
  std::vector<bool> close;
  for_each_interior(surface, [&](std::size_t i, const AnalyticTruth&) {
    close.push_back(analysis.field.label[i] == SurfaceLabel::kCurved &&
                    std::abs(analysis.field.shape_index[i] - 0.75f) <= 0.05f);
  });
  ASSERT_GT(close.size(), 50000u);
  EXPECT_GE(fraction_true(close), 0.85);
}

TEST(CurvatureConsistency, NoiseFreeSphereKeepsItsCurvature) {
  const auto surface = analytic(AnalyticShape::kSphere);  // R = 25 mm: k1 = k2 = 0.04/mm
  const DarbouxFrameField fitted = fit_local_surfaces(surface.range, SurfaceFitParameters{});
  DarbouxFrameField smoothed = fitted;
  smooth_curvatures(smoothed, surface.range.pixel_size_x_mm, surface.range.pixel_size_y_mm,
                    SmoothingParameters{});
  double worst_fitted = 0, worst_smoothed = 0, largest_change = 0, largest_turn_deg = 0;
  int checked = 0;
  for_each_interior(surface, [&](std::size_t i, const AnalyticTruth& truth) {
    const PrincipalCurvatures a = principal_curvatures(fitted, i);
    const PrincipalCurvatures b = principal_curvatures(smoothed, i);
    worst_fitted = std::max({worst_fitted, std::abs(a.kappa1 - 0.04), std::abs(a.kappa2 - 0.04)});
    worst_smoothed =
        std::max({worst_smoothed, std::abs(b.kappa1 - 0.04), std::abs(b.kappa2 - 0.04)});
    largest_change = std::max({largest_change, std::abs(double{b.kappa1} - a.kappa1),
                               std::abs(double{b.kappa2} - a.kappa2)});
    largest_turn_deg =
        std::max(largest_turn_deg, normal_angle_deg(smoothed, i, truth.normal.cast<double>()));
    ++checked;
  });
  ASSERT_GT(checked, 4000);
  EXPECT_LT(largest_change, 0.02 * 0.04);
  EXPECT_LE(worst_smoothed, worst_fitted);
  EXPECT_LT(worst_smoothed, 0.06 * 0.04);
  EXPECT_LT(largest_turn_deg, 0.5);
}

// Two planes of slope -1 and +1 meeting in a crease along y between two pixel columns, with
// 0.02 mm of seeded noise, on 0.5 mm pixels: normals 90 degrees apart.
RangeImage noisy_roof() {
  RangeImage image(61, 41, 0.5, 0.5);
  image.origin_x_mm = -15.25;
  image.origin_y_mm = -10.0;
  std::mt19937_64 random(3);
  std::normal_distribution<double> noise(0.0, 0.02);
  for (int row = 0; row < image.height(); ++row)
    for (int column = 0; column < image.width(); ++column)
      image.z_mm(column, row) =
          static_cast<float>(30.0 - std::abs(image.x_mm(column)) + noise(random));
  return image;
}

// The largest angle between a pixel's normal and its own face's, over pixels 1 to 3 mm from
// the crease (away from the image border).
double largest_face_deviation_deg(const RangeImage& image, const DarbouxFrameField& field) {
  double largest = 0;
  for (int row = 3; row + 3 < image.height(); ++row)
    for (int column = 0; column < image.width(); ++column) {
      const double x = image.x_mm(column);
      if (std::abs(x) < 1.0 || std::abs(x) > 3.0) continue;
      const Eigen::Vector3d face(x < 0 ? -1.0 : 1.0, 0.0, 1.0);  // z = 30 + x, z = 30 - x
      largest = std::max(largest, normal_angle_deg(field, field.valid.index(column, row), face));
    }
  return largest;
}

TEST(CurvatureConsistency, NormalsAreNotAveragedAcrossACrease) {
  const RangeImage image = noisy_roof();
  const DarbouxFrameField fitted = fit_local_surfaces(image, SurfaceFitParameters{});
  DarbouxFrameField smoothed = fitted;
  smooth_curvatures(smoothed, 0.5, 0.5, SmoothingParameters{});
  EXPECT_LT(largest_face_deviation_deg(image, smoothed), 3.0);
  // The same iterations with weights that no longer tell the faces apart (a normal scale of
  // 180 degrees, no tensor term) pull these pixels far off their faces.
  SmoothingParameters indiscriminate;
  indiscriminate.normal_scale_deg = 180.0;
  indiscriminate.curvature_scale = 1e6;
  DarbouxFrameField averaged = fitted;
  smooth_curvatures(averaged, 0.5, 0.5, indiscriminate);
  EXPECT_GT(largest_face_deviation_deg(image, averaged), 10.0);
}

// x < 0: a ridge, the cylinder of radius 20 mm about the axis x = -10 mm (z 13 to 17 mm near
// x = 0); x >= 0: a plane at 40 mm. A depth jump of more than 20 mm between them.
RangeImage ridge_beside_a_raised_plane() {
  RangeImage image(81, 41, 0.5, 0.5);
  image.origin_x_mm = -25.0;
  image.origin_y_mm = -10.0;
  for (int row = 0; row < image.height(); ++row)
    for (int column = 0; column < image.width(); ++column) {
      const double x = image.x_mm(column);
      image.z_mm(column, row) =
          static_cast<float>(x < 0 ? std::sqrt(400.0 - (x + 10) * (x + 10)) : 40.0);
    }
  return image;
}

struct JumpSideErrors {
  double ridge_relative = 0;  // largest |kappa1 - 1/20| * 20 on the ridge side
  double plane_per_mm = 0;    // largest |kappa| on the plane side
};

// Over the pixels within 2 mm of the jump.
JumpSideErrors jump_side_errors(const RangeImage& image, const DarbouxFrameField& field) {
  JumpSideErrors errors;
  for (int row = 3; row + 3 < image.height(); ++row)
    for (int column = 0; column < image.width(); ++column) {
      const double x = image.x_mm(column);
      if (std::abs(x) > 2.0) continue;
      const std::size_t i = field.valid.index(column, row);
      EXPECT_TRUE(field.valid[i]) << column << "," << row;
      const PrincipalCurvatures k = principal_curvatures(field, i);
      if (x < 0) {
        errors.ridge_relative = std::max(errors.ridge_relative, std::abs(k.kappa1 - 0.05) / 0.05);
      } else {
        errors.plane_per_mm =
            std::max({errors.plane_per_mm, std::abs(double{k.kappa1}), std::abs(double{k.kappa2})});
      }
    }
  return errors;
}

TEST(CurvatureConsistency, NothingIsSmoothedAcrossADepthJump) {
  const RangeImage image = ridge_beside_a_raised_plane();
  const DarbouxFrameField fitted = fit_local_surfaces(image, SurfaceFitParameters{});
  DarbouxFrameField smoothed = fitted;
  smooth_curvatures(smoothed, 0.5, 0.5, SmoothingParameters{});
  const JumpSideErrors errors = jump_side_errors(image, smoothed);
  EXPECT_LT(errors.ridge_relative, 0.03);
  EXPECT_LT(errors.plane_per_mm, 1e-6);
  // Linked across the jump, the plane takes the ridge's curvature and the ridge loses some.
  DarbouxFrameField linked = fitted;
  for (int row = 0; row < image.height(); ++row)
    for (int column = 0; column < image.width(); ++column) {
      std::uint8_t mask = 0;
      for (int k = 0; k < 8; ++k) {
        const int c = column + kNeighborOffsets[k].column, r = row + kNeighborOffsets[k].row;
        if (linked.valid.contains(c, r) && linked.valid(c, r))
          mask |= static_cast<std::uint8_t>(1u << k);
      }
      linked.same_side(column, row) = mask;
    }
  smooth_curvatures(linked, 0.5, 0.5, SmoothingParameters{});
  const JumpSideErrors mixed = jump_side_errors(image, linked);
  EXPECT_GT(mixed.ridge_relative, 0.05);
  EXPECT_GT(mixed.plane_per_mm, 0.01);
}

}  // namespace
}  // namespace cosmos::testing
