#pragma once
// Conveyor encoder position from the edges of its output lines, with the kernel's time stamps.
//
// Quadrature mode: lines A and B are square waves 90° apart; each edge of either line is one
// count (4× decoding), and which line leads gives the direction (A leading B counts up).
// The Gray sequence lets exactly one line change per count, so an edge that does not fit it
// is an error, never a step: an edge repeating its line's level means the opposite edge was
// missed (kernel event FIFO overflow, a glitch shorter than the input can resolve), and a
// sample in which both lines changed skipped a state. Both are counted in invalid_transitions
// and leave the count alone: counting them would add a guess to the position.
//
// Step mode: line A is a step pulse (one count per rising edge) and line B, if wired, a
// direction level (high = counting down), as from a stepper drive or a single-channel sensor.
//
// Debounce: an edge closer than debounce_ns to the previous edge on the same line is
// contact/electrical bounce and is not counted. Its level is still tracked, and once the
// line has been quiet for debounce_ns a level that ended up different from the counted one
// is applied then: a glitch (edge + ignored return edge) nets to zero counts instead of
// leaving the decoder one state off. debounce_ns must stay well below the shortest quarter
// period at top belt speed, or real edges are taken for bounce.
//
// Every count is also kept with its edge's time stamp (EncoderHistory), so the count at a
// past instant, a frame's exposure, can be asked for once the edges up to it are decoded.
//
// Real-time: fixed state, no allocation, no exceptions.
#include <array>
#include <cstdint>

#include "firmware_bridge/encoder_history.hpp"

namespace cosmos {

enum class EncoderMode : std::uint8_t { kQuadrature, kStep };
enum class EncoderLine : std::uint8_t { kA = 0, kB = 1 };

struct QuadratureDecoderParameters {
  EncoderMode mode = EncoderMode::kQuadrature;
  std::int64_t debounce_ns = 0;     // 0 = every edge counts
  bool has_direction_line = false;  // step mode: line B gives the direction
};

struct EncoderCounts {
  std::int64_t ticks = 0;
  std::int64_t last_step_t_ns = 0;  // time stamp of the edge that made the last count
  int direction = 0;                // +1 / −1 of the last count, 0 before the first
  std::uint64_t steps = 0;          // counts made, either direction
  std::uint64_t reversals = 0;      // direction changes between consecutive counts
  std::uint64_t invalid_transitions = 0;
  std::uint64_t ignored_edges = 0;  // bounce inside debounce_ns
};

class QuadratureDecoder {
 public:
  explicit QuadratureDecoder(const QuadratureDecoderParameters& parameters = {});

  // The lines' levels as read when the lines were requested at t_ns, and the count to start
  // from.
  void reset(bool level_a, bool level_b, std::int64_t ticks = 0,
             std::int64_t t_ns = EncoderHistory::kSinceEver) noexcept;

  // One kernel edge event, in time order: `level` is the line's level after the edge.
  void on_edge(EncoderLine line, bool level, std::int64_t t_ns) noexcept;
  // Both levels sampled at once (for inputs that deliver states rather than edges).
  void on_sample(bool level_a, bool level_b, std::int64_t t_ns) noexcept;
  // Time has passed without edges: settles lines whose last ignored edge left them changed.
  void advance_to(std::int64_t t_ns) noexcept;

  const EncoderCounts& counts() const noexcept { return counts_; }
  std::int64_t ticks() const noexcept { return counts_.ticks; }
  // The count after every edge decoded so far that was stamped at or before t_ns.
  EncoderHistory::Count ticks_at(std::int64_t t_ns) const noexcept {
    return history_.ticks_at(t_ns);
  }
  const QuadratureDecoderParameters& parameters() const noexcept { return parameters_; }

 private:
  struct LineState {
    bool decoded = false;  // the level the count is based on
    bool raw = false;      // the level after the latest edge, bounce included
    bool seen_edge = false;
    std::int64_t last_edge_t_ns = 0;
  };

  void settle(std::int64_t t_ns) noexcept;
  void apply(EncoderLine line, bool level, std::int64_t t_ns) noexcept;
  void apply_state(bool level_a, bool level_b, std::int64_t t_ns) noexcept;
  void count(int step, std::int64_t t_ns) noexcept;

  QuadratureDecoderParameters parameters_;
  std::array<LineState, 2> lines_{};
  EncoderCounts counts_;
  EncoderHistory history_;
};

}  // namespace cosmos
