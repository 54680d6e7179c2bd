#pragma once
// The work cell's GPIO lines through libgpiod 1.6 (the character-device API: /dev/gpiochipN).
//
// start() opens the chip, finds each configured line by name or offset, requests the inputs
// (encoder A/B, photo eye) for both-edge events and the outputs (laser enable, result
// ready) driven inactive, and reads the inputs' levels to start decoding
// from. A missing chip or line, a busy line, a bad offset: one line naming chip, line, role
// and reason.
//
// The inputs' events are read as they come by a thread of the lines' own (GpioEventPump), with
// their kernel time stamps (CLOCK_MONOTONIC on kernels ≥ 5.7) and in their order across lines:
// the kernel keeps only 16 events per line, which at 20 kHz of encoder edges is 0.8 ms, and
// the loop may be held up far longer (the cell starts its source before loading its model
// base). poll_inputs() decodes the edges the pump has handed over (GpioInputDecoder), waiting
// up to its timeout when there are none; it is lock-free and allocates nothing. encoder_at()
// decodes until the pump has read the lines past the asked time (asking it for a fresh read
// when its last one was earlier, and sleeping first while the time still lies ahead), so a
// frame's count is the count at its time stamp, whenever the frame was dequeued. libgpiod's
// set-value calls use stack arrays and plain syscalls (Debian's 1.6.3 binary calls only ioctl
// in them), so set_output() runs on the acquisition thread too.
#include <array>
#include <cstdint>

#include "firmware_bridge/error_line.hpp"
#include "firmware_bridge/gpio.hpp"
#include "firmware_bridge/gpio_config.hpp"
#include "firmware_bridge/gpio_event_pump.hpp"
#include "firmware_bridge/gpio_input_decoder.hpp"

struct gpiod_chip;
struct gpiod_line;

namespace cosmos {

class LibgpiodLines final : public GpioLines {
 public:
  explicit LibgpiodLines(GpioConfig config);
  ~LibgpiodLines() override;
  LibgpiodLines(const LibgpiodLines&) = delete;
  LibgpiodLines& operator=(const LibgpiodLines&) = delete;

  GpioStatus start() noexcept override;
  GpioStatus stop() noexcept override;
  GpioStatus poll_inputs(std::int64_t timeout_ns) noexcept override;
  EncoderReading encoder() const noexcept override { return decoder_.encoder(); }
  GpioStatus encoder_at(std::int64_t t_ns, std::int64_t wait_ns,
                        EncoderAtTime& at) noexcept override;
  bool part_present() const noexcept override { return decoder_.part_present(); }
  bool next_photo_eye_event(PhotoEyeEvent& event) noexcept override {
    return decoder_.next_photo_eye_event(event);
  }
  GpioStatus set_output(GpioOutput output, bool active) noexcept override;
  std::string_view last_error() const noexcept override { return error_.view(); }

  bool started() const noexcept { return chip_ != nullptr; }
  const GpioInputDecoder& decoder() const noexcept { return decoder_; }
  // Edges the pump could not hold: the loop polled far too rarely.
  std::uint64_t lost_edges() const noexcept { return pump_.lost_edges(); }
  GpioInputHealth input_health() const noexcept override {
    GpioInputHealth health = decoder_.health();
    health.edges_lost += pump_.lost_edges();
    return health;
  }

 private:
  static constexpr std::size_t kOutputCount = 2;

  const GpioLineRef& input_ref(std::size_t input) const noexcept;
  const GpioLineRef& output_ref(std::size_t output) const noexcept;
  GpioStatus find_line(const GpioLineRef& ref, const char* role, gpiod_line*& line) noexcept;
  GpioStatus open_lines() noexcept;
  [[gnu::format(printf, 2, 3)]] GpioStatus fail(const char* format, ...) noexcept;

  GpioConfig config_;
  gpiod_chip* chip_ = nullptr;
  std::array<gpiod_line*, kGpioInputCount> inputs_{};
  std::array<gpiod_line*, kOutputCount> outputs_{};
  GpioInputDecoder decoder_;
  GpioEventPump pump_;
  ErrorLine error_;
};

}  // namespace cosmos
