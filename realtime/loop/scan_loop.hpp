#pragma once
// The acquisition thread's per-profile work, bounded and non-blocking so that every profile
// is done before the next one is exposed: condition the profile onto the COSMOS grid, track
// the parts on the belt, and advance the incremental COSMOS (thesis ch. 3, Fig. 3.22) of
// every open part by one row. When the tracker completes
// a part, its builder is finished and handed to the recognizer through a bounded
// single-producer/single-consumer ring; the recognizer gives builders back through another.
// Nothing here blocks, allocates or throws once constructed.
//
// Part images are in the loop frame L: rows in arrival order (row j = the part's j-th
// profile, y_L = profile index · Δy) and columns mirrored (x_L = −x_belt), i.e. the belt frame
// turned 180° about z. Rows in arrival order without the mirror would reflect the part (the
// sheet sweeps it from its downstream end, sim/range_image_scan.hpp); turning instead keeps
// the frame proper and lets each row be processed the moment it arrives.
//
// Every builder sees whole rows, so a part that the tracker later finds joined to another
// (two legs meeting further up) is still complete in the builder of the part it merges into:
// merges keep the earlier part, whose builder started first. The recognizer masks out other
// parts' pixels (separated from this one by background, so no fit window or smoothing
// neighbourhood ever crossed between them).
#include <array>
#include <atomic>
#include <cstdint>
#include <memory>
#include <vector>

#include "core/cosmos_parameters.hpp"
#include "core/parameter_visitor.hpp"
#include "core/profile.hpp"
#include "realtime/loop/incremental_cosmos.hpp"
#include "realtime/loop/part_tracker.hpp"
#include "realtime/loop/profile_conditioner.hpp"
#include "realtime/rt/spsc_ring.hpp"

namespace cosmos {

inline constexpr int kMaxMergedIds = 16;

// One part's incremental COSMOS and what the recognizer needs besides it.
struct PartBuilder {
  PartBuilder(const CosmosParameters& cosmos, int width, int max_rows, double grid_mm);

  IncrementalCosmos cosmos;
  std::vector<std::int64_t> labels;  // tracker part id per pixel (width x max_rows), -1 none
  std::int64_t part_id = -1;
  std::array<std::int64_t, kMaxMergedIds> merged_ids{};  // ids merged into this part
  int merged_count = 0;
  std::int64_t first_profile = 0;  // the source's profile index of row 0
  std::int64_t last_encoder_ticks = 0;
  std::int64_t last_t_us = 0;  // exposure time of the part's last row (data time)
  int column_min = 0;          // the tracked part's extent, loop-frame columns
  int column_max = 0;
  bool truncated = false;         // longer than max_rows: rows dropped
  std::int64_t completed_ns = 0;  // monotonic clock when the tracker completed it

  bool owns(std::int64_t id) const;
};

// The loop's part builders and its queue to the recognizer (keys of the cell's `realtime:`).
struct PartQueueSettings {
  // Parts in flight (open, queued and being recognized). A part that starts while every
  // builder is taken is dropped, so there must be enough for the parts that arrive during
  // the slowest recognitions, not just the typical ones (PacedReplayLatency in
  // bench/scan_loop_bench.cpp counts parts_dropped at the default cell's pace).
  int builders = 8;
  int part_queue_slots = 8;  // loop -> recognizer completed parts

  template <class Visitor>
  void visit(Visitor& v) {
    v("part_builders", builders, "parts in flight (open, queued, being recognized)", Range{1, 64});
    v("part_queue_slots", part_queue_slots, "completed parts queued for the recognizer",
      Range{1, 1024});
  }
};

struct ScanLoopSettings {
  ConditioningParameters conditioning;
  PartTrackerParameters tracking = cell_part_tracking();
  CosmosParameters cosmos;
  int max_part_rows = 750;  // 300 mm at 0.4 mm
  PartQueueSettings parts;
  // false (paced and hardware sources): a part that finds no free builder or queue slot is
  // dropped and counted. true (unpaced test and replay runs, no deadlines to keep): the loop
  // waits for the recognizer instead, so every part is recognized whatever the timing.
  bool wait_for_recognizer = false;
};

struct ScanLoopCounters {
  std::atomic<std::int64_t> profiles{0};
  std::atomic<std::int64_t> parts_seen{0};
  std::atomic<std::int64_t> parts_dropped{0};    // no free builder or queue slot
  std::atomic<std::int64_t> parts_truncated{0};  // longer than max_part_rows
  std::atomic<std::int64_t> noise_components{0};
  std::atomic<std::int64_t> profiles_refused{0};  // the conditioner refused its grid
  std::atomic<std::int64_t> runs_dropped{0};      // the tracker's, beyond its limits
};

class ScanLoop {
 public:
  explicit ScanLoop(const ScanLoopSettings& settings);

  // Acquisition thread. `profile_index` counts the source's profiles (seq).
  void process(const Profile& profile);
  // End of stream: completes every open part.
  void flush();

  // The recognizer's side: completed builders in completion order (their COSMOS still to
  // be finished: extract_part_view does it on the recognizer's thread), and their return.
  SpscRing<int>& completed() { return completed_; }
  SpscRing<int>& returned() { return returned_; }
  PartBuilder& builder(int index) { return *builders_[static_cast<std::size_t>(index)]; }
  const ScanLoopCounters& counters() const { return counters_; }
  int width() const { return conditioner_.width(); }
  // The loop frame's x of column 0: x_L = x0 + column · grid (mirrored belt x).
  double x0_loop_mm() const;

 private:
  void reclaim_returned();
  int acquire_builder();
  void start_parts(std::int64_t profile_index, const Profile& profile);
  void complete(const TrackedPart& part);
  int builder_of(std::int64_t id) const;

  ScanLoopSettings settings_;
  ProfileConditioner conditioner_;
  PartTracker tracker_;
  std::vector<std::unique_ptr<PartBuilder>> builders_;
  std::vector<int> free_builders_;  // stack, capacity reserved
  std::vector<int> open_builders_;  // builders of open parts
  SpscRing<int> completed_;
  SpscRing<int> returned_;
  std::vector<float> row_belt_;  // conditioned, belt column order
  std::vector<float> row_loop_;  // mirrored into the loop frame
  std::int64_t row_index_ = 0;
  ScanLoopCounters counters_;
};

}  // namespace cosmos
