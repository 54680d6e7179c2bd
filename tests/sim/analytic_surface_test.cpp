// Analytic test surfaces (sim/analytic_surface.hpp): sampled heights, normals, curvatures and
// areas against closed-form formulas written independently here, grid layout, rotation, and
// the seeded noise.
#include "sim/analytic_surface.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numbers>
#include <string>

#include "core/input_error.hpp"

namespace cosmos {
namespace {

constexpr AnalyticShape kAllShapes[] = {
    AnalyticShape::kSphere,    AnalyticShape::kCup,     AnalyticShape::kCylinder,
    AnalyticShape::kSaddle,    AnalyticShape::kPlane,   AnalyticShape::kTorus,
    AnalyticShape::kEllipsoid, AnalyticShape::kCapsule, AnalyticShape::kBoxCorner};

AnalyticSurface make(AnalyticShape shape, double rotate_deg = 0.0, double noise_mm = 0.0,
                     std::uint64_t seed = 1) {
  AnalyticSurfaceSpec spec;
  spec.shape = shape;
  spec.rotate_deg = rotate_deg;
  spec.noise_mm = noise_mm;
  spec.seed = seed;
  return make_analytic_surface(spec);
}

// Calls visit(x, y, truth, z) for every valid pixel.
template <class Visit>
void for_each_valid(const AnalyticSurface& s, Visit&& visit) {
  for (int row = 0; row < s.range.height(); ++row)
    for (int column = 0; column < s.range.width(); ++column)
      if (s.truth(column, row).valid)
        visit(s.range.x_mm(column), s.range.y_mm(row), s.truth(column, row),
              s.range.z_mm(column, row));
}

TEST(AnalyticSurface, ShapeNamesParseAndListTheValidOnes) {
  for (AnalyticShape shape : kAllShapes)
    EXPECT_EQ(parse_analytic_shape(analytic_shape_name(shape)), shape);
  EXPECT_EQ(parse_analytic_shape("box-corner"), AnalyticShape::kBoxCorner);
  EXPECT_EQ(parse_analytic_shape("box_corner"), AnalyticShape::kBoxCorner);
  try {
    parse_analytic_shape("blob");
    ADD_FAILURE() << "blob parsed";
  } catch (const InputError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("'blob'"), std::string::npos) << message;
    EXPECT_NE(message.find("sphere"), std::string::npos) << message;
    EXPECT_NE(message.find("box-corner"), std::string::npos) << message;
  }
}

TEST(AnalyticSurface, SphereMatchesTheFormulaAtEveryPixel) {
  const auto s = make(AnalyticShape::kSphere);  // R = 25 mm, 0.5 mm pixels
  // 50 px to the silhouette, 4 px of margin, each side of the centre pixel.
  EXPECT_EQ(s.range.width(), 109);
  EXPECT_EQ(s.range.height(), 109);
  EXPECT_EQ(s.range.x_mm(54), 0.0);
  EXPECT_EQ(s.range.y_mm(54), 0.0);
  EXPECT_EQ(s.range.z_mm(54, 54), 25.0f);
  const double r = 25.0;
  std::size_t valid = 0;
  for (int row = 0; row < s.range.height(); ++row) {
    for (int column = 0; column < s.range.width(); ++column) {
      const double x = -27.0 + 0.5 * column;
      const double y = -27.0 + 0.5 * row;
      const bool inside = x * x + y * y < r * r;
      ASSERT_EQ(s.truth(column, row).valid, inside) << column << "," << row;
      ASSERT_EQ(std::isfinite(s.range.z_mm(column, row)), inside);
      if (!inside) continue;
      ++valid;
      const auto& t = s.truth(column, row);
      const double z = std::sqrt(r * r - x * x - y * y);
      EXPECT_NEAR(s.range.z_mm(column, row), z, 1e-5);
      EXPECT_NEAR(t.normal.x(), x / r, 1e-6);
      EXPECT_NEAR(t.normal.z(), z / r, 1e-6);
      EXPECT_FLOAT_EQ(t.kappa1, 0.04f);
      EXPECT_FLOAT_EQ(t.kappa2, 0.04f);
      EXPECT_EQ(t.shape_index, 1.0f);
    }
  }
  EXPECT_EQ(valid, s.range.count_valid());
  EXPECT_NEAR(valid * 0.25, std::numbers::pi * r * r, 0.01 * std::numbers::pi * r * r);
}

TEST(AnalyticSurface, CupIsConcave) {
  const auto s = make(AnalyticShape::kCup);
  for_each_valid(s, [](double x, double y, const AnalyticTruth& t, float z) {
    EXPECT_NEAR(z, -std::sqrt(625.0 - x * x - y * y), 1e-5);
    EXPECT_FLOAT_EQ(t.kappa1, -0.04f);
    EXPECT_EQ(t.shape_index, 0.0f);
    EXPECT_GT(t.normal.z(), 0.0f);
    EXPECT_LE(t.normal.x() * x + t.normal.y() * y, 1e-6);  // leans towards the axis
  });
}

TEST(AnalyticSurface, CylinderIsARidgeAlongY) {
  const auto s = make(AnalyticShape::kCylinder);
  double max_y = 0;
  for_each_valid(s, [&](double x, double y, const AnalyticTruth& t, float z) {
    EXPECT_NEAR(z, std::sqrt(625.0 - x * x), 1e-5);
    EXPECT_FLOAT_EQ(t.kappa1, 0.04f);
    EXPECT_EQ(t.kappa2, 0.0f);
    EXPECT_FLOAT_EQ(t.shape_index, 0.75f);
    max_y = std::max(max_y, y);
  });
  EXPECT_EQ(max_y, 40.0);  // length 3.2 R
}

TEST(AnalyticSurface, SaddleHasTheGaussianCurvatureOfItsGraph) {
  const auto s = make(AnalyticShape::kSaddle);
  const AnalyticTruth& centre = s.truth(s.range.width() / 2, s.range.height() / 2);
  EXPECT_FLOAT_EQ(centre.kappa1, 0.04f);
  EXPECT_FLOAT_EQ(centre.kappa2, -0.04f);
  EXPECT_FLOAT_EQ(centre.shape_index, 0.5f);
  for_each_valid(s, [](double x, double y, const AnalyticTruth& t, float z) {
    EXPECT_NEAR(z, (x * x - y * y) / 50.0, 1e-5);
    // K = (f_xx f_yy - f_xy^2) / (1 + |grad f|^2)^2 for z = (x^2 - y^2) / (2R).
    const double w = 1.0 + (x * x + y * y) / 625.0;
    EXPECT_NEAR(t.kappa1 * t.kappa2, -1.0 / 625.0 / (w * w), 1e-8);
    EXPECT_GE(t.kappa1, t.kappa2);
  });
}

TEST(AnalyticSurface, PlaneIsTiltedAndPlanar) {
  const auto s = make(AnalyticShape::kPlane);
  const double tilt = 20.0 * std::numbers::pi / 180.0;
  std::size_t valid = 0;
  for_each_valid(s, [&](double x, double, const AnalyticTruth& t, float z) {
    ++valid;
    EXPECT_NEAR(z, std::tan(tilt) * x, 1e-5);
    EXPECT_NEAR(t.normal.x(), -std::sin(tilt), 1e-7);
    EXPECT_NEAR(t.normal.z(), std::cos(tilt), 1e-7);
    EXPECT_EQ(t.shape_index, 2.0f);
  });
  EXPECT_EQ(valid, 101u * 101u);  // |x|, |y| <= 25 mm
  EXPECT_NEAR(analytic_region_area_mm2(s, 0) / (101 * 101 * 0.25 / std::cos(tilt)), 1.0, 1e-6);
}

TEST(AnalyticSurface, TorusHasAHoleAndKnownCurvatures) {
  const auto s = make(AnalyticShape::kTorus);  // R = 30, a = 12
  const int c = s.range.width() / 2;
  EXPECT_FALSE(s.truth(c, c).valid);
  const AnalyticTruth& crest = s.truth(c + 60, c);  // x = 30 mm: the top of the tube
  ASSERT_TRUE(crest.valid);
  EXPECT_FLOAT_EQ(crest.z_mm, 12.0f);
  EXPECT_FLOAT_EQ(crest.shape_index, 0.75f);
  for_each_valid(s, [](double x, double y, const AnalyticTruth& t, float z) {
    const double rho = std::hypot(x, y);
    EXPECT_NEAR(z, std::sqrt(144.0 - (rho - 30.0) * (rho - 30.0)), 1e-5);
    EXPECT_FLOAT_EQ(t.kappa1, 1.0f / 12.0f);
    EXPECT_NEAR(t.kappa2, (rho - 30.0) / (12.0 * rho), 1e-7);
    EXPECT_EQ(t.shape_index > 0.75f, rho > 30.0);  // outer side elliptic, inner hyperbolic
  });
}

TEST(AnalyticSurface, EllipsoidCurvatureMatchesItsGaussianCurvature) {
  const auto s = make(AnalyticShape::kEllipsoid);  // 30 x 20 x 15
  const double a = 30, b = 20, c = 15;
  for_each_valid(s, [&](double x, double y, const AnalyticTruth& t, float z) {
    const double u = 1.0 - x * x / (a * a) - y * y / (b * b);
    EXPECT_NEAR(z, c * std::sqrt(u), 1e-5);
    if (u < 0.05) return;  // near the rim float curvatures lose relative precision
    const double zz = c * std::sqrt(u);
    const double q = x * x / (a * a * a * a) + y * y / (b * b * b * b) + zz * zz / (c * c * c * c);
    const double gaussian = 1.0 / (a * a * b * b * c * c * q * q);
    EXPECT_NEAR(t.kappa1 * t.kappa2 / gaussian, 1.0, 1e-4);
    EXPECT_GT(t.kappa2, 0.0f);
  });
  // At the top: k = c / a^2 and c / b^2.
  const AnalyticTruth& top = s.truth(s.range.width() / 2, s.range.height() / 2);
  EXPECT_FLOAT_EQ(top.kappa1, 15.0f / 400.0f);
  EXPECT_FLOAT_EQ(top.kappa2, 15.0f / 900.0f);
}

TEST(AnalyticSurface, RotationTurnsTheEllipsoidSilhouette) {
  const auto flat = make(AnalyticShape::kEllipsoid);
  const auto turned = make(AnalyticShape::kEllipsoid, 90.0);
  EXPECT_EQ(flat.range.width(), turned.range.height());
  EXPECT_EQ(flat.range.height(), turned.range.width());
  EXPECT_EQ(flat.range.width(), 2 * (60 + 4) + 1);
  const double angle = 30.0 * std::numbers::pi / 180.0;
  const auto oblique = make(AnalyticShape::kEllipsoid, 30.0);
  std::size_t valid = 0;
  for (int row = 0; row < oblique.range.height(); ++row) {
    for (int column = 0; column < oblique.range.width(); ++column) {
      const double x = oblique.range.x_mm(column), y = oblique.range.y_mm(row);
      const double along = x * std::cos(angle) + y * std::sin(angle);
      const double across = -x * std::sin(angle) + y * std::cos(angle);
      const double level = along * along / 900.0 + across * across / 400.0;
      if (std::abs(level - 1.0) < 1e-9) continue;
      EXPECT_EQ(oblique.range.has_data(column, row), level < 1.0) << x << "," << y;
      valid += level < 1.0 ? 1 : 0;
    }
  }
  EXPECT_NEAR(valid * 0.25, std::numbers::pi * 600.0, 0.01 * std::numbers::pi * 600.0);
  ASSERT_TRUE(oblique.range.ground_truth.has_value());
  EXPECT_EQ(oblique.range.ground_truth->part, "ellipsoid");
  EXPECT_NEAR(oblique.range.ground_truth->rotation(1, 0), std::sin(angle), 1e-15);
}

TEST(AnalyticSurface, CapsuleRegionsAndAreas) {
  const auto s = make(AnalyticShape::kCapsule);  // r = 15, cylinder 40
  for_each_valid(s, [](double x, double, const AnalyticTruth& t, float) {
    const int region = x < -20.0 ? 0 : (x > 20.0 ? 2 : 1);
    ASSERT_EQ(t.region, region) << x;
    EXPECT_FLOAT_EQ(t.shape_index, region == 1 ? 0.75f : 1.0f);
  });
  // The per-pixel sum dx*dy/n_z, with n_z from the formulas: sqrt(r^2 - y^2)/r on the ridge.
  double ridge_mm2 = 0.0;
  for_each_valid(s, [&](double, double y, const AnalyticTruth& t, float) {
    if (t.region == 1) ridge_mm2 += 0.25 * 15.0 / std::sqrt(225.0 - y * y);
  });
  EXPECT_NEAR(analytic_region_area_mm2(s, 1) / ridge_mm2, 1.0, 1e-6);
  EXPECT_NEAR(analytic_region_area_mm2(s, 2), analytic_region_area_mm2(s, 0), 1e-6);
  // Against the continuum areas (half a cylinder, pi r L; a quarter sphere per cap, pi r^2)
  // the sum misses part of the steep rim, less so on a finer grid.
  const double ridge_ratio = analytic_region_area_mm2(s, 1) / (std::numbers::pi * 15 * 40);
  const double cap_ratio = analytic_region_area_mm2(s, 0) / (std::numbers::pi * 225);
  EXPECT_NEAR(ridge_ratio, 0.9, 0.03);
  EXPECT_NEAR(cap_ratio, 0.92, 0.03);
  AnalyticSurfaceSpec fine = s.spec;
  fine.pixel_size_mm = 0.125;
  const double fine_ratio =
      analytic_region_area_mm2(make_analytic_surface(fine), 1) / (std::numbers::pi * 15 * 40);
  EXPECT_GT(fine_ratio, ridge_ratio);
  EXPECT_NEAR(fine_ratio, 0.94, 0.03);
}

TEST(AnalyticSurface, BoxCornerShowsThreeOrthogonalSquareFaces) {
  for (double rotate_deg : {0.0, 25.0}) {
    const auto s = make(AnalyticShape::kBoxCorner, rotate_deg);
    const auto normals = box_corner_face_normals(s.spec);
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(normals[i].norm(), 1.0f, 1e-6f);
      EXPECT_NEAR(normals[i].z(), 1.0f / std::sqrt(3.0f), 1e-6f);
      EXPECT_NEAR(normals[i].dot(normals[(i + 1) % 3]), 0.0f, 1e-6f);
    }
    int counts[3] = {0, 0, 0};
    for_each_valid(s, [&](double, double, const AnalyticTruth& t, float) {
      ASSERT_TRUE(t.region >= 0 && t.region < 3);
      ++counts[t.region];
      EXPECT_LT((t.normal - normals[t.region]).norm(), 1e-6f);
      EXPECT_EQ(t.shape_index, 2.0f);
    });
    for (int face = 0; face < 3; ++face) {
      EXPECT_NEAR(analytic_region_area_mm2(s, face) / 1600.0, 1.0, 0.03) << face;  // 40 mm square
    }
  }
}

