// The lanes of the separable window fit's kernels (core/surface/window_lanes.hpp): the
// four-column and the one-column forms must agree lane by lane, since a row's last columns
// take the one-column form.
#include "core/surface/window_lanes.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>

namespace cosmos {
namespace {

using window_lanes::Double4;
using window_lanes::Float4;
using window_lanes::Lanes;
using Four = Lanes<Double4>;
using One = Lanes<double>;

TEST(WindowLanes, FourLanesLoadWidenNarrowAndStoreLikeOne) {
  const float floats[4] = {1.5f, -2.25f, 1e-30f, 3e38f};
  const double doubles[4] = {0.1, -7.0, 1e20, -0.0};
  const Double4 wide = Four::widen(Four::load(floats));
  const Double4 loaded = Four::load(doubles);
  float narrowed[4];
  double stored[4];
  Four::store(narrowed, Four::narrow(loaded));
  Four::store(stored, wide);
  for (int lane = 0; lane < 4; ++lane) {
    EXPECT_EQ(wide[lane], One::widen(One::load(floats + lane))) << lane;
    EXPECT_EQ(stored[lane], static_cast<double>(floats[lane])) << lane;
    EXPECT_EQ(loaded[lane], doubles[lane]) << lane;
    EXPECT_EQ(narrowed[lane], One::narrow(doubles[lane])) << lane;
  }
  EXPECT_NE(static_cast<double>(narrowed[0]), 0.1);  // rounded to float
  const Double4 b = Four::broadcast(2.5);
  for (int lane = 0; lane < 4; ++lane) EXPECT_EQ(b[lane], 2.5);
}

TEST(WindowLanes, MinAndMaxAreLaneWise) {
  const Float4 a = {1, 5, -3, 0};
  const Float4 b = {2, 4, -4, 0};
  const Float4 low = Four::min(a, b), high = Four::max(a, b);
  const Double4 wide_high = Four::max(Double4{1, 5, -3, 0}, Double4{2, 4, -4, 0});
  const float expected_low[4] = {1, 4, -4, 0}, expected_high[4] = {2, 5, -3, 0};
  for (int lane = 0; lane < 4; ++lane) {
    EXPECT_EQ(low[lane], expected_low[lane]) << lane;
    EXPECT_EQ(high[lane], expected_high[lane]) << lane;
    EXPECT_EQ(wide_high[lane], expected_high[lane]) << lane;
    EXPECT_EQ(One::min(a[lane], b[lane]), expected_low[lane]) << lane;
    EXPECT_EQ(One::max(a[lane], b[lane]), expected_high[lane]) << lane;
  }
}

TEST(WindowLanes, CompleteNeedsAFiniteResidualAndADepthRangeWithinTheLimit) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const Double4 residual = {0.5, nan, 0.5, 0.5};
  const Double4 range = {3.0, 1.0, 3.0000001, 0.0};
  std::uint8_t four[4], one[4];
  Four::store_complete(four, residual, range, 3.0);
  for (int lane = 0; lane < 4; ++lane)
    One::store_complete(one + lane, residual[lane], range[lane], 3.0);
  const std::uint8_t expected[4] = {1, 0, 0, 1};  // range == limit still complete
  for (int lane = 0; lane < 4; ++lane) {
    EXPECT_EQ(four[lane], expected[lane]) << lane;
    EXPECT_EQ(one[lane], expected[lane]) << lane;
  }
}

}  // namespace
}  // namespace cosmos
