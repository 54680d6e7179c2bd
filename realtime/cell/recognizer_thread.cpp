#include "realtime/cell/recognizer_thread.hpp"

#include <algorithm>
#include <chrono>
#include <deque>
#include <optional>
#include <thread>
#include <vector>

#include "firmware_bridge/kernel_timestamp.hpp"
#include "realtime/cell/blob_groups.hpp"
#include "realtime/cell/blob_recognition.hpp"
#include "realtime/cell/piece_joiner.hpp"
#include "realtime/rt/heap_policy.hpp"
#include "realtime/rt/ordered_workers.hpp"

namespace cosmos {
namespace {

// The longest an idle recognizer sleeps before it looks again without being woken.
constexpr std::int64_t kRecognizerIdleNs = 50'000'000;
// While the joiner holds pieces: they go out as the belt moves on, not when a part completes,
// so the recognizer looks more often (2 ms is 5 profiles at the default line rate).
constexpr std::int64_t kHoldingIdleNs = 2'000'000;

}  // namespace

void run_recognizer(ScanLoop& loop, const PartRecognitionContext& context,
                    SpscRing<CompletedPose>& poses, SharedStatus& status,
                    const CellRunSettings& settings) {
  std::int64_t part_seq = 0;
  const auto publish = [&](JoinedRecognition&& joined) {
    PartRecognition& recognition = joined.recognition;
    recognition.pose.part_seq = part_seq++;
    (recognition.pose.status == PoseStatus::kOk ? status.parts_recognized : status.parts_rejected)
        .fetch_add(1, std::memory_order_relaxed);
    CompletedPose completed{std::move(recognition), joined.completed_ns};
    while (!poses.try_push(std::move(completed))) std::this_thread::sleep_for(kIdleWait);
    status.publisher_wake.notify();
  };
  PieceJoiner joiner(context);
  int blobs_since_trim = 0;
  // Per builder: where its blob's recognition stands. A part the loop sent ahead of its
  // completion (speculative) is recognized from a copy of what the loop knew of it then, its
  // builder's pipeline finished by the worker; at completion that result holds if the part is
  // still the same, else it is recognized again.
  enum class Stage : std::uint8_t {
    kNone,
    kAheadQueued,
    kAheadRunning,
    kAheadDone,
    kRunning,
    kReady
  };
  const std::size_t builders = static_cast<std::size_t>(loop.builder_count());
  std::vector<Stage> stage(builders, Stage::kNone);
  std::vector<BuiltPart> ahead(builders);
  std::vector<std::optional<BlobRecognition>> results(builders);
  std::deque<int> ahead_queue;      // speculative parts waiting for a worker
  std::deque<int> completed_order;  // completed builders, oldest first
  // Blobs recognized together, one group per piece a part's shadow cut off (blob_groups.hpp),
  // once the group's last piece has completed; their own speculative recognitions are not
  // used. A blob is no part alone under blob.min_stretch_fraction of a typical view's area.
  const double small_piece_mm2 = context.model_base ? context.blob.min_stretch_fraction *
                                                          typical_view_area_mm2(*context.model_base)
                                                    : 0.0;
  BlobGroups groups(static_cast<int>(builders),
                    small_piece_mm2 / (context.grid_mm * context.grid_mm));
  std::vector<std::vector<PartBuilder*>> group_builders(builders);
  // A speculative part that continues an open group is recognized ahead with the group's
  // pieces: per builder, the tracker's soft link when it was sent ahead, and the pieces its
  // speculative recognition took (empty: it alone). The result holds at completion when the
  // group turned out to be those pieces, each the same.
  std::vector<std::int64_t> ahead_link(builders, -1);
  std::vector<std::vector<int>> ahead_pieces(builders);
  // Per builder: speculative group recognitions reading it as an earlier piece.
  std::vector<int> read_ahead(builders, 0);
  const auto idle = [&](int piece) {
    const auto k = static_cast<std::size_t>(piece);
    return read_ahead[k] == 0 && (stage[k] == Stage::kNone || stage[k] == Stage::kAheadDone);
  };
  // Jobs: a builder index; kAhead plus it for a speculative one; kGroup plus its first
  // piece for a group; kAheadGroup plus its last piece for a group with a speculative last
  // piece. A blob's recognition depends on its rows (a group's on its pieces') alone; its
  // part_seq is given in order by publish().
  constexpr int kAhead = 1 << 20;
  constexpr int kGroup = 2 << 20;
  constexpr int kAheadGroup = 3 << 20;
  OrderedWorkers<BlobRecognition> workers(
      settings.threads.recognizer_threads,
      [&](int job) {
        if (settings.recognizer_delay_ms > 0)
          std::this_thread::sleep_for(std::chrono::milliseconds(settings.recognizer_delay_ms));
        if (job >= kAheadGroup) {
          const int last = job - kAheadGroup;
          std::vector<BuiltPart> pieces;
          for (const int piece : ahead_pieces[static_cast<std::size_t>(last)]) {
            loop.builder(piece).cosmos.finish();
            pieces.push_back(piece == last ? ahead[static_cast<std::size_t>(last)]
                                           : loop.builder(piece).built());
          }
          return recognize_blob(pieces, context, 0);
        }
        if (job >= kGroup)
          return recognize_blob_group(group_builders[static_cast<std::size_t>(job - kGroup)],
                                      context, 0);
        if (job >= kAhead) {
          // The loop left the builder's pipeline to this worker (ScanLoop::speculate).
          loop.builder(job - kAhead).cosmos.finish();
          return recognize_blob(ahead[static_cast<std::size_t>(job - kAhead)], context, 0);
        }
        return recognize_blob(loop.builder(job), context, 0);
      },
      status.recognizer_wake);
  const auto end_ahead = [&](int index) {
    while (!loop.speculated().try_push(index)) std::this_thread::sleep_for(kIdleWait);
  };
  for (;;) {
    const std::uint32_t seen = status.recognizer_wake.epoch();
    // Read before the completed parts are drained: every blob that starts before it is then
    // in completed_order or already joined (ScanLoop::unfinished_from_profile).
    const std::int64_t unfinished_from_profile = loop.unfinished_from_profile();
    // Parts the loop dropped are reported too (ERROR poses): none passes unannounced.
    LostPart lost;
    while (loop.lost_parts().try_pop(lost))
      publish({report_lost_part(lost, context, 0), monotonic_now_ns()});
    SpeculativePart early;
    while (loop.speculative().try_pop(early)) {
      const auto k = static_cast<std::size_t>(early.builder);
      ahead[k] = early.built;
      ahead_link[k] = early.soft_link_of;
      results[k].reset();
      stage[k] = Stage::kAheadQueued;
      ahead_queue.push_back(early.builder);
    }
    int index = -1;
    while (loop.completed().try_pop(index)) {
      completed_order.push_back(index);
      groups.add_completed(index, links_of(loop.builder(index)), completed_order);
    }
    // Completed parts first (they are on the latency path), oldest first.
    for (const int done : completed_order) {
      const auto k = static_cast<std::size_t>(done);
      if (groups.first_of(done) >= 0) {
        if (stage[k] == Stage::kAheadQueued) {
          ahead_queue.erase(std::find(ahead_queue.begin(), ahead_queue.end(), done));
          end_ahead(done);
          stage[k] = Stage::kNone;
        }
        // A later piece's speculative recognition is judged with the first piece.
        if (groups.first_of(done) != done) continue;
        if (stage[k] == Stage::kAheadDone) {
          results[k].reset();  // of the first piece alone
          stage[k] = Stage::kNone;
        }
        if (stage[k] != Stage::kNone) continue;
        const std::vector<int>& pieces = groups.pieces(done);
        const auto last = static_cast<std::size_t>(pieces.back());
        if (groups.open(done)) groups.close_if_settled(done, unfinished_from_profile);
        // A piece's speculative recognition still reads the builders' pipelines.
        const bool pieces_idle = std::all_of(pieces.begin(), pieces.end(), idle);
        if (groups.open(done) || !pieces_idle) continue;
        if (stage[last] == Stage::kAheadDone && ahead_pieces[last] == pieces &&
            ahead[last].same_as(loop.builder(pieces.back()).built())) {
          // Recognized ahead as this very group.
          results[k] = std::move(results[last]);
          for (PartRecognition& part : results[k]->parts)
            for (const int piece : pieces) mark_stream_fault(part, loop.builder(piece), context);
          for (const int piece : pieces) {
            if (piece != done) results[static_cast<std::size_t>(piece)].emplace();
            stage[static_cast<std::size_t>(piece)] = Stage::kReady;
          }
          status.blobs_recognized_ahead.fetch_add(1, std::memory_order_relaxed);
          continue;
        }
        if (!workers.can_submit()) continue;
        group_builders[k].clear();
        for (const int piece : pieces) {
          results[static_cast<std::size_t>(piece)].reset();
          stage[static_cast<std::size_t>(piece)] = Stage::kRunning;
          group_builders[k].push_back(&loop.builder(piece));
        }
        workers.submit(done + kGroup);
        status.blobs_recognized_at_completion.fetch_add(1, std::memory_order_relaxed);
        continue;
      }
      if (stage[k] == Stage::kAheadQueued) {
        // Completed before a worker took it up: recognized as any completed part.
        ahead_queue.erase(std::find(ahead_queue.begin(), ahead_queue.end(), done));
        end_ahead(done);
        stage[k] = Stage::kNone;
      } else if (stage[k] == Stage::kAheadDone) {
        // Recognized ahead alone, not as the last piece of a group it did not join.
        if (ahead_pieces[k].empty() && ahead[k].same_as(loop.builder(done).built())) {
          for (PartRecognition& part : results[k]->parts)
            mark_stream_fault(part, loop.builder(done), context);
          stage[k] = Stage::kReady;
          status.blobs_recognized_ahead.fetch_add(1, std::memory_order_relaxed);
        } else {
          results[k].reset();
          stage[k] = Stage::kNone;
        }
      }
      if (stage[k] == Stage::kNone && workers.can_submit()) {
        workers.submit(done);
        stage[k] = Stage::kRunning;
        status.blobs_recognized_at_completion.fetch_add(1, std::memory_order_relaxed);
      }
    }
    for (auto next = ahead_queue.begin(); next != ahead_queue.end() && workers.can_submit();) {
      const auto k = static_cast<std::size_t>(*next);
      ahead_pieces[k].clear();
      const int first = groups.open_group_continued_by(ahead_link[k], completed_order);
      if (first >= 0) {
        // It continues an open group: recognized ahead with the group's pieces, once no other
        // recognition reads them.
        const std::vector<int>& pieces = groups.pieces(first);
        if (!std::all_of(pieces.begin(), pieces.end(), idle)) {
          ++next;
          continue;
        }
        ahead_pieces[k] = pieces;
        ahead_pieces[k].push_back(*next);
        for (const int piece : pieces) ++read_ahead[static_cast<std::size_t>(piece)];
      }
      stage[k] = Stage::kAheadRunning;
      workers.submit(*next + (first >= 0 ? kAheadGroup : kAhead));
      next = ahead_queue.erase(next);
    }
    bool progressed = false;
    // Those wait for a part still open: the loop must not wait for their builders.
    loop.set_builders_waiting_on_open_parts(groups.waiting_on_open_parts(completed_order));
    while (auto finished = workers.take_oldest()) {
      progressed = true;
      const bool group_job = finished->job >= kGroup && finished->job < kAheadGroup;
      const bool early_job = finished->job >= kAhead && !group_job;
      const int job = finished->job >= kAheadGroup ? finished->job - kAheadGroup
                      : group_job                  ? finished->job - kGroup
                      : early_job                  ? finished->job - kAhead
                                                   : finished->job;
      const auto k = static_cast<std::size_t>(job);
      results[k] = std::move(finished->result);
      stage[k] = early_job ? Stage::kAheadDone : Stage::kReady;
      if (early_job) end_ahead(job);
      for (const int piece : ahead_pieces[k])
        if (piece != job && finished->job >= kAheadGroup)
          --read_ahead[static_cast<std::size_t>(piece)];
      if (group_job)
        for (const int piece : groups.pieces(job))
          if (piece != job) {
            results[static_cast<std::size_t>(piece)].emplace();
            stage[static_cast<std::size_t>(piece)] = Stage::kReady;
          }
    }
    // Blobs are joined and published in the order they completed, whichever worker is done
    // first; a group's blob with its first piece, the others adding nothing.
    while (!completed_order.empty() &&
           stage[static_cast<std::size_t>(completed_order.front())] == Stage::kReady) {
      const int done = completed_order.front();
      completed_order.pop_front();
      const auto k = static_cast<std::size_t>(done);
      BlobRecognition blob = std::move(*results[k]);
      results[k].reset();
      stage[k] = Stage::kNone;
      const int first = groups.first_of(done);
      groups.leave(done);
      if (first < 0 || first == done) {
        status.blobs_merged.fetch_add(blob.merged ? 1 : 0, std::memory_order_relaxed);
        if (first >= 0 && groups.pieces(done).size() > 1)
          status.blob_groups_recognized.fetch_add(1, std::memory_order_relaxed);
        const PartBuilder& last = loop.builder(first < 0 ? done : groups.pieces(done).back());
        for (JoinedRecognition& joined : joiner.add(std::move(blob), loop.builder(done), last))
          publish(std::move(joined));
      }
      loop.returned().try_push(done);  // room for every builder: never full
      if (++blobs_since_trim >= settings.threads.heap_trim_blobs) {
        return_free_heap_pages();
        blobs_since_trim = 0;
      }
      progressed = true;
    }
    // Held pieces go out as soon as no blob still to come can join them.
    std::int64_t unjoined_from_profile = unfinished_from_profile;
    for (const int waiting : completed_order)
      unjoined_from_profile = std::min(unjoined_from_profile, loop.builder(waiting).first_profile);
    for (JoinedRecognition& joined : joiner.release_settled(unjoined_from_profile)) {
      publish(std::move(joined));
      progressed = true;
    }
    if (progressed) continue;
    if (workers.in_flight() == 0 && status.acquisition_done.load(std::memory_order_acquire) &&
        loop.completed().empty() && loop.lost_parts().empty() && completed_order.empty() &&
        loop.speculative().empty() && ahead_queue.empty())
      break;
    status.recognizer_wake.wait(seen, joiner.holding() ? kHoldingIdleNs : kRecognizerIdleNs);
  }
  for (JoinedRecognition& joined : joiner.finish()) publish(std::move(joined));
  status.blobs_held_for_successor.store(joiner.blobs_held_for_successor(),
                                        std::memory_order_relaxed);
  status.recognizer_done.store(true, std::memory_order_release);
  status.publisher_wake.notify();
}

}  // namespace cosmos
