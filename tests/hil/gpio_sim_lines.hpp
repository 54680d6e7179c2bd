#pragma once
// The outside of a gpio-sim chip: what the cell's encoder, photo eye and output wiring would
// be. gpio-sim (drivers/gpio/gpio-sim.c) is configured through configfs, a device with one
// bank whose lines carry names; once live, each line has sysfs attributes under the chip's
// device: `pull` ("pull-up" / "pull-down") sets the level an input sees, raising a real edge
// interrupt and a kernel line event for whoever requested the line (the cell's libgpiod
// lines), and `value` reads the level of a line the cell drives as an output.
//
// Edges are handed over one at a time. gpio-cdev turns a requested line's interrupt into a
// line event in a one-shot interrupt thread ("irq/N-consumer") that reads the line's level
// when it runs: an edge made before that thread has finished is dropped (the interrupt is
// masked) or typed by the next edge's level. A real encoder's edges are slower than that
// thread; the simulated one's would not be, under TCG. So after each edge on a requested
// line, drive() waits until the line's interrupt thread has run and gone back to sleep (its
// voluntary context switches in /proc, the thread found through /proc/interrupts), which is
// when the event is queued and the interrupt unmasked.
#include <cstdint>
#include <string>
#include <vector>

namespace cosmos::hil {

// Two-bit quadrature levels of an encoder at `tick`, in the Gray order A leading B (counting
// up): 00 → 10 → 11 → 01, repeating; negative ticks continue the cycle backwards.
struct QuadratureLevels {
  bool a = false;
  bool b = false;
};
QuadratureLevels quadrature_levels(long long tick);

class GpioSimLines {
 public:
  // `device_dir`: the live configfs device (/sys/kernel/config/gpio-sim/NAME) with one bank.
  explicit GpioSimLines(const std::string& device_dir);
  ~GpioSimLines();
  GpioSimLines(const GpioSimLines&) = delete;
  GpioSimLines& operator=(const GpioSimLines&) = delete;

  // The line's offset on the chip by its configfs name; throws when no line has it.
  int offset(const std::string& name) const;
  // Pulls the line up or down (nothing when it is there already); an input requested by the
  // cell sees the edge, and the call returns once its event is queued (see above).
  void drive(int offset, bool high);
  // A pulse shorter than the interrupt thread can resolve: the line flips and flips back
  // without waiting between, then the call waits as drive() does.
  void pulse(int offset);
  // The line's current level (an output's driven value, an input's pull).
  bool value(int offset) const;
  const std::string& chip_name() const { return chip_name_; }

  // Finds the interrupt threads of the lines requested for edges now; call after the cell
  // (re)requested its lines. Lines without one are driven without waiting.
  void find_interrupt_threads();
  bool has_interrupt_thread(int offset) const {
    return !lines_[static_cast<std::size_t>(offset)].thread_status.empty();
  }
  // Edges whose interrupt thread did not run within the wait (each waited 1 s).
  std::uint64_t unacknowledged_edges() const { return unacknowledged_; }

 private:
  struct Line {
    std::string name;
    int pull_fd = -1;
    std::string value_path;
    int level = -1;             // the last level written, -1 before the first
    std::string thread_status;  // /proc/PID/status of its interrupt thread, empty if none
  };
  bool wait_for_thread(Line& line, long long switches_before);
  void write_pull(const Line& line, int offset, bool high) const;

  std::vector<Line> lines_;
  std::string chip_name_;
  std::uint64_t unacknowledged_ = 0;
};

}  // namespace cosmos::hil
