#include "firmware_bridge/gpio_input_decoder.hpp"

#include <algorithm>

namespace cosmos {

GpioInputDecoder::GpioInputDecoder(const GpioInputParameters& parameters)
    : encoder_(parameters.encoder), photo_eye_(parameters.photo_eye) {}

void GpioInputDecoder::reset(bool encoder_a, bool encoder_b, bool photo_eye,
                             std::int64_t t_ns) noexcept {
  encoder_.reset(encoder_a, encoder_b, 0, t_ns);
  photo_eye_.reset(photo_eye, t_ns);
  decoded_until_ns_ = t_ns;
  first_event_ = 0;
  event_count_ = 0;
  lost_events_ = 0;
}

void GpioInputDecoder::record(const PhotoEyeChange& change) noexcept {
  if (!change.changed) return;
  if (event_count_ == kEventCapacity) {
    ++lost_events_;
    return;
  }
  events_[(first_event_ + event_count_) % kEventCapacity] = {change.present, change.t_ns,
                                                             change.tag};
  ++event_count_;
}

void GpioInputDecoder::on_edge(const GpioEdge& edge) noexcept {
  switch (edge.input) {
    case GpioInput::kEncoderA:
      encoder_.on_edge(EncoderLine::kA, edge.level, edge.t_ns);
      break;
    case GpioInput::kEncoderB:
      encoder_.on_edge(EncoderLine::kB, edge.level, edge.t_ns);
      break;
    case GpioInput::kPhotoEye:
      // Settle the encoder up to this edge first, so the count it carries is complete.
      encoder_.advance_to(edge.t_ns);
      record(photo_eye_.on_edge(edge.level, edge.t_ns, encoder_.ticks()));
      break;
  }
}

void GpioInputDecoder::advance_to(std::int64_t t_ns) noexcept {
  decoded_until_ns_ = std::max(decoded_until_ns_, t_ns);
  encoder_.advance_to(t_ns);
  record(photo_eye_.advance_to(t_ns));
}

EncoderReading GpioInputDecoder::encoder() const noexcept {
  const EncoderCounts& counts = encoder_.counts();
  return {counts.ticks, counts.last_step_t_ns, counts.invalid_transitions, counts.ignored_edges,
          counts.reversals};
}

bool GpioInputDecoder::next_photo_eye_event(PhotoEyeEvent& event) noexcept {
  if (event_count_ == 0) return false;
  event = events_[first_event_];
  first_event_ = (first_event_ + 1) % kEventCapacity;
  --event_count_;
  return true;
}

}  // namespace cosmos