TEST(AnalyticSurface, EveryShapeHasUnitNormalsOrderedCurvaturesAndANaNMargin) {
  for (AnalyticShape shape : kAllShapes) {
    for (double rotate_deg : {0.0, 37.0}) {
      const auto s = make(shape, rotate_deg);
      SCOPED_TRACE(analytic_shape_name(shape) + " " + std::to_string(rotate_deg));
      EXPECT_EQ(s.range.width() % 2, 1);
      EXPECT_EQ(s.range.x_mm(s.range.width() / 2), 0.0);
      EXPECT_GT(s.range.count_valid(), 1000u);
      for (int row = 0; row < s.range.height(); ++row) {
        for (int column = 0; column < s.range.width(); ++column) {
          const bool border =
              std::min({row, column, s.range.width() - 1 - column, s.range.height() - 1 - row}) < 4;
          const auto& t = s.truth(column, row);
          if (border) {
            ASSERT_FALSE(t.valid) << column << "," << row;
          }
          if (!t.valid) continue;
          ASSERT_NEAR(t.normal.norm(), 1.0f, 1e-5f);
          ASSERT_GT(t.normal.z(), 0.0f);
          ASSERT_GE(t.kappa1, t.kappa2);
          ASSERT_EQ(t.z_mm, s.range.z_mm(column, row));
        }
      }
    }
  }
}

