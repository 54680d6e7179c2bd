#include "tests/hil/frame_player.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include "firmware_bridge/kernel_timestamp.hpp"
#include "tests/hil/capture_ticks.hpp"
#include "tests/hil/output_stream.hpp"
#include "tests/hil/realtime_threads.hpp"

namespace cosmos::hil {
namespace {

// The head, the frame behind it, the one drawn ahead, and room for vivid's output thread to
// fall behind after a drop or on a loaded host (it retires one frame per tick of its own).
constexpr int kOutputBuffers = 16;
constexpr std::int64_t kEmpty = -1;
constexpr std::int64_t kDoneIdleNs = 2'000'000'000;  // idle after the conveyor: the cell stopped

struct QueuedFrame {
  int buffer = -1;
  std::int64_t content = kEmpty;
  std::int64_t retired_ns = -1;  // -1: not (yet) retired
  std::int64_t queued_ns = 0;
};

class Player {
 public:
  Player(FrameTapeReader& tape, GpioSimLines& lines, const HardwareConfig& hardware,
         const FramePlayerSettings& settings)
      : tape_(tape),
        hardware_(hardware),
        settings_(settings),
        capture_(settings.capture_node),
        output_(settings.output_node),
        format_(configure_vivid_loop(capture_, output_, settings.loop)),
        period_ns_(1e9 / format_.capture_rate_hz),
        lead_in_(std::llround(settings.lead_in_s * format_.capture_rate_hz)),
        stream_(output_, kOutputBuffers),
        ticks_(output_, period_ns_),
        lines_(lines),
        laser_line_(lines.offset(hardware.gpio.laser_enable.name)),
        result_line_(lines.offset(hardware.gpio.result_ready.name)),
        encoder_(lines, encoder_settings(lines)) {
    const TapeHeader& header = tape_.header();
    if (header.bytes_per_pixel != bytes_per_pixel(hardware.camera.pixel_format) ||
        header.roi_left_px + header.width_px > format_.width_px ||
        header.roi_top_px + header.height_px > format_.height_px) {
      throw std::runtime_error("the tape's frames do not fit vivid's frame in the camera's format");
    }
    // Profile 0 is empty belt (the conveyor's own lead-in): it stands for every empty frame.
    row_bytes_ = static_cast<std::size_t>(header.width_px * header.bytes_per_pixel);
    empty_.resize(header.frame_bytes());
    tape_.decode(0, empty_.data(), row_bytes_);
    PlayerPlan& plan = log_.plan;
    plan.lead_in_frames = lead_in_;
    plan.conveyor_frames = header.last_profile + 1;
    plan.end_sequence = lead_in_ + header.last_profile;
    plan.capture_rate_hz = format_.capture_rate_hz;
    plan.ticks_per_frame = header.ticks_per_profile;
    plan.cell_duration_s =
        static_cast<double>(plan.end_sequence) / format_.capture_rate_hz + settings.tail_s;
  }

  PlayerLog run();

 private:
  EncoderPlayerSettings encoder_settings(const GpioSimLines& lines) const {
    EncoderPlayerSettings encoder;
    encoder.line_a = lines.offset(hardware_.gpio.encoder_a.name);
    encoder.line_b = lines.offset(hardware_.gpio.encoder_b.name);
    encoder.photo_eye = lines.offset(hardware_.gpio.photo_eye.name);
    encoder.ticks_per_frame = tape_.header().ticks_per_profile;
    encoder.frame_period_ns = period_ns_;
    encoder.beam = tape_.header().beam;
    encoder.beam_offset_ticks = lead_in_ * tape_.header().ticks_per_profile;
    encoder.bouncing_arrivals.insert(settings_.bouncing_arrivals.begin(),
                                     settings_.bouncing_arrivals.end());
    return encoder;
  }

  std::int64_t content_of(std::int64_t sequence) const {
    const std::int64_t profile = sequence - lead_in_;
    return profile >= 0 && profile <= tape_.header().last_profile ? profile : kEmpty;
  }

