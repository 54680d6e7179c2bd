#pragma once
// The running cell: three threads around the ScanLoop, so that the acquisition thread, which
// must keep the line rate, never waits on recognition or on the network.
//   acquisition  (the calling thread, with the real-time settings applied): source.next() →
//                ScanLoop::process, paced on absolute deadlines at the line rate or unpaced;
//                records per-profile processing time (from the profile in hand to
//                its last stage, source time excluded); never waits on the others when
//                paced. Unpaced, it waits for room in the recorded-profile ring, and with
//                wait_for_recognizer (scan_loop.hpp) for the recognizer.
//   recognizer   completed parts → recognizer_threads workers (recognize_blob) → joined and
//                numbered in completion order → poses ring; gives the builder back.
//   publisher    poses ring → Publisher; cell_status_t every status period; recorded
//                profiles when asked.
// Rings between them are single-producer/single-consumer and lock-free; counters are atomics.
// With deterministic_output the poses carry only data-derived values (utime is the part's
// last exposure time, latency_ms 0), so replaying a stream gives byte-identical messages
// however the threads are scheduled.
#include <atomic>
#include <cstdint>
#include <functional>
#include <string>

#include "core/parameter_visitor.hpp"
#include "realtime/cell/cell_status.hpp"
#include "realtime/cell/part_recognition.hpp"
#include "realtime/lcm/pose_publisher.hpp"
#include "realtime/loop/scan_loop.hpp"
#include "realtime/rt/realtime_settings.hpp"
#include "realtime/sources/scanner_source.hpp"

namespace cosmos {

// The acquisition thread and the queues between the cell's threads (keys of the cell's
// `realtime:`, beside the scan loop's PartQueueSettings).
struct CellThreadSettings {
  RealtimeSettings thread;        // the acquisition thread: SCHED_FIFO, cpu, mlockall
  int profile_ring_slots = 4096;  // loop -> publisher recorded profiles (1.6 s at 2,500/s)
  int pose_queue_slots = 32;      // recognizer -> publisher poses
  // Blobs recognized at once (blob_recognition_workers.hpp). The acquisition thread takes a
  // fraction of a core, so on two cores a second worker uses what it leaves; each worker in
  // use adds its recognition's working memory to the cell's peak.
  int recognizer_threads = 2;
  // Threads besides the workers that take a share of one recognition's independent work (the
  // first views' verifications, the shares of its searches, registrations and support
  // measurements; core/task_runner.hpp, helper_threads.hpp): while a single
  // part is recognized, the core the other worker leaves idle shortens its latency. The poses
  // are the same for any count.
  int recognition_helpers = 1;
  // Blobs recognized between two trims of the heap (heap_policy.hpp). A trim gives the free
  // pages of the recognitions back to the system, and the next recognition faults its working
  // memory in anew, page by page: trimming after every blob keeps the memory flattest but puts
  // those faults on every part's latency path. Between trims the pages of the largest recent
  // recognitions stay resident (tens of MB).
  int heap_trim_blobs = 16;

  template <class Visitor>
  void visit(Visitor& v) {
    v.fields(thread);
    v("profile_ring_slots", profile_ring_slots,
      "recorded profiles queued for publishing (only with lcm.publish_profiles; each a "
      "whole profile, 2.6 kB at 640 points)",
      Range{1, 1 << 20});
    v("pose_queue_slots", pose_queue_slots, "poses queued for the publisher", Range{1, 4096});
    v("recognizer_threads", recognizer_threads,
      "blobs recognized at once, each on its own thread; poses are published in the order "
      "the parts completed whatever the count",
      Range{1, 64});
    v("recognition_helpers", recognition_helpers,
      "threads that share a recognition's independent work with its worker (0: none); the "
      "poses are the same for any count",
      Range{0, 64});
    v("heap_trim_blobs", heap_trim_blobs,
      "blobs recognized between two trims of the heap's free pages (1: after each; more "
      "keeps recent recognitions' pages, tens of MB, and spares the next ones their faults)",
      Range{1, 1 << 20});
  }
};

// What the publisher thread sends besides poses (keys of the cell's `lcm:`).
struct CellPublishSettings {
  bool publish_profiles = false;  // every profile on profile_channel, for record/replay
  double status_period_s = 1.0;   // cell_status_t period

  template <class Visitor>
  void visit(Visitor& v) {
    v("publish_profiles", publish_profiles, "every profile on profile_channel");
    v("status_period_s", status_period_s, "cell_status_t period, s", Range::above(0, 3600));
  }
};

struct CellRunSettings {
  double line_rate_hz = 2500;  // pacing of the acquisition loop
  bool paced = true;
  bool deterministic_output = false;
  CellThreadSettings threads;
  CellPublishSettings publishing;
  double duration_s = 0;  // stop after this much (data time); 0 = until the source ends
  // Test hook: extra time the recognizer spends per part (a slow worker must not change
  // the output in deterministic mode).
  int recognizer_delay_ms = 0;
};

struct CellRunSummary {
  std::int64_t profiles = 0;
  std::int64_t profiles_dropped = 0;
  std::int64_t deadline_overruns = 0;
  std::int64_t parts_seen = 0;
  std::int64_t parts_dropped = 0;
  std::int64_t poses_published = 0;
  std::int64_t publish_failures = 0;
  // Blobs whose recognition before the tracker completed them held (speculative
  // recognition), and those recognized at completion.
  std::int64_t blobs_recognized_ahead = 0;
  std::int64_t blobs_recognized_at_completion = 0;
  // Recognized blobs whose poses waited for their soft successor (PieceJoiner): a part that,
  // as placed, reaches past its blob into the shadow, or nearly failed recognition; their
  // latency is the part behind's, not their own recognition's.
  std::int64_t blobs_held_for_successor = 0;
  // Groups of blobs recognized as one (recognize_blob_group): a piece too small to be a part
  // alone and the blobs the tracker linked softly to it.
  std::int64_t blob_groups_recognized = 0;
  double profile_time_p50_us = 0, profile_time_p99_us = 0, profile_time_p999_us = 0,
         profile_time_max_us = 0;
  double start_jitter_p50_us = 0, start_jitter_p99_us = 0, start_jitter_max_us = 0;
  CellStatus last_status;  // the last COSMOS_STATUS sent: every total at the end of the run
  std::string realtime_report;
  std::string source_error;  // set when the source failed
};

// Called on the publisher thread after each pose went out (the live table, the web view).
using PoseObserver = std::function<void(const PartRecognition&)>;

CellRunSummary run_cell(ScannerSource& source, ScanLoop& loop,
                        const PartRecognitionContext& recognition, Publisher& publisher,
                        const CellRunSettings& settings, const PoseObserver& observer = {});

}  // namespace cosmos
