#include "firmware_bridge/quadrature_decoder.hpp"

#include <gtest/gtest.h>

#include <cstdint>

namespace cosmos {
namespace {

// A quadrature encoder as a state machine: emits the edge events a real one would, one per
// quarter period, A leading B when moving forward.
class SyntheticEncoder {
 public:
  explicit SyntheticEncoder(QuadratureDecoder& decoder, std::int64_t quarter_period_ns = 10'000)
      : decoder_(decoder), quarter_ns_(quarter_period_ns) {
    decoder_.reset(false, false);
  }

  // Moves `steps` counts (negative = backwards), emitting one edge per count.
  void move(int steps) {
    const int direction = steps >= 0 ? 1 : -1;
    for (int i = 0; i != steps; i += direction) {
      position_ += direction;
      // Gray sequence 00 → 10 → 11 → 01: A is high in phases 1 and 2, B in phases 2 and 3.
      const int phase = ((position_ % 4) + 4) % 4;
      const bool a = phase == 1 || phase == 2;
      const bool b = phase == 2 || phase == 3;
      t_ns_ += quarter_ns_;
      if (a != a_) decoder_.on_edge(EncoderLine::kA, a, t_ns_);
      if (b != b_) decoder_.on_edge(EncoderLine::kB, b, t_ns_);
      a_ = a;
      b_ = b;
    }
  }

  // An edge and its return on one line, `width_ns` apart, leaving the line as it was.
  void glitch(EncoderLine line, std::int64_t width_ns) {
    bool& level = line == EncoderLine::kA ? a_ : b_;
    t_ns_ += quarter_ns_ / 2;
    decoder_.on_edge(line, !level, t_ns_);
    decoder_.on_edge(line, level, t_ns_ + width_ns);
  }

  std::int64_t t_ns() const { return t_ns_; }

 private:
  QuadratureDecoder& decoder_;
  std::int64_t quarter_ns_;
  std::int64_t t_ns_ = 0;
  int position_ = 0;
  bool a_ = false;
  bool b_ = false;
};

TEST(QuadratureDecoder, ForwardStepsCountFourPerCycle) {
  QuadratureDecoder decoder;
  SyntheticEncoder encoder(decoder);
  encoder.move(1000);
  EXPECT_EQ(decoder.ticks(), 1000);
  EXPECT_EQ(decoder.counts().direction, +1);
  EXPECT_EQ(decoder.counts().invalid_transitions, 0u);
  EXPECT_EQ(decoder.counts().last_step_t_ns, encoder.t_ns());
}

TEST(QuadratureDecoder, KeepsTheCountAtEveryEdgesTime) {
  QuadratureDecoder decoder;
  SyntheticEncoder encoder(decoder);  // edges 10 us apart from t = 10 us
  encoder.move(100);
  encoder.move(-20);
  EXPECT_EQ(decoder.ticks_at(0).ticks, 0);
  EXPECT_EQ(decoder.ticks_at(25'000).ticks, 2);
  EXPECT_EQ(decoder.ticks_at(1'000'000).ticks, 100);
  EXPECT_EQ(decoder.ticks_at(1'100'000).ticks, 90);  // ten counts back
  EXPECT_EQ(decoder.ticks_at(encoder.t_ns()).ticks, 80);
  EXPECT_TRUE(decoder.ticks_at(0).covered);
}

TEST(QuadratureDecoder, ReversalCountsBackAndIsCounted) {
  QuadratureDecoder decoder;
  SyntheticEncoder encoder(decoder);
  encoder.move(37);
  encoder.move(-50);
  EXPECT_EQ(decoder.ticks(), -13);
  EXPECT_EQ(decoder.counts().direction, -1);
  EXPECT_EQ(decoder.counts().reversals, 1u);
  encoder.move(13);
  EXPECT_EQ(decoder.ticks(), 0);
  EXPECT_EQ(decoder.counts().reversals, 2u);
  EXPECT_EQ(decoder.counts().steps, 100u);
}

TEST(QuadratureDecoder, MissedEdgeIsAnErrorNotAStep) {
  QuadratureDecoder decoder;
  decoder.reset(false, false);
  decoder.on_edge(EncoderLine::kA, true, 100);  // 00 → 10: +1
  decoder.on_edge(EncoderLine::kA, true, 200);  // A high again: its falling edge was lost
  EXPECT_EQ(decoder.ticks(), 1);
  EXPECT_EQ(decoder.counts().invalid_transitions, 1u);
  decoder.on_edge(EncoderLine::kB, true, 300);  // 10 → 11: decoding carries on
  EXPECT_EQ(decoder.ticks(), 2);
}

TEST(QuadratureDecoder, BothLinesChangingAtOnceIsAnErrorNotAStep) {
  QuadratureDecoder decoder;
  decoder.reset(false, false);
  decoder.on_sample(true, false, 100);  // 00 → 10: +1
  decoder.on_sample(false, true, 200);  // 10 → 01: two states away, direction unknowable
  EXPECT_EQ(decoder.ticks(), 1);
  EXPECT_EQ(decoder.counts().invalid_transitions, 1u);
  decoder.on_sample(false, false, 300);  // 01 → 00: +1 from the state now known
  EXPECT_EQ(decoder.ticks(), 2);
}

TEST(QuadratureDecoder, UndebouncedGlitchNetsToZero) {
  QuadratureDecoder decoder;
  SyntheticEncoder encoder(decoder);
  encoder.move(10);
  encoder.glitch(EncoderLine::kA, 50);
  encoder.move(10);
  EXPECT_EQ(decoder.ticks(), 20);
  EXPECT_EQ(decoder.counts().invalid_transitions, 0u);
}

TEST(QuadratureDecoder, BounceInsideTheDebounceTimeIsIgnored) {
  QuadratureDecoderParameters parameters;
  parameters.debounce_ns = 1'000;
  QuadratureDecoder decoder(parameters);
  decoder.reset(false, false);
  // A rises with two bounces 200 ns apart, then B rises cleanly.
  decoder.on_edge(EncoderLine::kA, true, 10'000);
  decoder.on_edge(EncoderLine::kA, false, 10'200);
  decoder.on_edge(EncoderLine::kA, true, 10'400);
  EXPECT_EQ(decoder.ticks(), 1);
  EXPECT_EQ(decoder.counts().ignored_edges, 2u);
  decoder.on_edge(EncoderLine::kB, true, 20'000);
  EXPECT_EQ(decoder.ticks(), 2);
  EXPECT_EQ(decoder.counts().invalid_transitions, 0u);
}

TEST(QuadratureDecoder, DebouncedGlitchSettlesBackOnceTheLineIsQuiet) {
  QuadratureDecoderParameters parameters;
  parameters.debounce_ns = 1'000;
  QuadratureDecoder decoder(parameters);
  SyntheticEncoder encoder(decoder);
  encoder.move(10);
  encoder.glitch(EncoderLine::kA, 100);  // the return edge falls inside the debounce time
  EXPECT_EQ(decoder.ticks(), 11);        // the glitch's first edge counted…
  decoder.advance_to(encoder.t_ns() + 2'000);
  EXPECT_EQ(decoder.ticks(), 10);  // …and is taken back once A stayed put
  encoder.move(10);
  EXPECT_EQ(decoder.ticks(), 20);
  EXPECT_EQ(decoder.counts().invalid_transitions, 0u);
  EXPECT_EQ(decoder.counts().ignored_edges, 1u);
}

TEST(QuadratureDecoder, GlitchSettlesBeforeTheNextEdgeEvenWithoutAdvance) {
  QuadratureDecoderParameters parameters;
  parameters.debounce_ns = 1'000;
  QuadratureDecoder decoder(parameters);
  SyntheticEncoder encoder(decoder, 20'000);
  encoder.move(3);
  encoder.glitch(EncoderLine::kB, 100);
  encoder.move(-3);  // the next edge comes long after the glitch
  EXPECT_EQ(decoder.ticks(), 0);
  EXPECT_EQ(decoder.counts().invalid_transitions, 0u);
}

TEST(QuadratureDecoder, StepModeCountsRisingEdges) {
  QuadratureDecoderParameters parameters;
  parameters.mode = EncoderMode::kStep;
  QuadratureDecoder decoder(parameters);
  decoder.reset(false, false);
  std::int64_t t = 0;
  for (int i = 0; i < 25; ++i) {
    decoder.on_edge(EncoderLine::kA, true, t += 1000);
    decoder.on_edge(EncoderLine::kA, false, t += 1000);
  }
  EXPECT_EQ(decoder.ticks(), 25);
  EXPECT_EQ(decoder.counts().invalid_transitions, 0u);
}

TEST(QuadratureDecoder, StepModeDirectionLineCountsDown) {
  QuadratureDecoderParameters parameters;
  parameters.mode = EncoderMode::kStep;
  parameters.has_direction_line = true;
  parameters.debounce_ns = 300;
  QuadratureDecoder decoder(parameters);
  decoder.reset(false, false);
  std::int64_t t = 0;
  for (int i = 0; i < 5; ++i) {
    decoder.on_edge(EncoderLine::kA, true, t += 1000);
    decoder.on_edge(EncoderLine::kA, false, t += 1000);
  }
  decoder.on_edge(EncoderLine::kB, true, t += 1000);
  for (int i = 0; i < 8; ++i) {
    decoder.on_edge(EncoderLine::kA, true, t += 1000);
    decoder.on_edge(EncoderLine::kA, false, t + 100);  // bounce: ignored…
    decoder.on_edge(EncoderLine::kA, true, t + 200);   // …ending high
    decoder.on_edge(EncoderLine::kA, false, t += 1000);
  }
  EXPECT_EQ(decoder.ticks(), 5 - 8);
  EXPECT_EQ(decoder.counts().reversals, 1u);
  EXPECT_EQ(decoder.counts().ignored_edges, 16u);
  EXPECT_EQ(decoder.counts().invalid_transitions, 0u);
}

}  // namespace
}  // namespace cosmos
