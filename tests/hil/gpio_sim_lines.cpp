#include "tests/hil/gpio_sim_lines.hpp"

#include <fcntl.h>
#include <sched.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace cosmos::hil {
namespace {

namespace fs = std::filesystem;

// Long enough for a guest CPU the host has descheduled: an edge handed over before the
// thread ran is lost for good, one handed over late only holds the belt back a moment.
constexpr auto kThreadWait = std::chrono::milliseconds(1000);

std::string read_attribute(const fs::path& path) {
  std::ifstream file(path);
  std::string text;
  if (!file || !std::getline(file, text)) {
    throw std::runtime_error(path.string() + ": cannot read");
  }
  return text;
}

struct ThreadState {
  long long voluntary_switches = -1;  // -1: the thread is gone
  bool sleeping = false;              // "S": waiting for its next interrupt
};

ThreadState thread_state(const std::string& status_path) {
  std::ifstream file(status_path);
  std::string line;
  ThreadState state;
  while (std::getline(file, line)) {
    if (line.rfind("State:", 0) == 0) state.sleeping = line.find('S', 6) != std::string::npos;
    if (line.rfind("voluntary_ctxt_switches:", 0) == 0) {
      state.voluntary_switches = std::stoll(line.substr(line.find(':') + 1));
    }
  }
  return state;
}

}  // namespace

QuadratureLevels quadrature_levels(long long tick) {
  const long long phase = ((tick % 4) + 4) % 4;
  constexpr QuadratureLevels kCycle[4] = {
      {false, false}, {true, false}, {true, true}, {false, true}};
  return kCycle[phase];
}

GpioSimLines::GpioSimLines(const std::string& device_dir) {
  const fs::path device(device_dir);
  const std::string dev_name = read_attribute(device / "dev_name");
  chip_name_ = read_attribute(device / "bank0" / "chip_name");
  const int count = std::stoi(read_attribute(device / "bank0" / "num_lines"));
  const fs::path sysfs = fs::path("/sys/devices/platform") / dev_name / chip_name_;
  for (int i = 0; i < count; ++i) {
    Line line;
    const fs::path line_dir = device / "bank0" / ("line" + std::to_string(i));
    line.name = fs::exists(line_dir / "name") ? read_attribute(line_dir / "name") : "";
    const fs::path attributes = sysfs / ("sim_gpio" + std::to_string(i));
    line.pull_fd = ::open((attributes / "pull").c_str(), O_WRONLY);
    if (line.pull_fd < 0) {
      throw std::runtime_error((attributes / "pull").string() + ": open: " + std::strerror(errno));
    }
    line.value_path = (attributes / "value").string();
    lines_.push_back(std::move(line));
  }
}

GpioSimLines::~GpioSimLines() {
  for (const Line& line : lines_) ::close(line.pull_fd);
}

int GpioSimLines::offset(const std::string& name) const {
  for (std::size_t i = 0; i < lines_.size(); ++i) {
    if (lines_[i].name == name) return static_cast<int>(i);
  }
  throw std::runtime_error("gpio-sim chip " + chip_name_ + ": no line named " + name);
}

void GpioSimLines::find_interrupt_threads() {
  for (Line& line : lines_) line.thread_status.clear();
  // "  24:   0   1   irq_sim   0  cosmos-cell": interrupt 24 is line 0's, requested.
  std::ifstream interrupts("/proc/interrupts");
  std::string text;
  std::vector<int> irq_of_line(lines_.size(), -1);
  while (std::getline(interrupts, text)) {
    const std::size_t chip = text.find(" irq_sim ");
    const std::size_t colon = text.find(':');
    if (chip == std::string::npos || colon == std::string::npos) continue;
    std::istringstream rest(text.substr(chip + 9));
    std::size_t hwirq = 0;
    if (!(rest >> hwirq) || hwirq >= lines_.size()) continue;
    irq_of_line[hwirq] = std::stoi(text.substr(0, colon));
  }
  for (const fs::directory_entry& process : fs::directory_iterator("/proc")) {
    const std::string pid = process.path().filename().string();
    if (pid.empty() || pid[0] < '0' || pid[0] > '9') continue;
    std::ifstream comm(process.path() / "comm");
    std::string name;
    if (!std::getline(comm, name) || name.rfind("irq/", 0) != 0) continue;
    const int irq = std::atoi(name.c_str() + 4);
    for (std::size_t i = 0; i < lines_.size(); ++i) {
      if (irq_of_line[i] == irq) lines_[i].thread_status = (process.path() / "status").string();
    }
  }
}

bool GpioSimLines::wait_for_thread(Line& line, long long switches_before) {
  const auto deadline = std::chrono::steady_clock::now() + kThreadWait;
  while (std::chrono::steady_clock::now() < deadline) {
    const ThreadState state = thread_state(line.thread_status);
    if (state.voluntary_switches < 0) {
      line.thread_status.clear();  // the cell released the line
      return true;
    }
    // Asleep again after running: it may also have slept on gpio-sim's lock while reading the
    // level (state D), which is not done.
    if (state.voluntary_switches > switches_before && state.sleeping) return true;
    sched_yield();
  }
  return false;
}

void GpioSimLines::write_pull(const Line& line, int offset, bool high) const {
  const char* text = high ? "pull-up" : "pull-down";
  if (::pwrite(line.pull_fd, text, std::strlen(text), 0) < 0) {
    throw std::runtime_error("gpio-sim chip " + chip_name_ + ": line " + std::to_string(offset) +
                             ": pull: " + std::strerror(errno));
  }
}

void GpioSimLines::drive(int offset, bool high) {
  Line& line = lines_[static_cast<std::size_t>(offset)];
  if (line.level == (high ? 1 : 0)) return;
  const long long before =
      line.thread_status.empty() ? -1 : thread_state(line.thread_status).voluntary_switches;
  write_pull(line, offset, high);
  line.level = high ? 1 : 0;
  if (before >= 0 && !wait_for_thread(line, before)) ++unacknowledged_;
}

void GpioSimLines::pulse(int offset) {
  Line& line = lines_[static_cast<std::size_t>(offset)];
  const bool level = line.level == 1;
  const long long before =
      line.thread_status.empty() ? -1 : thread_state(line.thread_status).voluntary_switches;
  write_pull(line, offset, !level);
  write_pull(line, offset, level);
  line.level = level ? 1 : 0;
  if (before >= 0 && !wait_for_thread(line, before)) ++unacknowledged_;
}

bool GpioSimLines::value(int offset) const {
  return read_attribute(lines_[static_cast<std::size_t>(offset)].value_path) == "1";
}

}  // namespace cosmos::hil
