// The simulator's normals (ziggurat) against the standard normal: moments, tail masses,
// the Kolmogorov-Smirnov distance, and the same stream for the same seed.
#include "sim/seeded_random.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace cosmos {
namespace {

constexpr int kDraws = 400000;

std::vector<double> draw_normals(std::uint64_t seed) {
  SeededRandom random(seed);
  std::vector<double> values(kDraws);
  for (double& v : values) v = random.normal();
  return values;
}

double standard_normal_cdf(double x) { return 0.5 * std::erfc(-x / std::sqrt(2.0)); }

TEST(SeededRandom, NormalsHaveUnitVarianceAndNoSkewOrExcessKurtosis) {
  const std::vector<double> values = draw_normals(3);
  double sum = 0, squares = 0, cubes = 0, fourths = 0;
  for (double v : values) sum += v, squares += v * v, cubes += v * v * v, fourths += v * v * v * v;
  const double n = kDraws;
  // Standard errors at n = 4e5: mean 0.0016, variance 0.0022, skew 0.0039, kurtosis 0.0077.
  EXPECT_NEAR(sum / n, 0.0, 0.007);
  EXPECT_NEAR(squares / n, 1.0, 0.01);
  EXPECT_NEAR(cubes / n, 0.0, 0.02);
  EXPECT_NEAR(fourths / n, 3.0, 0.04);
}

TEST(SeededRandom, NormalsFollowTheNormalDistributionIncludingItsTails) {
  std::vector<double> values = draw_normals(11);
  std::sort(values.begin(), values.end());
  double ks_distance = 0;
  for (int i = 0; i < kDraws; ++i) {
    const double cdf = standard_normal_cdf(values[static_cast<std::size_t>(i)]);
    ks_distance = std::max({ks_distance, std::abs(cdf - static_cast<double>(i) / kDraws),
                            std::abs(cdf - static_cast<double>(i + 1) / kDraws)});
  }
  // The 1 % critical value of the KS distance is 1.63 / sqrt(n) = 0.0026.
  EXPECT_LT(ks_distance, 0.0026);
  // Beyond the ziggurat's base layer (r = 3.654): expected 2 (1 - Phi(r)) n = 103 draws.
  const auto beyond = std::count_if(values.begin(), values.end(),
                                    [](double v) { return std::abs(v) > 3.6541528853610088; });
  const double expected = 2.0 * (1.0 - standard_normal_cdf(3.6541528853610088)) * kDraws;
  EXPECT_NEAR(static_cast<double>(beyond), expected, 4.0 * std::sqrt(expected));
  EXPECT_GT(values.back(), 4.0);
  EXPECT_LT(values.front(), -4.0);
}

TEST(SeededRandom, TheSameSeedGivesTheSameStreamAndAnotherSeedAnother) {
  EXPECT_EQ(draw_normals(5), draw_normals(5));
  EXPECT_NE(draw_normals(5), draw_normals(6));
}

}  // namespace
}  // namespace cosmos
