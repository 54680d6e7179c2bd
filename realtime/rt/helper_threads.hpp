#pragma once
// A TaskRunner (core/task_runner.hpp) with helper threads: the calling thread runs
// a batch's tasks itself and the helpers take what it has not reached yet, so the caller only
// ever waits for a task that has started, and a batch ends sooner when a helper's core is free.
// In the cell a recognition worker is the caller: while the other worker is idle (one part at a
// time on the belt), the helpers give the one recognition in flight the core the acquisition
// thread leaves. Several callers may run batches at once; the helpers serve the oldest first.
//
// Under a lock and a condition variable: for the recognizer's batches (each task a view's
// verification or a share of the parts' quick fits), never for the acquisition thread.
#include <condition_variable>
#include <deque>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

#include "core/task_runner.hpp"

namespace cosmos {

class HelperThreads final : public TaskRunner {
 public:
  // `helpers` threads besides each caller (0: every batch runs on its caller alone).
  explicit HelperThreads(int helpers);
  ~HelperThreads() override;
  HelperThreads(const HelperThreads&) = delete;
  HelperThreads& operator=(const HelperThreads&) = delete;

  void run(int count, const std::function<void(int task)>& task) const override;
  int threads() const override { return static_cast<int>(threads_.size()) + 1; }

 private:
  struct Batch {
    const std::function<void(int)>* task = nullptr;
    int count = 0;
    int next = 0;                // the next task not taken yet
    int running = 0;             // taken (by the caller or a helper) and not ended
    std::exception_ptr failure;  // the first task's exception, rethrown by the caller
  };
  // Takes the batch's next task under the lock, runs it without, and records its end.
  void run_next(Batch& batch, std::unique_lock<std::mutex>& lock) const;
  void serve();

  mutable std::mutex mutex_;
  mutable std::condition_variable work_ready_;
  mutable std::condition_variable task_ended_;
  mutable std::deque<Batch*> batches_;  // with tasks not taken yet, oldest first
  bool stopping_ = false;
  std::vector<std::thread> threads_;
};

}  // namespace cosmos
