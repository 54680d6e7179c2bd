// Partial-window kernels against a direct least-squares solve, on random validity patterns of
// a 5x5 window; degenerate patterns; and results that do not depend on the cache's contents.
#include "core/surface/partial_window_kernels.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <bit>
#include <random>

namespace cosmos {
namespace {

constexpr int kSide = 5;
constexpr int kSamples = kSide * kSide;

// Taylor terms at the centre of the least-squares polynomial through the valid samples.
Eigen::Matrix<double, 6, 1> direct_fit(const PartialWindowKernels::Mask& mask, int terms,
                                       const Eigen::Matrix<double, kSamples, 1>& z) {
  Eigen::MatrixXd design(0, terms);
  Eigen::VectorXd values(0);
  for (int k = 0; k < kSamples; ++k) {
    if (((mask[0] >> k) & 1u) == 0) continue;
    const double u = k % kSide - 2, v = k / kSide - 2;
    Eigen::Matrix<double, 10, 1> m;
    m << 1, u, v, u * u, u * v, v * v, u * u * u, u * u * v, u * v * v, v * v * v;
    design.conservativeResize(design.rows() + 1, Eigen::NoChange);
    design.row(design.rows() - 1) = m.head(terms).transpose();
    values.conservativeResize(values.size() + 1);
    values(values.size() - 1) = z(k);
  }
  const Eigen::VectorXd c = design.colPivHouseholderQr().solve(values);
  return c.head<6>();
}

TEST(PartialWindowKernels, MatchDirectLeastSquaresOnRandomPatterns) {
  PartialWindowKernels kernels(kSide, true);
  std::mt19937_64 random(17);
  std::uniform_real_distribution<double> height(-2.0, 2.0);
  int checked = 0, bicubic = 0;
  for (int trial = 0; trial < 400; ++trial) {
    PartialWindowKernels::Mask mask{};
    int count = 0;
    const double keep = 0.45 + 0.5 * (trial % 10) / 10.0;
    for (int k = 0; k < kSamples; ++k) {
      if (std::uniform_real_distribution<double>(0, 1)(random) < keep || k == 12) {
        mask[0] |= std::uint64_t{1} << k;
        ++count;
      }
    }
    Eigen::Matrix<double, kSamples, 1> z;
    for (int k = 0; k < kSamples; ++k) z(k) = ((mask[0] >> k) & 1u) ? height(random) : 0.0;
    const PartialWindowKernels::Kernel* kernel = kernels.kernel(mask, count);
    if (count < 10 || kernel == nullptr) continue;
    const int terms = count >= 16 ? 10 : 6;
    const Eigen::Matrix<double, 6, 1> expected = direct_fit(mask, terms, z);
    const Eigen::Matrix<double, 6, 1> got = *kernel * z;
    EXPECT_LT((got - expected).cwiseAbs().maxCoeff(), 1e-9) << "trial " << trial;
    ++checked;
    bicubic += terms == 10;
  }
  EXPECT_GT(checked, 300);
  EXPECT_GT(bicubic, 100);
  EXPECT_LT(bicubic, checked);
}

TEST(PartialWindowKernels, SamplesOnOneLineDetermineNoSurface) {
  PartialWindowKernels kernels(kSide, true);
  PartialWindowKernels::Mask row{};
  for (int k = 10; k < 15; ++k) row[0] |= std::uint64_t{1} << k;  // the middle row only
  EXPECT_EQ(kernels.kernel(row, 5), nullptr);
}

TEST(PartialWindowKernels, ResultsDoNotDependOnWhatWasCached) {
  PartialWindowKernels fresh(kSide, false), busy(kSide, false);
  PartialWindowKernels::Mask mask{};
  for (int k = 0; k < kSamples; ++k)
    if (k % 3 != 0 || k == 12) mask[0] |= std::uint64_t{1} << k;
  const int count = static_cast<int>(std::popcount(mask[0]));
  // Fill the busy table with 2,000 other patterns first, evicting whatever shares a slot.
  for (std::uint64_t other = 1; other <= 2000; ++other) {
    PartialWindowKernels::Mask m{};
    m[0] = (other * 0x9E3779B97F4A7C15ULL) & ((std::uint64_t{1} << kSamples) - 1);
    busy.kernel(m, static_cast<int>(std::popcount(m[0])));
  }
  const PartialWindowKernels::Kernel* a = fresh.kernel(mask, count);
  const PartialWindowKernels::Kernel* b = busy.kernel(mask, count);
  ASSERT_NE(a, nullptr);
  ASSERT_NE(b, nullptr);
  EXPECT_EQ(*a, *b);
}

}  // namespace
}  // namespace cosmos
