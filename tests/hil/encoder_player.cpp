#include "tests/hil/encoder_player.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iterator>

#include "firmware_bridge/kernel_timestamp.hpp"

namespace cosmos::hil {
namespace {

// How often the thread looks for the cell's line requests (their interrupt threads): while
// waiting for the first, and later in case the cell requested its lines again.
constexpr std::int64_t kArmPollNs = 20'000'000;
constexpr std::int64_t kRefreshNs = 1'000'000'000;
// Steps of a run of a few minutes (sixteen thousand and some), reserved once.
constexpr std::size_t kStepsReserved = 1 << 16;

}  // namespace

EncoderPlayer::EncoderPlayer(GpioSimLines& lines, const EncoderPlayerSettings& settings)
    : lines_(lines), settings_(settings) {
  const QuadratureLevels levels = quadrature_levels(0);
  lines_.drive(settings_.line_a, levels.a);
  lines_.drive(settings_.line_b, levels.b);
  lines_.drive(settings_.photo_eye, false);
  steps_.reserve(kStepsReserved);
  thread_ = std::thread([this] { run(); });
}

EncoderPlayer::~EncoderPlayer() { stop(); }

void EncoderPlayer::stop() {
  stop_ = true;
  wake_.notify_all();
  if (thread_.joinable()) thread_.join();
}

void EncoderPlayer::observe_capture(std::int64_t sequence, std::int64_t t_ns) {
  const auto t0 = t_ns - static_cast<std::int64_t>(std::llround(static_cast<double>(sequence) *
                                                                settings_.frame_period_ns));
  std::int64_t current = t0_ns_.load();
  while ((current == 0 || t0 < current) && !t0_ns_.compare_exchange_weak(current, t0)) {
  }
}

void EncoderPlayer::jiggle(int ticks) {
  std::lock_guard lock(mutex_);
  jiggles_.push_back(ticks);
  wake_.notify_all();
}

void EncoderPlayer::glitch() {
  std::lock_guard lock(mutex_);
  ++glitches_pending_;
  wake_.notify_all();
}

EncoderPlayerCounts EncoderPlayer::counts() const {
  std::lock_guard lock(mutex_);
  EncoderPlayerCounts counts = counts_;
  counts.unacknowledged_edges = lines_.unacknowledged_edges();
  return counts;
}

std::int64_t EncoderPlayer::tick_at(std::int64_t t_ns) const {
  std::lock_guard lock(mutex_);
  const auto after =
      std::upper_bound(steps_.begin(), steps_.end(), t_ns,
                       [](std::int64_t t, const Step& step) { return t < step.t_ns; });
  return after == steps_.begin() ? 0 : std::prev(after)->tick;
}

void EncoderPlayer::drive_photo_eye(std::int64_t tick) {
  const std::int64_t conveyor_tick = tick - settings_.beam_offset_ticks;
  const std::vector<BeamInterruption>& beam = settings_.beam;
  while (next_beam_ < beam.size() && beam[next_beam_].leave_tick <= conveyor_tick && !eye_) {
    ++next_beam_;
  }
  const bool interrupted = next_beam_ < beam.size() &&
                           beam[next_beam_].enter_tick <= conveyor_tick &&
                           conveyor_tick < beam[next_beam_].leave_tick;
  if (interrupted == eye_) return;
  if (interrupted && settings_.bouncing_arrivals.count(next_beam_) != 0) {
    lines_.drive(settings_.photo_eye, true);
    lines_.drive(settings_.photo_eye, false);
    std::lock_guard lock(mutex_);
    ++counts_.bounced_arrivals;
    counts_.edges += 2;
  }
  lines_.drive(settings_.photo_eye, interrupted);
  eye_ = interrupted;
  std::lock_guard lock(mutex_);
  ++counts_.edges;
  if (interrupted) ++counts_.beam_arrivals;
}

void EncoderPlayer::step_to(std::int64_t tick) {
  while (tick_ != tick && !stop_) {
    const std::int64_t next = tick_ + (tick > tick_ ? 1 : -1);
    const QuadratureLevels before = quadrature_levels(tick_);
    const QuadratureLevels after = quadrature_levels(next);
    if (after.a != before.a) lines_.drive(settings_.line_a, after.a);
    if (after.b != before.b) lines_.drive(settings_.line_b, after.b);
    tick_ = next;
    drive_photo_eye(tick_);
    std::lock_guard lock(mutex_);
    ++counts_.edges;
    counts_.tick = tick_;
    steps_.push_back({monotonic_now_ns(), tick_});
  }
}

void EncoderPlayer::do_jiggle(int ticks) {
  const std::int64_t from = tick_;
  step_to(from - ticks);
  step_to(from);
  std::lock_guard lock(mutex_);
  ++counts_.jiggles;
  counts_.jiggle_reversals += 2;
}

void EncoderPlayer::do_glitch() {
  lines_.pulse(settings_.line_a);
  std::lock_guard lock(mutex_);
  ++counts_.glitches;
}

void EncoderPlayer::run() {
  const double tick_period_ns = settings_.frame_period_ns / settings_.ticks_per_frame;
  bool armed = false;
  std::int64_t last_refresh_ns = 0;
  while (!stop_) {
    const std::int64_t now_ns = monotonic_now_ns();
    if (now_ns - last_refresh_ns >= (armed ? kRefreshNs : kArmPollNs)) {
      lines_.find_interrupt_threads();
      last_refresh_ns = now_ns;
      armed = armed || (lines_.has_interrupt_thread(settings_.line_a) &&
                        lines_.has_interrupt_thread(settings_.line_b));
    }
    const std::int64_t t0_ns = t0_ns_.load();
    std::int64_t wait_ns = kArmPollNs;
    if (armed && t0_ns != 0) {
      int jiggle = 0;
      bool glitch = false;
      {
        std::lock_guard lock(mutex_);
        if (!jiggles_.empty()) {
          jiggle = jiggles_.front();
          jiggles_.pop_front();
        } else if (glitches_pending_ > 0) {
          --glitches_pending_;
          glitch = true;
        }
      }
      if (jiggle > 0) do_jiggle(jiggle);
      if (glitch) do_glitch();
      const auto target = static_cast<std::int64_t>(
          std::floor(static_cast<double>(monotonic_now_ns() - t0_ns) / tick_period_ns));
      if (target > tick_) step_to(target);
      const double next_tick_ns = static_cast<double>(t0_ns) + (tick_ + 1) * tick_period_ns;
      wait_ns =
          std::max<std::int64_t>(0, static_cast<std::int64_t>(next_tick_ns) - monotonic_now_ns());
    }
    std::unique_lock lock(mutex_);
    if (jiggles_.empty() && glitches_pending_ == 0) {
      wake_.wait_for(lock, std::chrono::nanoseconds(std::min(wait_ns, kArmPollNs)));
    }
  }
}

}  // namespace cosmos::hil
