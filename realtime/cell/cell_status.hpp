#pragma once
// The cell's health once a second, as the publisher sends it on COSMOS_STATUS. Every drop,
// overrun and fault the cell counts appears here, live, so overload and failing hardware are
// visible instead of silent.
#include <cstdint>
#include <string>

namespace cosmos {

// Numbered like cell_status_t's constants (checked where they are converted).
enum class CellState : std::int8_t { kIdle = 0, kScanning = 1, kFault = 2 };

// "IDLE", "SCANNING", "FAULT", or "UNKNOWN" for a value off the wire that is none of them.
const char* to_string(CellState state);

struct CellStatus {
  std::int64_t utime_us = 0;  // utime_us of the last published pose (source clock)
  CellState state = CellState::kIdle;
  std::string state_text;  // one line for people: the fault's reason, or what the cell does

  // Totals since start (visit_totals lists them with their meaning).
  std::int64_t profiles_acquired = 0;
  std::int64_t profiles_dropped = 0;
  std::int64_t profiles_lost = 0;
  std::int64_t profiles_refused = 0;
  std::int64_t samples_too_high = 0;
  std::int64_t deadline_overruns = 0;
  std::int64_t camera_timeouts = 0;
  std::int64_t encoder_errors = 0;
  std::int64_t encoder_reversals = 0;
  std::int64_t gpio_edges_lost = 0;
  std::int64_t photo_eye_bounces = 0;
  std::int64_t encoder_stalls = 0;
  std::int64_t laser_off_profiles = 0;
  std::int64_t encoder_counts_unsettled = 0;

  // Per-profile processing time of the acquisition thread over the last period.
  double profile_time_p50_us = 0.0;
  double profile_time_p99_us = 0.0;
  double profile_time_max_us = 0.0;

  std::int64_t parts_seen = 0;
  std::int64_t parts_recognized = 0;
  std::int64_t parts_rejected = 0;
  std::int64_t parts_dropped = 0;
  std::int64_t parts_truncated = 0;
  std::int64_t runs_dropped = 0;
  std::int64_t blobs_merged = 0;
  std::int64_t specks_discarded = 0;

  std::int32_t recognition_queue_depth = 0;
  std::int32_t publish_queue_depth = 0;

  // Every total, with what it counts: the one list the summary, `cosmos listen`, the tests
  // and the message conversion's check read, so a new counter is declared once here.
  template <class Self, class Visitor>
  static void visit_totals(Self& self, Visitor&& v) {
    v("profiles_acquired", self.profiles_acquired, "profiles the loop processed");
    v("profiles_dropped", self.profiles_dropped,
      "profiles never processed or never published (source losses and full rings)");
    v("profiles_lost", self.profiles_lost,
      "the source's share: camera frame gaps, skipped replays");
    v("profiles_refused", self.profiles_refused,
      "profiles whose grid (x0_mm, dx_mm) no scanner has: processed as empty rows");
    v("samples_too_high", self.samples_too_high,
      "samples above conditioning.max_height_mm, which a pitched sheet's de-shear drops");
    v("deadline_overruns", self.deadline_overruns, "paced profiles started after their deadline");
    v("camera_timeouts", self.camera_timeouts, "waits for a frame that hit the watchdog");
    v("encoder_errors", self.encoder_errors, "quadrature states skipped: a missed encoder edge");
    v("encoder_reversals", self.encoder_reversals, "direction changes of the encoder count");
    v("gpio_edges_lost", self.gpio_edges_lost, "GPIO input edges never decoded (overflow)");
    v("photo_eye_bounces", self.photo_eye_bounces, "photo-eye edges rejected as bounce");
    v("encoder_stalls", self.encoder_stalls, "profiles whose encoder count did not advance");
    v("laser_off_profiles", self.laser_off_profiles, "profiles without a single laser point");
    v("encoder_counts_unsettled", self.encoder_counts_unsettled,
      "profiles whose encoder count is not the count at their time stamp (edges read too late)");
    v("parts_seen", self.parts_seen, "parts the tracker completed");
    v("parts_recognized", self.parts_recognized, "poses published with status OK");
    v("parts_rejected", self.parts_rejected, "poses published as REJECTED or ERROR");
    v("parts_dropped", self.parts_dropped,
      "parts that found no free builder, queue slot or row-pool block");
    v("parts_truncated", self.parts_truncated, "parts longer than the builders' rows");
    v("runs_dropped", self.runs_dropped,
      "runs of data beyond the tracker's per-row or open limits");
    v("blobs_merged", self.blobs_merged,
      "blobs holding several parts (touching or not separated): one pose or rejection each");
    v("specks_discarded", self.specks_discarded,
      "components too small and short to be a part (tracking.min_pixels): not reported");
  }
};

}  // namespace cosmos
