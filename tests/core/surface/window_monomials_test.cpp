// The bicubic monomials of the local surface fit (§3.5.1), in the order whose first six
// coefficients are the centre's Taylor terms z, z_u, z_v, z_uu/2, z_uv, z_vv/2.
#include "core/surface/window_monomials.hpp"

#include <gtest/gtest.h>

namespace cosmos {
namespace {

TEST(WindowMonomials, AreTheBicubicTermsInTheFitsOrder) {
  static_assert(kBicubicTerms == 10 && kBiquadraticTerms == 6);
  Eigen::Matrix<double, kBicubicTerms, 1> expected;
  // 1, u, v, u^2, uv, v^2, u^3, u^2 v, u v^2, v^3 at u = 2, v = -3.
  expected << 1, 2, -3, 4, -6, 9, 8, -12, 18, -27;
  EXPECT_EQ(window_monomials(2, -3), expected);
  expected << 1, -1, 0.5, 1, -0.5, 0.25, -1, 0.5, -0.25, 0.125;
  EXPECT_EQ(window_monomials(-1, 0.5), expected);
}

TEST(WindowMonomials, FirstSixCoefficientsAreTheTaylorTermsAtTheCentre) {
  // z(u, v) = c . m(u, v); its derivatives at 0 by central differences.
  Eigen::Matrix<double, kBicubicTerms, 1> c;
  c << 0.7, -0.3, 0.2, 0.05, -0.04, 0.09, 0.011, -0.013, 0.017, 0.019;
  const auto z = [&](double u, double v) { return c.dot(window_monomials(u, v)); };
  const double h = 1e-3;
  EXPECT_NEAR(z(0, 0), c[0], 1e-15);
  EXPECT_NEAR((z(h, 0) - z(-h, 0)) / (2 * h), c[1], 1e-6);
  EXPECT_NEAR((z(0, h) - z(0, -h)) / (2 * h), c[2], 1e-6);
  EXPECT_NEAR((z(h, 0) - 2 * z(0, 0) + z(-h, 0)) / (h * h) / 2, c[3], 1e-6);
  EXPECT_NEAR((z(h, h) - z(h, -h) - z(-h, h) + z(-h, -h)) / (4 * h * h), c[4], 1e-6);
  EXPECT_NEAR((z(0, h) - 2 * z(0, 0) + z(0, -h)) / (h * h) / 2, c[5], 1e-6);
}

}  // namespace
}  // namespace cosmos
