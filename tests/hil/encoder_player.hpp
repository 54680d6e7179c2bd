#pragma once
// The conveyor's encoder and photo eye, driven onto gpio-sim lines by a thread of the player.
// The belt runs at constant speed on the capture's clock, as a real belt under a free-running
// camera: tick k falls at t0 + k · P / ticks_per_frame, where t0 is when the capture's frame 0
// was exposed and P its frame period, so frame s is exposed at tick s · ticks_per_frame (the
// cell's seq and encoder count belong together as on the twins), give or take the jiffy on
// which vivid's capture thread runs. The thread holds the belt still until the cell has
// requested its encoder lines (their interrupt threads exist): the cell counts from zero
// when it starts, so earlier ticks would be lost to it.
//
// The photo eye is the conveyor's beam (ConveyorFrames::beam_interruptions), its conveyor
// ticks offset by the lead-in the player puts before the conveyor's first profile.
//
// Faults, each carried out by the thread at its next tick: a jiggle (the belt backs up n
// ticks and comes forward again: 2 reversals, no net count), a glitch (a pulse on A shorter
// than gpio-cdev's interrupt thread can see, gpio_sim_lines.hpp: the decoder's invalid
// transition, or 2 reversals if the thread was quick; never a count), and bounces of the
// beam at chosen parts' arrivals (on, off, on within a few ms).
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <mutex>
#include <set>
#include <thread>
#include <vector>

#include "sim/twins/simulated_gpio_lines.hpp"
#include "tests/hil/gpio_sim_lines.hpp"

namespace cosmos::hil {

struct EncoderPlayerSettings {
  int line_a = 0;
  int line_b = 1;
  int photo_eye = 2;
  int ticks_per_frame = 4;
  double frame_period_ns = 0;
  std::vector<BeamInterruption> beam;       // conveyor ticks
  std::int64_t beam_offset_ticks = 0;       // cell tick = conveyor tick + this
  std::set<std::size_t> bouncing_arrivals;  // indices into beam
};

struct EncoderPlayerCounts {
  std::int64_t tick = 0;  // the belt's count now (cell ticks)
  std::uint64_t edges = 0;
  std::uint64_t jiggles = 0;
  std::uint64_t jiggle_reversals = 0;  // reversals the jiggles make
  std::uint64_t glitches = 0;
  std::uint64_t bounced_arrivals = 0;
  std::uint64_t beam_arrivals = 0;
  std::uint64_t unacknowledged_edges = 0;
};

class EncoderPlayer {
 public:
  EncoderPlayer(GpioSimLines& lines, const EncoderPlayerSettings& settings);
  ~EncoderPlayer();
  EncoderPlayer(const EncoderPlayer&) = delete;
  EncoderPlayer& operator=(const EncoderPlayer&) = delete;

  // The exposure time of capture frame 0 (CLOCK_MONOTONIC ns), as far as the captures seen
  // so far tell: the earliest of t_capture(s) − s · P.
  void observe_capture(std::int64_t sequence, std::int64_t t_ns);
  void jiggle(int ticks);
  void glitch();
  EncoderPlayerCounts counts() const;
  // The count the belt had driven onto the lines at t_ns (CLOCK_MONOTONIC): the belt's true
  // count at that moment, jiggles and the hold before the cell's lines included.
  std::int64_t tick_at(std::int64_t t_ns) const;
  void stop();

 private:
  void run();
  void step_to(std::int64_t tick);
  void drive_photo_eye(std::int64_t tick);
  void do_jiggle(int ticks);
  void do_glitch();

  GpioSimLines& lines_;
  EncoderPlayerSettings settings_;
  std::atomic<std::int64_t> t0_ns_{0};  // 0: no capture seen yet
  std::atomic<bool> stop_{false};
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<int> jiggles_;  // pending: ticks of each
  int glitches_pending_ = 0;
  EncoderPlayerCounts counts_;  // under mutex_
  struct Step {
    std::int64_t t_ns = 0;  // when the lines showed `tick`
    std::int64_t tick = 0;
  };
  std::vector<Step> steps_;  // under mutex_, in time order
  std::int64_t tick_ = 0;    // the thread's
  bool eye_ = false;
  std::size_t next_beam_ = 0;
  std::thread thread_;
};

}  // namespace cosmos::hil
