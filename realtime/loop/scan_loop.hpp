#pragma once
// The acquisition thread's per-profile work, bounded and non-blocking so that every profile
// is done before the next one is exposed: condition the profile onto the COSMOS grid,
// de-shear the rows of a pitched laser sheet (which delays them by the de-shear's window),
// track the parts on the belt, and advance the incremental COSMOS (thesis ch. 3, Fig. 3.22)
// of every open part by one row. When the tracker completes
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
#include "realtime/loop/built_part.hpp"
#include "realtime/loop/incremental_cosmos.hpp"
#include "realtime/loop/part_tracker.hpp"
#include "realtime/loop/profile_conditioner.hpp"
#include "realtime/loop/row_block_pool.hpp"
#include "realtime/loop/sheet_deshear.hpp"
#include "realtime/rt/spsc_ring.hpp"

namespace cosmos {

// A part the loop could not hand to the recognizer. It is still reported (an ERROR pose:
// a robot or reject gate must learn that something passed), with what the tracker knows.
enum class LostPartReason : std::uint8_t {
  kNoBuilder,    // it started while every builder was taken
  kQueueFull,    // it completed while the recognizer's queue was full
  kNoRowMemory,  // a row of it found the builders' row pool empty
};
// The reason as its ERROR pose says it, naming the setting that ran out.
const char* lost_part_reason_text(LostPartReason reason);

struct LostPart {
  LostPartReason reason = LostPartReason::kNoBuilder;
  std::int64_t first_profile = 0;  // the source's profile indices of its first and last rows
  std::int64_t last_profile = 0;
  std::int64_t first_encoder_ticks = 0;
  std::int64_t last_encoder_ticks = 0;
  std::int64_t last_t_us = 0;
  int column_min = 0;  // loop-frame columns
  int column_max = 0;
  float max_z_mm = 0;
};

// One part's incremental COSMOS (its rows hold the tracker's part id of every pixel) and
// what the recognizer needs besides it.
struct PartBuilder {
  PartBuilder(const CosmosParameters& cosmos, int width, int max_rows, double grid_mm,
              RowBlockPool& row_pool);

  IncrementalCosmos cosmos;
  std::int64_t part_id = -1;
  std::array<std::int64_t, kMaxMergedIds> merged_ids{};  // ids merged into this part
  int merged_count = 0;
  std::int64_t first_profile = 0;  // the source's profile index of row 0
  std::int64_t first_row = 0;      // the tracker's row index of row 0
  std::int64_t last_data_row = 0;  // the tracker's row index of its last row with data
  // The profile indices of its last row with data (known once the tracker completed it) and
  // of the last row added, up to tracking.link_gap_rows of empty belt later.
  std::int64_t last_data_profile = 0;
  std::int64_t last_profile = 0;
  // The profile index of the row at which the tracker completed it: a piece that continues it
  // (soft_link_of) started by then.
  std::int64_t completed_profile = 0;
  // The encoder counts and exposure times (data time) of its first row and, once the tracker
  // completed it, of its last row with data, where its pose holds.
  std::int64_t first_encoder_ticks = 0;
  std::int64_t last_data_encoder_ticks = 0;
  std::int64_t first_t_us = 0;
  std::int64_t last_data_t_us = 0;
  int column_min = 0;  // the tracked part's extent, loop-frame columns
  int column_max = 0;
  float max_z_mm = 0;       // the tracked part's highest sample
  std::int64_t pixels = 0;  // the tracked part's data pixels
  // The tracker's soft links (PartTrackerParameters::shadow_rows_per_mm): the earlier piece
  // (tracker id) this one may continue, and whether a later piece may continue this one.
  std::int64_t soft_link_of = -1;
  bool has_soft_successor = false;
  std::int64_t tracked_rows = 0;  // rows from its first to its last data (all, when truncated)
  bool truncated = false;         // longer than max_rows: rows dropped
  std::int64_t completed_ns = 0;  // monotonic clock when the tracker completed it
  // Rows given to it, up to its builder's max_rows: cosmos.rows(), and the rows counted
  // once it was sent ahead of its completion (ScanLoop::speculate), when its pipeline became
  // the recognizer worker's to finish.
  int rows_added = 0;

