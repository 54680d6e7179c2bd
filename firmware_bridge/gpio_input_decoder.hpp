#pragma once
// The cell's GPIO inputs decoded from time-ordered edges: the encoder count, part-present,
// and the photo-eye transitions each stamped with the encoder count at their edge. Decoding
// in time-stamp order across lines is what makes that count exact: when the photo-eye edge
// is processed, every encoder edge before it and none after has been counted.
//
// The libgpiod lines feed it kernel edge events (through EdgeEventMerger, which restores the
// order across lines); a simulated cell can feed it synthetic edges and exercise the same code.
// Real-time: fixed storage, no allocation, no exceptions.
#include <array>
#include <cstddef>
#include <cstdint>

#include "firmware_bridge/gpio.hpp"
#include "firmware_bridge/photo_eye_debouncer.hpp"
#include "firmware_bridge/quadrature_decoder.hpp"

namespace cosmos {

enum class GpioInput : std::uint8_t { kEncoderA = 0, kEncoderB = 1, kPhotoEye = 2 };
inline constexpr std::size_t kGpioInputCount = 3;

// One edge: the line's logical level after it (active_low already applied by the source).
struct GpioEdge {
  std::int64_t t_ns = 0;
  GpioInput input = GpioInput::kEncoderA;
  bool level = false;
};

struct GpioInputParameters {
  QuadratureDecoderParameters encoder;
  PhotoEyeParameters photo_eye;
};

class GpioInputDecoder {
 public:
  // Photo-eye transitions waiting for the loop: parts pass seconds apart, the loop reads
  // every few hundred µs, so a few slots are plenty; an overflow is counted, not hidden.
  static constexpr std::size_t kEventCapacity = 16;

  explicit GpioInputDecoder(const GpioInputParameters& parameters = {});

  // Logical levels read when the lines were requested.
  void reset(bool encoder_a, bool encoder_b, bool photo_eye, std::int64_t t_ns) noexcept;
  void on_edge(const GpioEdge& edge) noexcept;
  // Every edge stamped up to t_ns has been given to on_edge().
  void advance_to(std::int64_t t_ns) noexcept;
  // The latest advance_to() (or reset()) time: the counts up to it are final.
  std::int64_t decoded_until_ns() const noexcept { return decoded_until_ns_; }
  // The encoder count as of t_ns; final when t_ns <= decoded_until_ns().
  EncoderHistory::Count encoder_ticks_at(std::int64_t t_ns) const noexcept {
    return encoder_.ticks_at(t_ns);
  }

  EncoderReading encoder() const noexcept;
  const EncoderCounts& encoder_counts() const noexcept { return encoder_.counts(); }
  const PhotoEyeCounts& photo_eye_counts() const noexcept { return photo_eye_.counts(); }
  bool part_present() const noexcept { return photo_eye_.present(); }
  bool next_photo_eye_event(PhotoEyeEvent& event) noexcept;
  std::uint64_t lost_photo_eye_events() const noexcept { return lost_events_; }
  // The decoder's share of GpioInputHealth (a line source adds the edges it lost itself).
  GpioInputHealth health() const noexcept {
    return {lost_events_, photo_eye_.counts().bounces + photo_eye_.counts().rejected_pulses};
  }

 private:
  void record(const PhotoEyeChange& change) noexcept;

  QuadratureDecoder encoder_;
  PhotoEyeDebouncer photo_eye_;
  std::array<PhotoEyeEvent, kEventCapacity> events_{};
  std::size_t first_event_ = 0;
  std::size_t event_count_ = 0;
  std::uint64_t lost_events_ = 0;
  std::int64_t decoded_until_ns_ = EncoderHistory::kSinceEver;
};

}  // namespace cosmos
