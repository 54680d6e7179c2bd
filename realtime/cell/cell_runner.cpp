#include "realtime/cell/cell_runner.hpp"

#include <algorithm>
#include <chrono>
#include <string>
#include <thread>

#include "firmware_bridge/kernel_timestamp.hpp"
#include "realtime/cell/cell_state_rule.hpp"
#include "realtime/cell/cell_threads_shared.hpp"
#include "realtime/cell/recognizer_thread.hpp"
#include "realtime/rt/deadline_pacer.hpp"
#include "realtime/rt/heap_policy.hpp"
#include "realtime/rt/latency_histogram.hpp"
#include "realtime/rt/spsc_ring.hpp"
#include "realtime/rt/wake_signal.hpp"

namespace cosmos {
namespace {

CellStatus status_message(ScanLoop& loop, const SharedStatus& shared,
                          const SpscRing<CompletedPose>& poses, std::int64_t utime_us) {
  CellStatus status;
  status.utime_us = utime_us;
  const ScanLoopCounters& counters = loop.counters();
  status.profiles_acquired = counters.profiles;
  status.profiles_lost = shared.profiles_lost;
  status.profiles_dropped = shared.profiles_dropped + status.profiles_lost;
  status.profiles_refused = counters.profiles_refused;
  status.samples_too_high = counters.samples_too_high;
  status.deadline_overruns = shared.overruns;
  status.camera_timeouts = shared.camera_timeouts;
  status.encoder_errors = shared.encoder_errors;
  status.encoder_reversals = shared.encoder_reversals;
  status.gpio_edges_lost = shared.gpio_edges_lost;
  status.photo_eye_bounces = shared.photo_eye_bounces;
  status.encoder_stalls = shared.encoder_stalls;
  status.laser_off_profiles = shared.laser_off_profiles;
  status.encoder_counts_unsettled = shared.encoder_counts_unsettled;
  status.profile_time_p50_us = shared.time_p50_ns / 1e3;
  status.profile_time_p99_us = shared.time_p99_ns / 1e3;
  status.profile_time_max_us = shared.time_max_ns / 1e3;
  status.parts_seen = counters.parts_seen;
  status.parts_recognized = shared.parts_recognized;
  status.parts_rejected = shared.parts_rejected;
  status.parts_dropped = counters.parts_dropped;
  status.parts_truncated = counters.parts_truncated;
  status.runs_dropped = counters.runs_dropped;
  status.blobs_merged = shared.blobs_merged;
  status.specks_discarded = counters.specks_discarded;
  status.recognition_queue_depth = static_cast<std::int32_t>(loop.completed().size());
  status.publish_queue_depth = static_cast<std::int32_t>(poses.size());
  return status;
}

// The source as the acquisition thread left it, for the state rule.
SourceCondition source_condition(const SharedStatus& shared) {
  SourceCondition source;
  source.failed = shared.fault.load(std::memory_order_acquire);
  if (source.failed) source.failure = shared.fault_reason.data();
  source.ended = shared.acquisition_done.load();
  source.stalled = shared.source_stalled.load();
  return source;
}

void run_publisher(ScanLoop& loop, Publisher& publisher, SpscRing<CompletedPose>& poses,
                   SpscRing<Profile>& profiles, SharedStatus& shared,
                   const CellRunSettings& settings, const PoseObserver& observer,
                   CellRunSummary& summary) {
  const auto period = std::chrono::duration<double>(settings.publishing.status_period_s);
  auto next_status = std::chrono::steady_clock::now();
  std::int64_t last_data_us = 0;
  CellStatus previous;
  for (;;) {
    const std::uint32_t seen = shared.publisher_wake.epoch();
    bool idle = true;
    if (CompletedPose* completed = poses.try_front()) {
      PartPose& pose = completed->recognition.pose;
      if (!settings.deterministic_output)
        pose.latency_ms = (monotonic_now_ns() - completed->completed_ns) / 1e6;
      last_data_us = pose.utime_us;
      (publisher.publish(pose) ? summary.poses_published : summary.publish_failures)++;
      if (observer) observer(completed->recognition);
      // The observer has had the part's image (PartRecognitionContext::keep_part_image): free
      // it here rather than leave it in the slot until the ring comes round again.
      completed->recognition.image = RangeImage{};
      poses.pop();
      idle = false;
    }
    if (const Profile* profile = profiles.try_front()) {
      if (!publisher.publish(*profile)) summary.publish_failures++;
      profiles.pop();
      idle = false;
    }
    const bool finished =
        shared.recognizer_done.load(std::memory_order_acquire) && poses.empty() && profiles.empty();
    if (finished || std::chrono::steady_clock::now() >= next_status) {
      summary.last_status = status_message(loop, shared, poses, last_data_us);
      decide_cell_state(source_condition(shared), previous, summary.last_status);
      previous = summary.last_status;
      if (!publisher.publish(summary.last_status)) summary.publish_failures++;
      next_status += std::chrono::duration_cast<std::chrono::steady_clock::duration>(period);
    }
    if (finished) break;
    if (idle) {
      const auto until_status = std::chrono::duration_cast<std::chrono::nanoseconds>(
          next_status - std::chrono::steady_clock::now());
      shared.publisher_wake.wait(seen, until_status.count());
    }
  }
}

}  // namespace

CellRunSummary run_cell(ScannerSource& source, ScanLoop& loop,
                        const PartRecognitionContext& recognition, Publisher& publisher,
                        const CellRunSettings& settings, const PoseObserver& observer) {
  keep_heap_flat();
  CellRunSummary summary;
  SharedStatus shared;
  SpscRing<CompletedPose> poses(
      static_cast<std::size_t>(std::max(settings.threads.pose_queue_slots, 1)));
  // Only a cell that publishes its profiles queues them: otherwise the ring's slots, each a
  // whole profile reserved up front, would be resident memory nothing ever reads.
  const int recorded_slots =
      settings.publishing.publish_profiles ? std::max(settings.threads.profile_ring_slots, 1) : 1;
  SpscRing<Profile> recorded(static_cast<std::size_t>(recorded_slots),
                             [&source](Profile& slot) { source.reserve(slot); });
  std::thread recognizer(run_recognizer, std::ref(loop), std::cref(recognition), std::ref(poses),
                         std::ref(shared), std::cref(settings));
  std::thread publishing(run_publisher, std::ref(loop), std::ref(publisher), std::ref(poses),
                         std::ref(recorded), std::ref(shared), std::cref(settings),
                         std::cref(observer), std::ref(summary));

  summary.realtime_report =
      describe_realtime_report(apply_realtime_settings(settings.threads.thread));
  Profile profile;
  source.reserve(profile);
  DeadlinePacer pacer(settings.paced ? static_cast<std::int64_t>(1e9 / settings.line_rate_hz) : 0);
  LatencyHistogram processing, processing_period;
  const auto status_period_ns =
      static_cast<std::int64_t>(settings.publishing.status_period_s * 1e9);
  std::int64_t next_snapshot_ns = monotonic_now_ns() + status_period_ns;
  std::int64_t first_t_us = -1;
  const auto snapshot_health = [&source, &shared] {
    const SourceHealth health = source.health();
    const auto store = [](std::atomic<std::int64_t>& to, std::uint64_t value) {
      to.store(static_cast<std::int64_t>(value), std::memory_order_relaxed);
    };
    store(shared.profiles_lost, health.profiles_lost);
    store(shared.camera_timeouts, health.camera_timeouts);
    store(shared.encoder_errors, health.encoder_errors);
    store(shared.encoder_reversals, health.encoder_reversals);
    store(shared.gpio_edges_lost, health.gpio_edges_lost);
    store(shared.photo_eye_bounces, health.photo_eye_bounces);
    store(shared.encoder_stalls, health.encoder_stalls);
    store(shared.laser_off_profiles, health.laser_off_profiles);
    store(shared.encoder_counts_unsettled, health.encoder_counts_unsettled);
  };
  for (;;) {
    pacer.wait_next();
    const SourceStatus status = source.next(profile);
    // Processing time starts when the profile is in hand: a hardware source's next() waits
    // for the camera, and the simulator's ray casting is the scanner's work, not the cell's.
    const std::int64_t start_ns = monotonic_now_ns();
    if (status == SourceStatus::kEndOfStream) break;
    if (status == SourceStatus::kTimeout) {
      // A stall shows live, with its counts from its first timeout on: the periodic
      // snapshot below would otherwise wait for the next frame.
      if (!shared.source_stalled.load(std::memory_order_relaxed) || start_ns >= next_snapshot_ns) {
        snapshot_health();
        next_snapshot_ns = start_ns + status_period_ns;
      }
      shared.source_stalled.store(true, std::memory_order_release);
      continue;
    }
    shared.source_stalled.store(false, std::memory_order_relaxed);
    if (status == SourceStatus::kError) {
      summary.source_error = std::string(source.last_error());
      const std::size_t length =
          std::min(summary.source_error.size(), shared.fault_reason.size() - 1);
      std::copy_n(summary.source_error.data(), length, shared.fault_reason.data());
      shared.fault.store(true, std::memory_order_release);
      break;
    }
    loop.process(profile);
    if (!loop.completed().empty() || !loop.lost_parts().empty() || !loop.speculative().empty())
      shared.recognizer_wake.notify();
    if (settings.publishing.publish_profiles) {
      Profile* slot = recorded.try_begin_push();
      // Unpaced runs (replays, log recording) lose nothing: they wait for the publisher,
      // which a loaded machine may starve for longer than the ring lasts.
      while (!slot && !settings.paced) {
        std::this_thread::sleep_for(kIdleWait);
        slot = recorded.try_begin_push();
      }
      if (slot) {
        *slot = profile;
        recorded.commit_push();
        shared.publisher_wake.notify();
      } else {
        shared.profiles_dropped.fetch_add(1, std::memory_order_relaxed);
      }
    }
    const std::int64_t end_ns = monotonic_now_ns();
    processing.record_ns(end_ns - start_ns);
    processing_period.record_ns(end_ns - start_ns);
    if (end_ns >= next_snapshot_ns) {
      shared.time_p50_ns = processing_period.p50_ns();
      shared.time_p99_ns = processing_period.p99_ns();
      shared.time_max_ns = processing_period.max_ns();
      shared.overruns = pacer.overruns();
      snapshot_health();
      processing_period.reset();
      next_snapshot_ns = end_ns + status_period_ns;
    }
    if (first_t_us < 0) first_t_us = profile.t_us;
    if (settings.duration_s > 0 && profile.t_us - first_t_us >= settings.duration_s * 1e6) break;
  }
  loop.flush();
  shared.overruns = pacer.overruns();
  snapshot_health();
  shared.source_stalled = false;
  shared.acquisition_done.store(true, std::memory_order_release);
  shared.recognizer_wake.notify();
  recognizer.join();
  publishing.join();

  summary.profiles = loop.counters().profiles;
  summary.profiles_dropped = shared.profiles_dropped + shared.profiles_lost;
  summary.deadline_overruns = pacer.overruns();
  summary.parts_seen = loop.counters().parts_seen;
  summary.parts_dropped = loop.counters().parts_dropped;
  summary.blobs_recognized_ahead = shared.blobs_recognized_ahead;
  summary.blobs_recognized_at_completion = shared.blobs_recognized_at_completion;
  summary.blobs_held_for_successor = shared.blobs_held_for_successor;
  summary.blob_groups_recognized = shared.blob_groups_recognized;
  summary.profile_time_p50_us = processing.p50_ns() / 1e3;
  summary.profile_time_p99_us = processing.p99_ns() / 1e3;
  summary.profile_time_p999_us = processing.p999_ns() / 1e3;
  summary.profile_time_max_us = processing.max_ns() / 1e3;
  summary.start_jitter_p50_us = pacer.lateness().p50_ns() / 1e3;
  summary.start_jitter_p99_us = pacer.lateness().p99_ns() / 1e3;
  summary.start_jitter_max_us = pacer.lateness().max_ns() / 1e3;
  return summary;
}

}  // namespace cosmos
