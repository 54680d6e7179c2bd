#include "sim/twins/simulated_gpio_lines.hpp"

#include <algorithm>
#include <cmath>

namespace cosmos {
namespace {

// Ticks emitted between two drains of the merger: at most 16 edges per line, as one read
// of a kernel event FIFO delivers, well inside the merger's rings.
constexpr std::int64_t kTicksPerBatch = 16;

std::vector<BeamInterruption> beam_interruptions_of(const SimulatedConveyor& conveyor,
                                                    double beam_y_mm) {
  // At tick e the part spans y_scanner in [y_min + e·m, y_max + e·m] (conveyor_scene.hpp).
  const double mm_per_tick = conveyor.parameters().encoder_mm_per_tick;
  std::vector<BeamInterruption> interruptions;
  for (const PlacedSimPart& part : conveyor.placed_parts()) {
    const auto enter =
        static_cast<std::int64_t>(std::ceil((beam_y_mm - part.bounds_mm.max().y()) / mm_per_tick));
    const auto leave = static_cast<std::int64_t>(
                           std::floor((beam_y_mm - part.bounds_mm.min().y()) / mm_per_tick)) +
                       1;
    interruptions.push_back({enter, leave});
  }
  std::sort(interruptions.begin(), interruptions.end(),
            [](const BeamInterruption& a, const BeamInterruption& b) {
              return a.enter_tick < b.enter_tick;
            });
  return interruptions;
}

}  // namespace

SimulatedGpioLines::SimulatedGpioLines(const SimulatedConveyor& conveyor,
                                       const SimulatedBeltClock& clock, const GpioConfig& config,
                                       const SimulatedGpioSettings& settings,
                                       const FaultPlan& faults)
    : clock_(clock),
      config_(config),
      faults_(faults),
      beam_(beam_interruptions_of(conveyor, settings.photo_eye_y_mm)),
      decoder_(GpioInputParameters{
          {config.encoder_mode, config.encoder_debounce_ns(), /*has_direction_line=*/true},
          {config.photo_eye_debounce_ns(), config.photo_eye_min_on_ns(),
           config.photo_eye_min_off_ns()}}) {
  // Parts that overlap along the belt interrupt the beam as one.
  for (const BeamInterruption& interruption : beam_) {
    if (!beam_edges_.empty() && interruption.enter_tick <= beam_edges_.back().tick) {
      beam_edges_.back().tick = std::max(beam_edges_.back().tick, interruption.leave_tick);
      continue;
    }
    beam_edges_.push_back({interruption.enter_tick, true});
    beam_edges_.push_back({interruption.leave_tick, false});
  }
  writes_.reserve(kWriteCapacity);
}

bool SimulatedGpioLines::level_a(std::int64_t position) const noexcept {
  if (config_.encoder_mode == EncoderMode::kStep) return false;  // between pulses
  const std::int64_t phase = ((position % 4) + 4) % 4;           // 00 → 10 → 11 → 01
  return phase == 1 || phase == 2;
}

bool SimulatedGpioLines::level_b(std::int64_t position) const noexcept {
  if (config_.encoder_mode == EncoderMode::kStep) return false;  // direction: forward
  const std::int64_t phase = ((position % 4) + 4) % 4;
  return phase == 2 || phase == 3;
}

std::int64_t SimulatedGpioLines::profile_of_tick(std::int64_t tick) const noexcept {
  const std::int64_t per_profile = std::max(clock_.ticks_per_frame(), 1);
  return (tick + per_profile - 1) / per_profile;
}

bool SimulatedGpioLines::beam_interrupted(std::int64_t tick) const noexcept {
  bool present = false;
  for (const BeamEdge& edge : beam_edges_) {
    if (edge.tick > tick) break;
    present = edge.present;
  }
  return present;
}

GpioStatus SimulatedGpioLines::start() noexcept {
  if (started_) return GpioStatus::kOk;
  error_.clear();
  const std::int64_t tick = clock_.ticks_now();
  if (tick == 0) position_offset_ = 0;  // a rewound belt: the encoder is where the belt is
  position_ = tick + position_offset_;
  step_down_ = false;
  merger_.clear();
  decoder_.reset(level_a(position_), level_b(position_), beam_interrupted(tick), clock_.now_ns());
  next_tick_ = tick + 1;
  next_beam_edge_ = 0;
  while (next_beam_edge_ < beam_edges_.size() && beam_edges_[next_beam_edge_].tick <= tick)
    ++next_beam_edge_;
  outputs_ = {};
  started_ = true;
  return GpioStatus::kOk;
}

GpioStatus SimulatedGpioLines::stop() noexcept {
  if (!started_) return GpioStatus::kOk;
  for (std::size_t i = 0; i < kOutputCount; ++i) {
    if (outputs_[i]) set_output(static_cast<GpioOutput>(i), false);
  }
  started_ = false;
  return GpioStatus::kOk;
}

void SimulatedGpioLines::push_encoder_edges(std::int64_t tick) noexcept {
  const std::int64_t t_ns = clock_.tick_time_ns(tick);
  const std::int64_t profile = profile_of_tick(tick);
  int step = 1;
  if (faults_.active(InjectedFault::kEncoderStuck, profile)) {
    step = 0;
  } else if (faults_.active(InjectedFault::kEncoderReversal, profile)) {
    step = -1;
  }
  const std::int64_t from = position_;
  position_ += step;
  position_offset_ = position_ - tick;
  if (step == 0) return;
  const bool first_of_profile = tick == (profile - 1) * clock_.ticks_per_frame() + 1;
  if (first_of_profile && faults_.active(InjectedFault::kEncoderGlitch, profile)) return;
  if (config_.encoder_mode == EncoderMode::kStep) {
    // B, the direction, changes before the step it sets (high: counting down).
    if ((step < 0) != step_down_) {
      step_down_ = step < 0;
      merger_.push({t_ns - 1, GpioInput::kEncoderB, step_down_});
    }
    merger_.push({t_ns, GpioInput::kEncoderA, true});
    merger_.push({(t_ns + clock_.tick_time_ns(tick + 1)) / 2, GpioInput::kEncoderA, false});
    return;
  }
  // One line changes per position: A into odd phases, B into even ones; backwards, the line
  // that changed on the way up changes back.
  const std::int64_t crossed = step > 0 ? position_ : from;
  if (((crossed % 2) + 2) % 2 != 0) {
    merger_.push({t_ns, GpioInput::kEncoderA, level_a(position_)});
  } else {
    merger_.push({t_ns, GpioInput::kEncoderB, level_b(position_)});
  }
}

void SimulatedGpioLines::push_beam_edge(const BeamEdge& edge) noexcept {
  const std::int64_t t_ns = clock_.tick_time_ns(edge.tick);
  merger_.push({t_ns, GpioInput::kPhotoEye, edge.present});
  if (!faults_.active(InjectedFault::kPhotoEyeBounce, profile_of_tick(edge.tick))) return;
  const std::int64_t bounce_ns = std::max<std::int64_t>(config_.photo_eye_debounce_ns() / 4, 1);
  for (int k = 1; k <= 4; ++k)
    merger_.push(
        {t_ns + k * bounce_ns, GpioInput::kPhotoEye, k % 2 == 0 ? edge.present : !edge.present});
}

GpioStatus SimulatedGpioLines::poll_inputs(std::int64_t) noexcept {
  if (!started_) {
    error_.set("simulated GPIO: poll_inputs: lines not started");
    return GpioStatus::kWrongState;
  }
  const std::int64_t target_tick = clock_.ticks_now();
  const auto decode = [this](const GpioEdge& edge) { decoder_.on_edge(edge); };
  bool edges = false;
  while (next_tick_ <= target_tick) {
    const std::int64_t last_tick = std::min(target_tick, next_tick_ + kTicksPerBatch - 1);
    for (; next_tick_ <= last_tick; ++next_tick_) push_encoder_edges(next_tick_);
    for (; next_beam_edge_ < beam_edges_.size() && beam_edges_[next_beam_edge_].tick <= last_tick;
         ++next_beam_edge_) {
      push_beam_edge(beam_edges_[next_beam_edge_]);
    }
    merger_.drain(clock_.tick_time_ns(last_tick), decode);
    edges = true;
  }
  decoder_.advance_to(clock_.now_ns());
  return edges ? GpioStatus::kOk : GpioStatus::kTimeout;
}

GpioStatus SimulatedGpioLines::encoder_at(std::int64_t t_ns, std::int64_t,
                                          EncoderAtTime& at) noexcept {
  if (poll_inputs(0) == GpioStatus::kWrongState) return GpioStatus::kError;
  const EncoderHistory::Count count = decoder_.encoder_ticks_at(t_ns);
  at.ticks = count.ticks;
  at.settled = count.covered && decoder_.decoded_until_ns() >= t_ns;
  return GpioStatus::kOk;
}

void SimulatedGpioLines::record(GpioOutput output, bool active) noexcept {
  if (writes_.size() == kWriteCapacity) {
    ++unrecorded_writes_;
    return;
  }
  writes_.push_back({output, active, clock_.now_ns(), clock_.frame()});
}

GpioStatus SimulatedGpioLines::set_output(GpioOutput output, bool active) noexcept {
  const auto index = static_cast<std::size_t>(output);
  if (!started_) {
    error_.set("simulated GPIO: set_output: lines not started");
    return GpioStatus::kWrongState;
  }
  if (active && !outputs_[index]) ++activations_[index];
  outputs_[index] = active;
  record(output, active);
  return GpioStatus::kOk;
}

bool SimulatedGpioLines::output_active(GpioOutput output) const noexcept {
  return outputs_[static_cast<std::size_t>(output)];
}

std::uint64_t SimulatedGpioLines::activations(GpioOutput output) const noexcept {
  return activations_[static_cast<std::size_t>(output)];
}

}  // namespace cosmos
