#pragma once
// What the cell's threads (cell_runner.hpp) share: the poses handed from the recognizer
// thread to the publisher, and the counters and wake-ups the acquisition, recognizer and
// publisher threads keep for the status messages. Internal to realtime/cell.
#include <array>
#include <atomic>
#include <chrono>
#include <cstdint>

#include "realtime/cell/part_recognition.hpp"
#include "realtime/rt/wake_signal.hpp"

namespace cosmos {

// How long a thread backs off when a ring it feeds is full (the consumer is behind).
constexpr auto kIdleWait = std::chrono::microseconds(200);
struct CompletedPose {
  PartRecognition recognition;
  std::int64_t completed_ns = 0;
};

// What the threads share with the publisher's status messages.
struct SharedStatus {
  std::atomic<std::int64_t> overruns{0};
  std::atomic<std::int64_t> profiles_dropped{0};  // the recorded-profile ring's share
  // The source's SourceHealth, copied by the acquisition thread (the only one that may
  // read the source) at every status snapshot.
  std::atomic<std::int64_t> profiles_lost{0}, camera_timeouts{0}, encoder_errors{0},
      encoder_reversals{0}, gpio_edges_lost{0}, photo_eye_bounces{0}, encoder_stalls{0},
      laser_off_profiles{0}, encoder_counts_unsettled{0};
  // The source's last call timed out: the camera stalls while this lasts.
  std::atomic<bool> source_stalled{false};
  std::atomic<std::int64_t> time_p50_ns{0}, time_p99_ns{0}, time_max_ns{0};
  std::atomic<std::int64_t> parts_recognized{0}, parts_rejected{0}, blobs_merged{0};
  std::atomic<std::int64_t> blobs_recognized_ahead{0}, blobs_recognized_at_completion{0};
  std::atomic<std::int64_t> blobs_held_for_successor{0};
  std::atomic<std::int64_t> blob_groups_recognized{0};
  std::atomic<bool> fault{false};
  // The source's one line, written before `fault` is set (release) and read after it.
  std::array<char, 256> fault_reason{};
  std::atomic<bool> acquisition_done{false}, recognizer_done{false};
  // Idle threads sleep until there is work: the recognizer until a part completed (or was
  // lost), the publisher until a pose or a profile arrived or its next status is due.
  WakeSignal recognizer_wake, publisher_wake;
};

}  // namespace cosmos