TEST(AnalyticSurface, NoiseIsSeededAndHasTheRequestedSpread) {
  const auto clean = make(AnalyticShape::kPlane);
  const auto a = make(AnalyticShape::kPlane, 0.0, 0.2, 7);
  const auto b = make(AnalyticShape::kPlane, 0.0, 0.2, 7);
  const auto c = make(AnalyticShape::kPlane, 0.0, 0.2, 8);
  const std::size_t bytes = a.range.z_mm.size() * sizeof(float);
  EXPECT_EQ(std::memcmp(a.range.z_mm.data(), b.range.z_mm.data(), bytes), 0);
  EXPECT_NE(std::memcmp(a.range.z_mm.data(), c.range.z_mm.data(), bytes), 0);
  double sum = 0, sum_sq = 0;
  std::size_t n = 0, differing = 0;
  for (std::size_t i = 0; i < a.range.z_mm.size(); ++i) {
    if (!a.truth[i].valid) continue;
    EXPECT_EQ(a.truth[i].z_mm, clean.range.z_mm[i]);  // truth stays noise-free
    const double e = a.range.z_mm[i] - clean.range.z_mm[i];
    sum += e;
    sum_sq += e * e;
    ++n;
    differing += a.range.z_mm[i] != c.range.z_mm[i] ? 1 : 0;
  }
  ASSERT_EQ(n, 101u * 101u);
  const double mean = sum / n;
  const double sd = std::sqrt(sum_sq / n - mean * mean);
  EXPECT_NEAR(sd / 0.2, 1.0, 0.05);
  EXPECT_NEAR(mean, 0.0, 4 * 0.2 / std::sqrt(static_cast<double>(n)));
  EXPECT_GT(differing, n * 99 / 100);
}

TEST(AnalyticSurface, InvalidSpecsThrowNamingTheField) {
  auto message_of = [](const AnalyticSurfaceSpec& spec) -> std::string {
    try {
      make_analytic_surface(spec);
    } catch (const InputError& error) {
      return error.what();
    }
    return "";
  };
  AnalyticSurfaceSpec spec;
  spec.radius_mm = -1;
  EXPECT_NE(message_of(spec).find("radius_mm"), std::string::npos);
  spec = {};
  spec.pixel_size_mm = 0;
  EXPECT_NE(message_of(spec).find("pixel_size_mm"), std::string::npos);
  spec = {};
  spec.noise_mm = std::nan("");
  EXPECT_NE(message_of(spec).find("noise_mm"), std::string::npos);
  spec = {};
  spec.shape = AnalyticShape::kTorus;
  spec.torus_minor_radius_mm = 40.0;
  EXPECT_NE(message_of(spec).find("torus_minor_radius_mm"), std::string::npos);
  spec = {};
  spec.pixel_size_mm = 1e-4;  // 500k x 500k pixels
  EXPECT_NE(message_of(spec).find("pixel_size_mm"), std::string::npos);
}

}  // namespace
}  // namespace cosmos