  bool owns(std::int64_t id) const;
  // What recognition reads of it: its rows up to its last with data, its extent and stamps.
  BuiltPart built() const;
};

// The loop's part builders, the pool their rows are kept in and the queue to the recognizer
// (keys of the cell's `realtime:`). The memory each costs is stated in the key's description
// for the default grid (640 columns, 15 smoothing iterations); it scales with the grid's
// columns (a part's rows with the part's own).
struct PartQueueSettings {
  // Parts in flight (open, queued and being recognized). A part that starts while every
  // builder is taken is dropped, so there must be enough for the parts that arrive during
  // the slowest recognitions, not just the typical ones (PacedReplayLatency in
  // bench/scan_loop_bench.cpp counts parts_dropped at the default cell's pace).
  int builders = 8;
  int part_queue_slots = 8;  // loop -> recognizer completed parts
  // The row pool shared by the builders: row_blocks blocks of row_block_rows full-width rows
  // each (a row takes 79 bytes per column between its first and last sample, and its CSMP
  // seed crossings a few more, row_seeds.hpp). A part holds the blocks its rows fill until
  // the recognizer is done with it; a part whose next row finds no block left is dropped and
  // counted like one that finds no builder. The default is well above the most blocks a
  // dense belt (parts 30 mm apart) and an overloaded hour-long soak held at once (the summary
  // prints the peak): the pool is resident from the start, so each block more is memory the
  // cell holds whatever the belt carries.
  int row_blocks = 48;
  int row_block_rows = 16;
  // A part is recognized in the rows after its end, while the tracker waits out
  // link_gap_rows before it completes it (speculative recognition): once nothing can join it
  // outright, no other part beside it could merge with it and the rows within the fit's
  // reach after its end are empty, its builder goes to a recognizer worker, which finishes
  // its pipeline as the end of the image would. At completion the result is used when the
  // part is still the same (else it is recognized again), so the poses are the same either
  // way, only earlier.
  bool speculative_recognition = true;
  // Parts lost for want of a builder or queue slot, queued for their ERROR poses: fixed
  // capacity (the hot path never allocates); beyond it a loss is only counted.
  static constexpr int kLostPartSlots = 64;

