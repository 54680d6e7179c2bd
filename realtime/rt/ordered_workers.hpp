#pragma once
// Jobs run on several worker threads and handed back in the order they were submitted,
// whichever finishes first. The cell's recognizer uses it for blobs (recognizer_thread.cpp):
// a slow part (a pose search over the catalog) no longer holds up the parts behind it while a
// core sits idle, and since the results come back in submission order, whatever follows them
// (joining pieces, numbering and publishing poses) sees the same sequence for any number of
// workers and any timing.
//
// One thread submits and takes; the workers share only the job list, under a lock: this is
// for work that dwarfs a lock, never for the acquisition thread's per-profile path.
#include <algorithm>
#include <condition_variable>
#include <deque>
#include <functional>
#include <mutex>
#include <optional>
#include <thread>
#include <utility>
#include <vector>

#include "realtime/rt/wake_signal.hpp"

namespace cosmos {

template <class Result>
class OrderedWorkers {
 public:
  using Work = std::function<Result(int job)>;

  // `done` is notified whenever a job ends (the submitting thread's wake-up).
  OrderedWorkers(int threads, Work work, WakeSignal& done) : work_(std::move(work)), done_(done) {
    for (int t = 0; t < std::max(threads, 1); ++t) threads_.emplace_back([this] { run(); });
  }
  ~OrderedWorkers() {
    {
      const std::lock_guard lock(mutex_);
      stopping_ = true;
    }
    job_ready_.notify_all();
    for (std::thread& thread : threads_) thread.join();
  }
  OrderedWorkers(const OrderedWorkers&) = delete;
  OrderedWorkers& operator=(const OrderedWorkers&) = delete;

  int threads() const { return static_cast<int>(threads_.size()); }
  // Jobs submitted and not yet taken back.
  int in_flight() const {
    const std::lock_guard lock(mutex_);
    return static_cast<int>(jobs_.size());
  }
  // Fewer in flight than workers: more would only wait in the list, and the submitter's own
  // queue is as good a place to wait.
  bool can_submit() const { return in_flight() < threads(); }

  void submit(int job) {
    {
      const std::lock_guard lock(mutex_);
      Slot& slot = jobs_.emplace_back();
      slot.job = job;
    }
    job_ready_.notify_one();
  }

  struct Finished {
    int job = -1;
    Result result;
  };
  // The oldest job submitted, once it has ended; nothing while it has not (even when later
  // ones have).
  std::optional<Finished> take_oldest() {
    const std::lock_guard lock(mutex_);
    if (jobs_.empty() || !jobs_.front().done) return std::nullopt;
    Finished finished{jobs_.front().job, std::move(jobs_.front().result)};
    jobs_.pop_front();
    --next_start_;
    return finished;
  }

 private:
  struct Slot {
    int job = -1;
    Result result{};
    bool done = false;
  };

  void run() {
    for (;;) {
      Slot* slot = nullptr;
      {
        std::unique_lock lock(mutex_);
        job_ready_.wait(lock, [this] { return stopping_ || next_start_ < jobs_.size(); });
        if (next_start_ >= jobs_.size()) return;  // stopping, and nothing left to start
        // A deque's elements stay where they are while others are added or taken at the
        // ends, and this one is not taken before it is done.
        slot = &jobs_[next_start_++];
      }
      Result result = work_(slot->job);
      {
        const std::lock_guard lock(mutex_);
        slot->result = std::move(result);
        slot->done = true;
      }
      done_.notify();
    }
  }

  Work work_;
  WakeSignal& done_;
  mutable std::mutex mutex_;
  std::condition_variable job_ready_;
  std::deque<Slot> jobs_;       // submission order
  std::size_t next_start_ = 0;  // jobs_[next_start_] is the first no worker has started
  bool stopping_ = false;
  std::vector<std::thread> threads_;  // last: started once everything they use is
};

}  // namespace cosmos
