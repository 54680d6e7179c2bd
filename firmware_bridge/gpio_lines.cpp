#include "firmware_bridge/gpio_lines.hpp"

#include <gpiod.h>

#include <algorithm>
#include <cerrno>
#include <cstdarg>
#include <cstdio>
#include <ctime>
#include <utility>

#include "firmware_bridge/kernel_timestamp.hpp"

namespace cosmos {

namespace {

constexpr std::array<const char*, kGpioInputCount> kInputRoles = {"encoder_a", "encoder_b",
                                                                  "photo_eye"};
constexpr std::array<const char*, 2> kOutputRoles = {"laser_enable", "result_ready"};

// "\"ENC_A\"" or "17": how the config named the line.
struct LineLabel {
  char text[72] = {};
  explicit LineLabel(const GpioLineRef& ref) noexcept {
    if (!ref.name.empty()) {
      std::snprintf(text, sizeof text, "\"%s\"", ref.name.c_str());
    } else {
      std::snprintf(text, sizeof text, "%d", ref.offset);
    }
  }
};

}  // namespace

LibgpiodLines::LibgpiodLines(GpioConfig config)
    : config_(std::move(config)),
      decoder_(GpioInputParameters{
          {config_.encoder_mode, config_.encoder_debounce_ns(), config_.encoder_b.configured()},
          {config_.photo_eye_debounce_ns(), config_.photo_eye_min_on_ns(),
           config_.photo_eye_min_off_ns()}}) {}

LibgpiodLines::~LibgpiodLines() { stop(); }

const GpioLineRef& LibgpiodLines::input_ref(std::size_t input) const noexcept {
  const std::array<const GpioLineRef*, kGpioInputCount> refs = {
      &config_.encoder_a, &config_.encoder_b, &config_.photo_eye};
  return *refs[input];
}

const GpioLineRef& LibgpiodLines::output_ref(std::size_t output) const noexcept {
  const std::array<const GpioLineRef*, kOutputCount> refs = {&config_.laser_enable,
                                                             &config_.result_ready};
  return *refs[output];
}

GpioStatus LibgpiodLines::fail(const char* format, ...) noexcept {
  char reason[ErrorLine::kCapacity];
  va_list arguments;
  va_start(arguments, format);
  std::vsnprintf(reason, sizeof reason, format, arguments);
  va_end(arguments);
  error_.set("%s: %s", config_.chip.c_str(), reason);
  return GpioStatus::kError;
}

GpioStatus LibgpiodLines::find_line(const GpioLineRef& ref, const char* role,
                                    gpiod_line*& line) noexcept {
  const LineLabel label(ref);
  if (!ref.name.empty()) {
    line = gpiod_chip_find_line(chip_, ref.name.c_str());
    if (line == nullptr) {
      return errno == ENOENT
                 ? fail("line %s (%s): no line of that name on this chip", label.text, role)
                 : fail("line %s (%s): %s", label.text, role, errno_text(errno));
    }
    return GpioStatus::kOk;
  }
  const unsigned line_count = gpiod_chip_num_lines(chip_);
  if (static_cast<unsigned>(ref.offset) >= line_count) {
    return fail("line %s (%s): offset out of range, the chip has %u lines", label.text, role,
                line_count);
  }
  line = gpiod_chip_get_line(chip_, static_cast<unsigned>(ref.offset));
  if (line == nullptr) return fail("line %s (%s): %s", label.text, role, errno_text(errno));
  return GpioStatus::kOk;
}

GpioStatus LibgpiodLines::open_lines() noexcept {
  if (!config_.encoder_a.configured()) return fail("encoder_a: no line configured");
  if (config_.encoder_mode == EncoderMode::kQuadrature && !config_.encoder_b.configured()) {
    return fail("encoder_b: no line configured, quadrature decoding needs both A and B");
  }
  errno = 0;
  chip_ = gpiod_chip_open_lookup(config_.chip.c_str());
  if (chip_ == nullptr) {
    return fail("cannot open GPIO chip: %s", errno == 0 ? "not found" : errno_text(errno));
  }
  const char* consumer = config_.consumer.c_str();
  std::array<bool, kGpioInputCount> levels{};
  for (std::size_t i = 0; i < kGpioInputCount; ++i) {
    const GpioLineRef& ref = input_ref(i);
    if (!ref.configured()) continue;
    if (const GpioStatus status = find_line(ref, kInputRoles[i], inputs_[i]);
        status != GpioStatus::kOk)
      return status;
    const LineLabel label(ref);
    // Edges are requested in electrical terms and active_low applied here, so the meaning
    // of an event type never depends on how a kernel version treats the ACTIVE_LOW flag.
    if (gpiod_line_request_both_edges_events(inputs_[i], consumer) < 0) {
      return fail("line %s (%s): cannot request edge events: %s", label.text, kInputRoles[i],
                  errno_text(errno));
    }
    const int value = gpiod_line_get_value(inputs_[i]);
    if (value < 0)
      return fail("line %s (%s): cannot read: %s", label.text, kInputRoles[i], errno_text(errno));
    levels[i] = (value != 0) != ref.active_low;
  }
  for (std::size_t i = 0; i < kOutputCount; ++i) {
    const GpioLineRef& ref = output_ref(i);
    if (!ref.configured()) continue;
    if (const GpioStatus status = find_line(ref, kOutputRoles[i], outputs_[i]);
        status != GpioStatus::kOk) {
      return status;
    }
    if (gpiod_line_request_output(outputs_[i], consumer, ref.active_low ? 1 : 0) < 0) {
      return fail("line %s (%s): cannot request as output: %s", LineLabel(ref).text,
                  kOutputRoles[i], errno_text(errno));
    }
  }
  decoder_.reset(levels[0], levels[1], levels[2], monotonic_now_ns());
  // The events since the levels were read are queued already: the pump reads from there.
  std::array<GpioEventPump::Line, kGpioInputCount> watched{};
  std::size_t count = 0;
  for (std::size_t i = 0; i < kGpioInputCount; ++i) {
    if (inputs_[i] == nullptr) continue;
    watched[count++] = {gpiod_line_event_get_fd(inputs_[i]), static_cast<GpioInput>(i),
                        input_ref(i).active_low, kInputRoles[i]};
  }
  if (!pump_.start(watched.data(), count)) {
    return fail("%.*s", static_cast<int>(pump_.error().size()), pump_.error().data());
  }
  return GpioStatus::kOk;
}

GpioStatus LibgpiodLines::start() noexcept {
  if (started()) return GpioStatus::kOk;
  const GpioStatus status = open_lines();
  if (status != GpioStatus::kOk) stop();
  return status;
}

GpioStatus LibgpiodLines::stop() noexcept {
  if (!started()) return GpioStatus::kOk;
  pump_.stop();  // before the lines (and their event fds) go
  // Releasing a line leaves it at its last level on most GPIO drivers: drive every output,
  // above all the laser enable, inactive before letting go.
  for (std::size_t i = 0; i < kOutputCount; ++i) {
    if (outputs_[i] != nullptr && gpiod_line_is_requested(outputs_[i])) {
      gpiod_line_set_value(outputs_[i], output_ref(i).active_low ? 1 : 0);
    }
  }
  gpiod_chip_close(chip_);  // releases every line requested from it
  chip_ = nullptr;
  inputs_ = {};
  outputs_ = {};
  return GpioStatus::kOk;
}

GpioStatus LibgpiodLines::set_output(GpioOutput output, bool active) noexcept {
  const auto index = static_cast<std::size_t>(output);
  if (!started()) {
    fail("%s: lines not started", kOutputRoles[index]);
    return GpioStatus::kWrongState;
  }
  if (outputs_[index] == nullptr) return GpioStatus::kNotConfigured;
  const GpioLineRef& ref = output_ref(index);
  if (gpiod_line_set_value(outputs_[index], active != ref.active_low ? 1 : 0) < 0) {
    return fail("line %s (%s): cannot set: %s", LineLabel(ref).text, kOutputRoles[index],
                errno_text(errno));
  }
  return GpioStatus::kOk;
}

GpioStatus LibgpiodLines::poll_inputs(std::int64_t timeout_ns) noexcept {
  if (!started()) {
    fail("poll_inputs: lines not started");
    return GpioStatus::kWrongState;
  }
  // Read before popping: every edge up to it has been handed over (GpioEventPump).
  std::int64_t known_ns = pump_.known_until_ns();
  bool decoded = false;
  GpioEdge edge;
  while (pump_.pop(edge)) {
    decoder_.on_edge(edge);
    decoded = true;
  }
  if (!decoded && timeout_ns > 0) {
    pump_.wait(timeout_ns);
    known_ns = pump_.known_until_ns();
    while (pump_.pop(edge)) {
      decoder_.on_edge(edge);
      decoded = true;
    }
  }
  if (pump_.failed()) {
    return fail("%.*s", static_cast<int>(pump_.error().size()), pump_.error().data());
  }
  decoder_.advance_to(known_ns);
  return decoded ? GpioStatus::kOk : GpioStatus::kTimeout;
}

GpioStatus LibgpiodLines::encoder_at(std::int64_t t_ns, std::int64_t wait_ns,
                                     EncoderAtTime& at) noexcept {
  const auto failed = [](GpioStatus status) {
    return status == GpioStatus::kError || status == GpioStatus::kWrongState;
  };
  if (const GpioStatus polled = poll_inputs(0); failed(polled)) return polled;
  const std::int64_t deadline_ns = monotonic_now_ns() + wait_ns;
  while (decoder_.decoded_until_ns() < t_ns) {
    const std::int64_t now_ns = monotonic_now_ns();
    if (now_ns >= deadline_ns) break;
    if (now_ns < t_ns) {
      // A time stamp still ahead (a driver that stamps the frame's end in advance): no read
      // of the lines can settle it before then.
      const timespec until = ns_to_timespec(std::min(t_ns, deadline_ns));
      clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &until, nullptr);
      continue;
    }
    pump_.request_cut();
    pump_.wait(deadline_ns - now_ns);
    if (const GpioStatus polled = poll_inputs(0); failed(polled)) return polled;
  }
  const EncoderHistory::Count count = decoder_.encoder_ticks_at(t_ns);
  at.ticks = count.ticks;
  at.settled = count.covered && decoder_.decoded_until_ns() >= t_ns;
  return GpioStatus::kOk;
}

}  // namespace cosmos