  template <class Visitor>
  void visit(Visitor& v) {
    v("part_builders", builders,
      "parts in flight (open, queued, being recognized); each ~4 MB (its working rows and fit "
      "kernels), its part's rows are in the row pool",
      Range{1, 64});
    v("part_queue_slots", part_queue_slots, "completed parts queued for the recognizer",
      Range{1, 1024});
    v("row_blocks", row_blocks,
      "blocks of the builders' shared row pool, allocated and made resident at start; "
      "0.81 MB each",
      Range{1, 65536});
    v("row_block_rows", row_block_rows,
      "full-width rows per row-pool block (a part's rows hold only its own columns, so "
      "more of them fit); 51 kB per row",
      Range{1, 4096});
    v("speculative_recognition", speculative_recognition,
      "recognize a part in the rows after its end, before the tracker completes it "
      "(link_gap_rows later); the same poses, earlier");
  }
};

struct ScanLoopSettings {
  ConditioningParameters conditioning;
  PartTrackerParameters tracking = cell_part_tracking();
  CosmosParameters cosmos;
  int max_part_rows = 750;  // 300 mm at 0.4 mm
  // tan of the scanner's triangulation angle: the camera's occlusion shadow in front of a
  // feature, mm of belt per mm of height, which the tracker's links across gaps respect
  // (PartTrackerParameters::shadow_rows_per_mm). The default is the default scanner's 30°;
  // 0 keeps the fixed link_gap_rows alone.
  double shadow_length_per_height = 0.5773502691896257;
  PartQueueSettings parts;
  // false (paced and hardware sources): a part that finds no free builder or queue slot is
  // dropped and counted. true (unpaced test and replay runs, no deadlines to keep): the loop
  // waits for the recognizer instead, so every part is recognized whatever the timing.
  bool wait_for_recognizer = false;
};

// A part handed to the recognizer before the tracker completed it (speculative recognition):
// its builder, whose pipeline the worker finishes (IncrementalCosmos::finish) before it
// reads the rows, and what recognition reads of it. The acquisition thread no longer touches
// that pipeline; it only counts the builder's rows until the tracker completes the part.
struct SpeculativePart {
  int builder = -1;
  BuiltPart built;
  // The tracker id of the part it may continue, across a gap its shadow can explain (-1:
  // none), as the tracker knew it then (PartBuilder::soft_link_of once it completes).
  std::int64_t soft_link_of = -1;
};

struct ScanLoopCounters {
  std::atomic<std::int64_t> profiles{0};
  std::atomic<std::int64_t> parts_seen{0};
  std::atomic<std::int64_t> parts_dropped{0};      // no free builder, row block or queue slot
  std::atomic<std::int64_t> parts_out_of_rows{0};  // of them: the row pool was empty
  std::atomic<std::int64_t> row_blocks_peak{0};    // the most row-pool blocks held at once
  std::atomic<std::int64_t> lost_unreported{0};    // dropped while lost_parts() was full
  std::atomic<std::int64_t> parts_truncated{0};    // longer than max_part_rows
  std::atomic<std::int64_t> specks_discarded{0};   // components too small to be parts
  std::atomic<std::int64_t> profiles_refused{0};   // the conditioner refused its grid
  std::atomic<std::int64_t> runs_dropped{0};       // the tracker's, beyond its limits
  // Samples above conditioning.max_height_mm, which the de-shear of a pitched sheet drops.
  std::atomic<std::int64_t> samples_too_high{0};
};

class ScanLoop {
 public:
  explicit ScanLoop(const ScanLoopSettings& settings);

  // Acquisition thread. `profile_index` counts the source's profiles (seq). With a pitched
  // sheet the row that reaches the tracker and the builders is the one of the profile
  // sheet_delay_rows() before this one, with that profile's stamp.
  void process(const Profile& profile);
  // End of stream: feeds the rows the de-shear still holds, then completes every open part.
  void flush();
  // Rows the de-shear of a pitched sheet delays the loop by (0: an upright sheet).
  int sheet_delay_rows() const { return deshear_.delay(); }

  // The recognizer's side: completed builders in completion order (their COSMOS still to
  // be finished: extract_part_view does it on the recognizer's thread), and their return.
  SpscRing<int>& completed() { return completed_; }
  SpscRing<int>& returned() { return returned_; }
  // How many of the builders the recognizer holds come back only once a part still open here
  // completes (a group of pieces waiting for its last piece's successor, and the blobs queued
  // behind it for publication). The recognizer sets it; a loop that waits for the recognizer
  // (ScanLoopSettings::wait_for_recognizer) does not wait for those, which would never come.
  void set_builders_waiting_on_open_parts(int count) {
    builders_waiting_on_open_parts_.store(count, std::memory_order_release);
  }
  // Parts to recognize before they complete (ScanLoopSettings::parts.speculative_recognition),
  // and the builders whose speculative recognition has ended or was dropped (no worker reads
  // them any more): until then the loop neither frees nor reuses the builder.
  SpscRing<SpeculativePart>& speculative() { return speculative_; }
  SpscRing<int>& speculated() { return speculated_; }
  // Parts dropped for want of a builder or a queue slot, each to be reported as an ERROR
  // pose by the recognizer's thread (report_lost_part, part_recognition.hpp).
  SpscRing<LostPart>& lost_parts() { return lost_; }
  // The source's profile index from which blobs may still be to come: the first profile of
  // the oldest open part, or the next profile when none is open (the largest index once
  // flush() has completed every part). Every part that started before it has completed and
  // is in completed() (or was lost) by the time this value is published, so the recognizer
  // that reads it before draining completed() knows every blob that starts earlier.
  std::int64_t unfinished_from_profile() const {
    return unfinished_from_profile_.load(std::memory_order_acquire);
  }
  PartBuilder& builder(int index) { return *builders_[static_cast<std::size_t>(index)]; }
  int builder_count() const { return static_cast<int>(builders_.size()); }
  const RowBlockPool& row_pool() const { return row_pool_; }
  const ScanLoopCounters& counters() const { return counters_; }
  int width() const { return conditioner_.width(); }
  // The loop frame's x of column 0: x_L = x0 + column · grid (mirrored belt x).
  double x0_loop_mm() const;

