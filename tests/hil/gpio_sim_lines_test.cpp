// The levels the HIL player drives onto the encoder lines: the Gray sequence the project's
// quadrature decoder counts up on (A leading B), and backwards below zero.
#include "tests/hil/gpio_sim_lines.hpp"

#include <gtest/gtest.h>

#include "firmware_bridge/quadrature_decoder.hpp"

namespace cosmos::hil {
namespace {

TEST(QuadratureLevels, AreTheSequenceTheDecoderCountsUpOn) {
  QuadratureDecoder decoder;
  decoder.reset(false, false);
  std::int64_t t_ns = 0;
  for (long long tick = 1; tick <= 9; ++tick) {
    const QuadratureLevels before = quadrature_levels(tick - 1);
    const QuadratureLevels after = quadrature_levels(tick);
    ASSERT_NE(before.a != after.a, before.b != after.b) << "one line per step, tick " << tick;
    if (before.a != after.a) decoder.on_edge(EncoderLine::kA, after.a, t_ns += 1000);
    if (before.b != after.b) decoder.on_edge(EncoderLine::kB, after.b, t_ns += 1000);
  }
  EXPECT_EQ(decoder.ticks(), 9);
  EXPECT_EQ(decoder.counts().invalid_transitions, 0u);
  EXPECT_EQ(quadrature_levels(-1).a, quadrature_levels(3).a);
  EXPECT_EQ(quadrature_levels(-1).b, quadrature_levels(3).b);
  EXPECT_FALSE(quadrature_levels(0).a);
  EXPECT_FALSE(quadrature_levels(0).b);
}

}  // namespace
}  // namespace cosmos::hil