  // The content's rows into an output buffer.
  void write_frame(int buffer, std::int64_t content);
  int free_buffer() const;  // not queued and not the prepared one
  void queue_frame(std::int64_t content);
  void prepare_frame(std::int64_t content);
  void retire_frames();
  void start_faults(std::int64_t next_sequence, std::int64_t t_ns, bool& hold);
  void resolve_contents();

  FrameTapeReader& tape_;
  const HardwareConfig& hardware_;
  const FramePlayerSettings& settings_;
  V4l2Node capture_;
  V4l2Node output_;
  OutputFormat format_;
  double period_ns_;
  std::int64_t lead_in_;
  OutputStream stream_;
  CaptureTicks ticks_;
  GpioSimLines& lines_;
  int laser_line_, result_line_;  // the cell's outputs, sampled at every capture
  EncoderPlayer encoder_;
  std::size_t row_bytes_ = 0;
  std::vector<std::uint8_t> empty_;
  std::vector<QueuedFrame> queued_;
  int prepared_buffer_ = -1;  // drawn ahead for the next capture but one
  std::int64_t prepared_content_ = kEmpty;
  std::size_t next_fault_ = 0;
  std::int64_t drop_until_ns_ = 0;
  std::int64_t output_full_ = 0;           // frames not played: every output buffer was queued
  std::vector<std::size_t> awaiting_gap_;  // faults whose gap the next capture shows
  PlayerLog log_;
};

void Player::write_frame(int buffer, std::int64_t content) {
  // The tape's rows where they lie on the sensor: the camera crops its own band of them.
  const TapeHeader& header = tape_.header();
  std::uint8_t* roi = stream_.data(buffer) +
                      static_cast<std::size_t>(header.roi_top_px) * format_.bytes_per_line +
                      static_cast<std::size_t>(header.roi_left_px) * header.bytes_per_pixel;
  if (content > 0) {
    // The tape only goes forward: a profile is read once, when it is first needed.
    tape_.decode(content, roi, static_cast<std::size_t>(format_.bytes_per_line));
    return;
  }
  for (int r = 0; r < header.height_px; ++r) {
    std::memcpy(roi + static_cast<std::size_t>(r) * format_.bytes_per_line,
                empty_.data() + static_cast<std::size_t>(r) * row_bytes_, row_bytes_);
  }
}

int Player::free_buffer() const {
  for (int i = 0; i < stream_.buffer_count(); ++i) {
    if (!stream_.is_queued(i) && i != prepared_buffer_) return i;
  }
  return -1;
}

void Player::queue_frame(std::int64_t content) {
  int buffer = -1;
  if (prepared_buffer_ >= 0 && prepared_content_ == content) {
    buffer = prepared_buffer_;
  } else {
    buffer = free_buffer();
    if (buffer < 0) buffer = prepared_buffer_;  // drawn for a frame a gap has skipped
    if (buffer < 0) {
      retire_frames();
      buffer = free_buffer();
    }
    if (buffer < 0) {
      // vivid's output thread is that far behind (a starved guest): this frame is not
      // played, and the capture shows the one before it again, counted as stale.
      ++output_full_;
      return;
    }
    write_frame(buffer, content);
  }
  prepared_buffer_ = -1;  // used, or not the frame wanted: a gap or a hold skipped it
  stream_.queue(buffer, format_.size_bytes);
  queued_.push_back({buffer, content, -1, monotonic_now_ns()});
}

void Player::prepare_frame(std::int64_t content) {
  if (content == kEmpty) return;  // nothing to draw
  const int buffer = free_buffer();
  if (buffer < 0) return;  // vivid's output is behind: draw it when it is needed
  write_frame(buffer, content);
  prepared_buffer_ = buffer;
  prepared_content_ = content;
}

void Player::retire_frames() {
  OutputStream::Retired retired;
  while (stream_.dequeue(retired)) {
    for (QueuedFrame& frame : queued_) {
      if (frame.buffer == retired.index && frame.retired_ns < 0) {
        frame.retired_ns = retired.t_ns;
        break;
      }
    }
  }
}

void Player::start_faults(std::int64_t next_sequence, std::int64_t t_ns, bool& hold) {
  while (next_fault_ < settings_.faults.size() &&
         lead_in_ + settings_.faults[next_fault_].profile <= next_sequence) {
    const FaultAt& fault = settings_.faults[next_fault_];
    log_.faults.push_back({fault.kind, next_sequence, fault.amount, -1});
    if (fault.kind == "skip" || fault.kind == "stall") {
      const double span_ns = fault.kind == "skip" ? static_cast<double>(fault.amount) * period_ns_
                                                  : static_cast<double>(fault.amount) * 1e6;
      capture_.set_control("Percentage of Dropped Buffers", 100);
      drop_until_ns_ = t_ns + static_cast<std::int64_t>(span_ns + period_ns_ / 2);
      awaiting_gap_.push_back(log_.faults.size() - 1);
    } else if (fault.kind == "jiggle") {
      encoder_.jiggle(static_cast<int>(fault.amount));
    } else if (fault.kind == "glitch") {
      encoder_.glitch();
    } else if (fault.kind == "corrupt") {
      // The flag goes to whichever of vivid's threads completes a buffer first: with no frame
      // queued behind the head, the output thread retires none, and the capture takes it.
      capture_.set_control("Inject V4L2_BUF_FLAG_ERROR", 1);
      log_.faults.back().observed = next_sequence;
      hold = true;
    } else {
      throw std::runtime_error("unknown fault " + fault.kind);
    }
    ++next_fault_;
  }
}

void Player::resolve_contents() {
  // The head of vivid's output queue at a capture is the first frame, in queue order, not yet
  // retired then: vivid retires the head only once another frame waits behind it.
  std::size_t head = 0;
  std::int64_t previous = -1;
  for (PlayedCapture& capture : log_.captures) {
    while (head + 1 < queued_.size() && queued_[head].retired_ns >= 0 &&
           queued_[head].retired_ns < capture.t_ns) {
      ++head;
    }
    capture.content = queued_[head].content;
    capture.stale = capture.content != content_of(capture.sequence);
    if (capture.stale) {
      // Why: the frame before was missing (a gap), the player queued the right one too late,
      // or vivid's output thread had not yet made it the head.
      const char* cause = "stale_after_gap";
      if (previous == capture.sequence - 1) {
        cause = "stale_player_late";
        for (std::size_t i = head; i < queued_.size(); ++i) {
          if (queued_[i].content == content_of(capture.sequence)) {
            if (queued_[i].queued_ns < capture.t_ns) cause = "stale_output_late";
            break;
          }
        }
      }
      ++log_.counts[cause];
    }
    previous = capture.sequence;
  }
}

PlayerLog Player::run() {
  if (!settings_.plan_file.empty()) write_player_plan(settings_.plan_file, log_.plan);
  queue_frame(kEmpty);
  stream_.stream_on();
  // This thread only: the encoder's waits for gpio-cdev by yielding, which a SCHED_FIFO
  // thread cannot do to the cell's.
  run_this_thread_fifo(kPlayerPriority);
  std::int64_t last_sequence = -1;
  std::int64_t last_event_ns = monotonic_now_ns();
  std::int64_t gaps = 0, stale_holds = 0, laser_on = 0, result_rises = 0;
  bool result_was_high = false;
  for (;;) {
    const std::int64_t now_ns = monotonic_now_ns();
    if (drop_until_ns_ != 0 && now_ns >= drop_until_ns_) {
      capture_.set_control("Percentage of Dropped Buffers", 0);
      drop_until_ns_ = 0;
    }
    const int wait_ms =
        drop_until_ns_ != 0
            ? static_cast<int>(std::max<std::int64_t>(1, (drop_until_ns_ - now_ns) / 1'000'000))
            : 100;
    CaptureTick tick;
    if (!ticks_.wait(wait_ms, tick)) {
      const std::int64_t idle_ns = monotonic_now_ns() - last_event_ns;
      if (last_sequence >= log_.plan.end_sequence && idle_ns >= kDoneIdleNs) break;
      if (idle_ns >= static_cast<std::int64_t>(settings_.idle_limit_s * 1e9)) {
        throw std::runtime_error("no capture for " + std::to_string(settings_.idle_limit_s) +
                                 " s: the cell's camera stopped before the conveyor ended");
      }
      continue;
    }
    last_event_ns = monotonic_now_ns();
    for (std::uint32_t i = 0; i < tick.missed_events; ++i) log_.merged.push_back(tick.sequence);
    if (last_sequence >= 0) {
      const std::int64_t gap =
          tick.sequence - last_sequence - 1 - static_cast<std::int64_t>(tick.missed_events);
      gaps += std::max<std::int64_t>(0, gap);
      for (const std::size_t fault : awaiting_gap_) log_.faults[fault].observed = gap;
      if (gap > 0 || drop_until_ns_ == 0) awaiting_gap_.clear();
    }
    last_sequence = tick.sequence;
    log_.captures.push_back({tick.sequence, tick.t_ns, kEmpty, false, 0});
    laser_on += lines_.value(laser_line_) ? 1 : 0;
    const bool result_high = lines_.value(result_line_);
    result_rises += result_high && !result_was_high ? 1 : 0;
    result_was_high = result_high;
    encoder_.observe_capture(tick.sequence, tick.t_ns);
    retire_frames();
    bool hold = false;
    start_faults(tick.sequence + 1, tick.t_ns, hold);
    if (hold) {
      ++stale_holds;
      continue;
    }
    queue_frame(content_of(tick.sequence + 1));
    // Draw the frame after next while the capture side works on this one.
    prepare_frame(content_of(tick.sequence + 2));
  }
  retire_frames();
  stream_.stream_off();
  encoder_.stop();
  resolve_contents();
  // The count half a tick after the fill began: the belt's schedule puts a frame's exposure
  // on a tick, which the encoder thread drives (and stamps) a moment after it is due.
  const auto half_tick_ns =
      static_cast<std::int64_t>(period_ns_ / (2.0 * tape_.header().ticks_per_profile));
  for (PlayedCapture& capture : log_.captures)
    capture.belt_tick = encoder_.tick_at(capture.t_ns + half_tick_ns);
  const EncoderPlayerCounts counts = encoder_.counts();
  std::int64_t stale = 0;
  for (const PlayedCapture& capture : log_.captures) stale += capture.stale ? 1 : 0;
  log_.counts.insert(
      {{"captures", static_cast<std::int64_t>(log_.captures.size())},
       {"merged_events", static_cast<std::int64_t>(log_.merged.size())},
       {"silent_first_fill", ticks_.first_fill_silent() ? 1 : 0},
       {"stale_captures", stale},
       {"held_frames", stale_holds},
       {"output_full_frames", output_full_},
       {"sequence_gaps", gaps},
       {"laser_on_captures", laser_on},
       {"result_ready_pulses", result_rises},
       {"encoder_ticks", counts.tick},
       {"encoder_edges", static_cast<std::int64_t>(counts.edges)},
       {"jiggles", static_cast<std::int64_t>(counts.jiggles)},
       {"jiggle_reversals", static_cast<std::int64_t>(counts.jiggle_reversals)},
       {"glitches", static_cast<std::int64_t>(counts.glitches)},
       {"beam_arrivals", static_cast<std::int64_t>(counts.beam_arrivals)},
       {"bounced_arrivals", static_cast<std::int64_t>(counts.bounced_arrivals)},
       {"unacknowledged_edges", static_cast<std::int64_t>(counts.unacknowledged_edges)}});
  return log_;
}

}  // namespace

PlayerLog play_conveyor(FrameTapeReader& tape, GpioSimLines& lines, const HardwareConfig& hardware,
                        const FramePlayerSettings& settings) {
  Player player(tape, lines, hardware, settings);
  return player.run();
}

}  // namespace cosmos::hil