 private:
  // The source's profile, encoder count and exposure time of a recent row (within the
  // tracker's link_gap_rows + 2: a part completes that many rows after its last; the
  // de-shear's rows still pending besides).
  struct RowStamp {
    std::int64_t profile = 0;
    std::int64_t encoder_ticks = 0;
    std::int64_t t_us = 0;
  };

  void reclaim_returned();
  // Builders handed to the recognizer and not yet returned, and of those the ones the loop
  // may wait for: all but those waiting on open parts (set_builders_waiting_on_open_parts).
  std::size_t builders_at_recognizer() const;
  bool recognizer_returns_builders() const;
  int acquire_builder();
  void free_builder(int index);
  // The conditioned (and de-sheared) row row_index_, stamped `stamp`, to the tracker and the
  // open parts' builders.
  void add_row(const float* z_mm, const std::uint8_t* belt, const RowStamp& stamp);
  // Adds row_loop_ to an open part's builder; false when the part is lost (no row block: it
  // becomes an unbuilt part, reported when the tracker completes it).
  bool add_row_to(int index, const RowStamp& stamp);
  void start_parts(const RowStamp& stamp);
  void complete(const TrackedPart& part);
  // The tracker's extent and last data row of `part`, in its builder.
  void describe(PartBuilder& builder, const TrackedPart& part);
  // Open parts that nothing can change any more before they complete, to the recognizer.
  void speculate();
  int builder_of(std::int64_t id) const;
  void report_lost(const LostPart& lost);
  RowStamp& stamp_of_row(std::int64_t row);
  // Parts that started without a builder, until the tracker completes them.
  struct UnbuiltPart {
    std::int64_t id = -1;
    RowStamp first;
    LostPartReason reason = LostPartReason::kNoBuilder;
  };

  ScanLoopSettings settings_;
  ProfileConditioner conditioner_;
  SheetDeshear deshear_;
  PartTracker tracker_;
  RowBlockPool row_pool_;  // before the builders, which give their blocks back to it
  std::vector<std::unique_ptr<PartBuilder>> builders_;
  std::vector<int> free_builders_;  // stack, capacity reserved
  std::vector<int> open_builders_;  // builders of open parts
  SpscRing<int> completed_;
  SpscRing<int> returned_;
  SpscRing<LostPart> lost_;
  SpscRing<SpeculativePart> speculative_;
  SpscRing<int> speculated_;
  // Per builder: its part went to speculative recognition (its pipeline is then frozen: the
  // worker finishes it, add_row_to only counts rows); a worker may read it (the loop frees it
  // only after); it was freed meanwhile, and goes back once no worker reads it.
  std::vector<std::uint8_t> speculation_sent_, speculation_running_, free_when_speculated_;
  std::vector<UnbuiltPart> unbuilt_;     // capacity: the tracker's max_open_parts
  std::vector<RowStamp> row_stamps_;     // ring over the last rows, by input row
  std::vector<float> row_belt_;          // conditioned, belt column order
  std::vector<float> row_loop_;          // mirrored into the loop frame
  std::vector<std::uint8_t> belt_seen_;  // conditioned, belt column order: belt measured
  std::vector<std::uint8_t> belt_loop_;  // belt_seen_ of the row added, mirrored like row_loop_
  std::int64_t input_index_ = 0;         // the next profile's row
  std::int64_t row_index_ = 0;           // the next row to the tracker and the builders
  std::int64_t row_profile_ = 0;         // the profile index of the row the tracker is given
  std::atomic<std::int64_t> unfinished_from_profile_{0};
  std::atomic<int> builders_waiting_on_open_parts_{0};
  ScanLoopCounters counters_;
};

}  // namespace cosmos
