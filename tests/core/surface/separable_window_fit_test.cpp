// The separable window fit (core/surface/separable_window_fit.hpp): on complete windows its
// Taylor terms and residual equal those of the direct least-squares fit of §3.5.1 (the
// design-matrix solve), for every window shape it supports; windows with a missing sample or
// too large a depth range are not complete; the row-filter ring gives the same result whatever
// order the rows are fitted in.
#include "core/surface/separable_window_fit.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

#include "core/surface/window_monomials.hpp"

namespace cosmos {
namespace {

// A relief of a few mm plus seeded noise: no polynomial fits it exactly, so the residual is
// not zero and every coefficient matters.
RangeImage noisy_relief(int width, int height, std::uint64_t seed) {
  RangeImage image(width, height, 0.5, 0.5);
  std::mt19937_64 random(seed);
  std::normal_distribution<double> noise(0.0, 0.05);
  for (int row = 0; row < height; ++row)
    for (int column = 0; column < width; ++column)
      image.z_mm(column, row) =
          static_cast<float>(40.0 + 2.0 * std::sin(0.3 * column) * std::cos(0.2 * row) +
                             0.05 * column + noise(random));
  return image;
}

struct DirectFit {
  Eigen::Matrix<double, 6, 1> taylor;  // z, z_u, z_v, z_uu/2, z_uv, z_vv/2 at the centre
  double residual_sum_of_squares = 0;
};

DirectFit direct_fit(const RangeImage& image, int column, int row, int half, int degree) {
  const int side = 2 * half + 1, terms = degree == 3 ? kBicubicTerms : kBiquadraticTerms;
  Eigen::MatrixXd design(side * side, terms);
  Eigen::VectorXd z(side * side);
  for (int v = -half, k = 0; v <= half; ++v)
    for (int u = -half; u <= half; ++u, ++k) {
      design.row(k) = window_monomials(u, v).head(terms).transpose();
      z(k) = image.z_mm(column + u, row + v);
    }
  const Eigen::VectorXd c = design.colPivHouseholderQr().solve(z);
  return {c.head<6>(), (design * c - z).squaredNorm()};
}

void expect_equals_direct_fit(int half, int degree) {
  SCOPED_TRACE("half window " + std::to_string(half) + ", degree " + std::to_string(degree));
  const RangeImage image = noisy_relief(23, 17, 3 + half * 10 + degree);
  SeparableWindowFit fit(half, degree, image.width());
  int checked = 0;
  for (int row = 0; row < image.height(); ++row) {
    fit.fit_row(image, row, 100.0);
    for (int column = 0; column < image.width(); ++column) {
      const bool inside = column >= half && row >= half && column + half < image.width() &&
                          row + half < image.height();
      ASSERT_EQ(fit.complete()[column], inside ? 1 : 0) << column << "," << row;
      if (!inside) {
        for (int t = 0; t < SeparableWindowFit::kQuadricTerms; ++t)
          EXPECT_EQ(fit.quadric(t)[column], 0.0f);
        continue;
      }
      const DirectFit expected = direct_fit(image, column, row, half, degree);
      EXPECT_NEAR(fit.quadric(0)[column], expected.taylor[0], 2e-5 * std::abs(expected.taylor[0]));
      for (int t = 1; t < SeparableWindowFit::kQuadricTerms; ++t)
        EXPECT_NEAR(fit.quadric(t)[column], expected.taylor[t], 2e-5) << "term " << t;
      EXPECT_NEAR(fit.residual_sum_of_squares()[column], expected.residual_sum_of_squares,
                  1e-6 + 1e-4 * expected.residual_sum_of_squares);
      ++checked;
    }
  }
  EXPECT_EQ(checked, (image.width() - 2 * half) * (image.height() - 2 * half));
}

TEST(SeparableWindowFit, EqualsTheDirectLeastSquaresFitOnCompleteWindows) {
  // 3x3 to 11x11 biquadratics, 5x5 to 11x11 bicubics (3x3 samples do not determine the ten
  // bicubic terms).
  for (int half = 1; half <= 5; ++half)
    for (int degree : {2, 3})
      if (half > 1 || degree == 2) expect_equals_direct_fit(half, degree);
}

TEST(SeparableWindowFit, AMissingSampleOrADepthRangeAboveTheLimitMakesAWindowIncomplete) {
  RangeImage image = noisy_relief(15, 11, 9);
  image.z_mm(7, 5) = std::numeric_limits<float>::quiet_NaN();
  image.z_mm(2, 8) += 6.0f;  // a spike: windows containing it span more than 5 mm
  SeparableWindowFit fit(2, 3, image.width());
  for (int row = 0; row < image.height(); ++row) {
    fit.fit_row(image, row, 5.0);
    for (int column = 2; column + 2 < image.width(); ++column) {
      if (row < 2 || row + 2 >= image.height()) continue;
      const bool sees_hole = std::abs(column - 7) <= 2 && std::abs(row - 5) <= 2;
      const bool sees_spike = std::abs(column - 2) <= 2 && std::abs(row - 8) <= 2;
      EXPECT_EQ(fit.complete()[column], sees_hole || sees_spike ? 0 : 1) << column << "," << row;
    }
  }
  // Without the limit the spike's windows are complete again (the hole's are not).
  SeparableWindowFit unlimited(2, 3, image.width());
  for (int row = 0; row <= 8; ++row) unlimited.fit_row(image, row, 1e9);
  EXPECT_EQ(unlimited.complete()[2], 1);
  EXPECT_EQ(unlimited.complete()[7], 1);  // row 8 is 3 rows from the hole
}

TEST(SeparableWindowFit, RowOrderAndResetDoNotChangeTheResult) {
  const RangeImage image = noisy_relief(20, 14, 4);
  const RangeImage other = noisy_relief(20, 14, 5);
  SeparableWindowFit in_order(2, 3, image.width()), jumping(2, 3, image.width());
  std::vector<std::vector<float>> expected(static_cast<std::size_t>(image.height()));
  for (int row = 0; row < image.height(); ++row) {
    in_order.fit_row(image, row, 100.0);
    expected[static_cast<std::size_t>(row)].assign(in_order.quadric(3),
                                                   in_order.quadric(3) + image.width());
  }
  // Another image first, then the rows backwards: every cached row filter is stale.
  for (int row = 0; row < other.height(); ++row) jumping.fit_row(other, row, 100.0);
  jumping.reset();
  for (int row = image.height() - 1; row >= 0; --row) {
    jumping.fit_row(image, row, 100.0);
    for (int column = 0; column < image.width(); ++column)
      EXPECT_EQ(jumping.quadric(3)[column], expected[static_cast<std::size_t>(row)][column])
          << column << "," << row;
  }
}

TEST(SeparableWindowFit, RefusesWindowShapesItHasNoKernelFor) {
  EXPECT_THROW(SeparableWindowFit(0, 3, 10), std::invalid_argument);  // 1x1
  EXPECT_THROW(SeparableWindowFit(6, 3, 10), std::invalid_argument);  // 13x13
  EXPECT_THROW(SeparableWindowFit(2, 1, 10), std::invalid_argument);  // a plane fit
  EXPECT_NO_THROW(SeparableWindowFit(5, 2, 10));
}

}  // namespace
}  // namespace cosmos
