#include "tests/hil/gpio_probe.hpp"

#include <chrono>
#include <cstdio>
#include <exception>
#include <thread>

#include "firmware_bridge/gpio_lines.hpp"
#include "firmware_bridge/kernel_timestamp.hpp"
#include "tests/hil/gpio_sim_lines.hpp"

namespace cosmos::hil {
namespace {

constexpr std::int64_t kQuietNs = 50'000'000;  // no edge for this long: all are read

// Reads edges until the count is `expected` and the lines have been quiet for a while, or a
// second has passed: the edge reader thread and gpio-cdev's may be late under TCG.
void drain(LibgpiodLines& lines, long long expected) {
  const std::int64_t give_up_ns = monotonic_now_ns() + 1'000'000'000;
  while (monotonic_now_ns() < give_up_ns) {
    const bool quiet = lines.poll_inputs(kQuietNs) == GpioStatus::kTimeout;
    if (quiet && lines.encoder().ticks == expected) return;
  }
}

// Moves the encoder from `from` to `to` one Gray step at a time, reading events every
// `poll_every` steps as the cell's loop does between frames.
void move_encoder(GpioSimLines& sim, int a, int b, LibgpiodLines& lines, long long from,
                  long long to, int poll_every) {
  const long long step = to > from ? 1 : -1;
  const long long expected = lines.encoder().ticks + (to - from);
  int since_poll = 0;
  for (long long tick = from + step; tick != to + step; tick += step) {
    const QuadratureLevels before = quadrature_levels(tick - step);
    const QuadratureLevels after = quadrature_levels(tick);
    if (after.a != before.a) sim.drive(a, after.a);
    if (after.b != before.b) sim.drive(b, after.b);
    if (++since_poll == poll_every) {
      lines.poll_inputs(0);
      since_poll = 0;
    }
  }
  drain(lines, expected);
}

}  // namespace

std::vector<ProbeCheck> probe_gpio(const GpioConfig& config, const std::string& device_dir) {
  std::vector<ProbeCheck> checks;
  try {
    GpioSimLines sim(device_dir);
    const int a = sim.offset(config.encoder_a.name);
    const int b = sim.offset(config.encoder_b.name);
    const int eye = sim.offset(config.photo_eye.name);
    const int laser = sim.offset(config.laser_enable.name);
    const int result = sim.offset(config.result_ready.name);
    sim.drive(a, false);
    sim.drive(b, false);
    sim.drive(eye, false);

    LibgpiodLines lines(config);
    if (lines.start() != GpioStatus::kOk) {
      checks.push_back(check_line(false, "gpio: start on %s: %.*s", sim.chip_name().c_str(),
                                  static_cast<int>(lines.last_error().size()),
                                  lines.last_error().data()));
      return checks;
    }
    sim.find_interrupt_threads();
    const bool idle = !sim.value(laser) && !sim.value(result);
    lines.set_output(GpioOutput::kLaserEnable, true);
    lines.set_output(GpioOutput::kResultReady, true);
    const bool driven = sim.value(laser) && sim.value(result);
    lines.set_output(GpioOutput::kResultReady, false);
    const bool released = sim.value(laser) && !sim.value(result);
    checks.push_back(check_line(idle && driven && released,
                                "gpio outputs on %s: inactive after start %s, laser_enable and "
                                "result_ready driven %s, result_ready released %s",
                                sim.chip_name().c_str(), idle ? "yes" : "no", driven ? "yes" : "no",
                                released ? "yes" : "no"));

    const std::int64_t before_ns = monotonic_now_ns();
    move_encoder(sim, a, b, lines, 0, 400, 16);
    const EncoderReading forward = lines.encoder();
    const bool stamped =
        forward.last_step_t_ns >= before_ns && forward.last_step_t_ns <= monotonic_now_ns();
    checks.push_back(check_line(
        forward.ticks == 400 && forward.invalid_transitions == 0 && forward.reversals == 0 &&
            stamped && lines.lost_edges() == 0 && sim.unacknowledged_edges() == 0,
        "gpio encoder forward: 400 quadrature steps driven, %lld counted, "
        "%llu invalid, %llu reversals, %llu edges lost, CLOCK_MONOTONIC "
        "time stamps %s",
        static_cast<long long>(forward.ticks),
        static_cast<unsigned long long>(forward.invalid_transitions),
        static_cast<unsigned long long>(forward.reversals),
        static_cast<unsigned long long>(lines.lost_edges()), stamped ? "yes" : "no"));

    move_encoder(sim, a, b, lines, 400, 300, 16);
    const EncoderReading back = lines.encoder();
    checks.push_back(check_line(
        back.ticks == 300 && back.reversals == 1 && back.invalid_transitions == 0,
        "gpio encoder backward: 100 steps back, count %lld (300 expected), "
        "%llu reversals, %llu invalid",
        static_cast<long long>(back.ticks), static_cast<unsigned long long>(back.reversals),
        static_cast<unsigned long long>(back.invalid_transitions)));

    // Edges made without waiting for the interrupt thread (gpio_sim_lines.hpp), then as many
    // back with it: gpio-cdev's v1 line events (libgpiod 1.6) come from a one-shot threaded
    // interrupt that reads the level in its thread, so edges closer than the thread's latency
    // are dropped or typed wrong, and v1 events carry no sequence number that would show the
    // loss. Reported, not failed.
    const EncoderReading was = lines.encoder();
    {
      GpioSimLines hasty(device_dir);  // has not looked for the interrupt threads: never waits
      move_encoder(hasty, a, b, lines, 300, 324, 48);
    }
    move_encoder(sim, a, b, lines, 324, 300, 48);
    const EncoderReading now = lines.encoder();
    checks.push_back(info_line(
        "gpio hasty edges: 24 steps forward without waiting for gpio-cdev's "
        "interrupt thread and back waiting: count off by %lld, %llu invalid, "
        "%llu reversals (2 if none lost)",
        static_cast<long long>(now.ticks - was.ticks),
        static_cast<unsigned long long>(now.invalid_transitions - was.invalid_transitions),
        static_cast<unsigned long long>(now.reversals - was.reversals)));
    // The arrival carries the count at the beam's edge: whatever the hasty edges left.
    const long long eye_ticks = lines.encoder().ticks;
    sim.drive(eye, true);
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    drain(lines, lines.encoder().ticks);
    sim.drive(eye, false);
    std::this_thread::sleep_for(std::chrono::milliseconds(60));
    drain(lines, lines.encoder().ticks);
    int arrivals = 0, departures = 0;
    long long arrival_ticks = -1;
    PhotoEyeEvent event;
    while (lines.next_photo_eye_event(event)) {
      if (event.present) {
        ++arrivals;
        arrival_ticks = event.encoder_ticks;
      } else {
        ++departures;
      }
    }
    checks.push_back(check_line(arrivals == 1 && departures == 1 && arrival_ticks == eye_ticks,
                                "gpio photo eye: a 20 ms interruption gives %d arrival(s) and %d "
                                "departure(s), the arrival at encoder count %lld (%lld expected)",
                                arrivals, departures, arrival_ticks, eye_ticks));
    lines.stop();
    checks.push_back(check_line(!sim.value(laser), "gpio stop: laser_enable %s after stop",
                                sim.value(laser) ? "still on" : "off"));
  } catch (const std::exception& error) {
    checks.push_back({false, std::string("gpio: ") + error.what()});
  }
  return checks;
}

}  // namespace cosmos::hil
