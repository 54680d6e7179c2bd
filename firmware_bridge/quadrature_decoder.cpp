#include "firmware_bridge/quadrature_decoder.hpp"

namespace cosmos {

namespace {

// Position of state (A, B) along the forward Gray sequence 00 → 10 → 11 → 01 (A leads B).
constexpr std::array<int, 4> kGrayPosition = {
    0,  // A=0 B=0
    3,  // A=0 B=1
    1,  // A=1 B=0
    2,  // A=1 B=1
};

int state_of(bool a, bool b) noexcept { return (a ? 2 : 0) | (b ? 1 : 0); }

}  // namespace

QuadratureDecoder::QuadratureDecoder(const QuadratureDecoderParameters& parameters)
    : parameters_(parameters) {}

void QuadratureDecoder::reset(bool level_a, bool level_b, std::int64_t ticks,
                              std::int64_t t_ns) noexcept {
  lines_[0] = {level_a, level_a, false, 0};
  lines_[1] = {level_b, level_b, false, 0};
  counts_ = {};
  counts_.ticks = ticks;
  history_.reset(ticks, t_ns);
}

void QuadratureDecoder::count(int step, std::int64_t t_ns) noexcept {
  if (counts_.direction != 0 && step != counts_.direction) ++counts_.reversals;
  counts_.direction = step;
  counts_.ticks += step;
  counts_.last_step_t_ns = t_ns;
  ++counts_.steps;
  history_.record(t_ns, counts_.ticks);
}

void QuadratureDecoder::apply_state(bool level_a, bool level_b, std::int64_t t_ns) noexcept {
  const int from =
      kGrayPosition[static_cast<std::size_t>(state_of(lines_[0].decoded, lines_[1].decoded))];
  const int to = kGrayPosition[static_cast<std::size_t>(state_of(level_a, level_b))];
  lines_[0].decoded = level_a;
  lines_[1].decoded = level_b;
  switch ((to - from + 4) % 4) {
    case 0:
      break;
    case 1:
      count(+1, t_ns);
      break;
    case 3:
      count(-1, t_ns);
      break;
    default:  // two states away: both lines changed, direction unknowable
      ++counts_.invalid_transitions;
      break;
  }
}

void QuadratureDecoder::apply(EncoderLine line, bool level, std::int64_t t_ns) noexcept {
  LineState& state = lines_[static_cast<std::size_t>(line)];
  if (state.decoded == level) {
    ++counts_.invalid_transitions;  // the opposite edge never arrived
    return;
  }
  if (parameters_.mode == EncoderMode::kStep) {
    state.decoded = level;
    if (line == EncoderLine::kA && level) {
      const bool down = parameters_.has_direction_line && lines_[1].decoded;
      count(down ? -1 : +1, t_ns);
    }
    return;
  }
  const bool a = line == EncoderLine::kA ? level : lines_[0].decoded;
  const bool b = line == EncoderLine::kB ? level : lines_[1].decoded;
  apply_state(a, b, t_ns);
}

void QuadratureDecoder::settle(std::int64_t t_ns) noexcept {
  // Settle in the order the lines went quiet, so two settled changes count in time order.
  const bool a_first = lines_[0].last_edge_t_ns <= lines_[1].last_edge_t_ns;
  for (const std::size_t i :
       {a_first ? std::size_t{0} : std::size_t{1}, a_first ? std::size_t{1} : std::size_t{0}}) {
    LineState& state = lines_[i];
    if (state.raw != state.decoded && t_ns - state.last_edge_t_ns >= parameters_.debounce_ns) {
      apply(static_cast<EncoderLine>(i), state.raw, state.last_edge_t_ns);
    }
  }
}

void QuadratureDecoder::on_edge(EncoderLine line, bool level, std::int64_t t_ns) noexcept {
  LineState& state = lines_[static_cast<std::size_t>(line)];
  if (parameters_.debounce_ns > 0 && state.seen_edge &&
      t_ns - state.last_edge_t_ns < parameters_.debounce_ns) {
    state.raw = level;
    state.last_edge_t_ns = t_ns;
    ++counts_.ignored_edges;
    return;
  }
  settle(t_ns);
  state.raw = level;
  state.seen_edge = true;
  state.last_edge_t_ns = t_ns;
  apply(line, level, t_ns);
}

void QuadratureDecoder::on_sample(bool level_a, bool level_b, std::int64_t t_ns) noexcept {
  lines_[0].raw = level_a;
  lines_[1].raw = level_b;
  if (parameters_.mode == EncoderMode::kStep) {
    if (level_b != lines_[1].decoded) apply(EncoderLine::kB, level_b, t_ns);
    if (level_a != lines_[0].decoded) apply(EncoderLine::kA, level_a, t_ns);
    return;
  }
  apply_state(level_a, level_b, t_ns);
}

void QuadratureDecoder::advance_to(std::int64_t t_ns) noexcept {
  if (parameters_.debounce_ns > 0) settle(t_ns);
}

}  // namespace cosmos
