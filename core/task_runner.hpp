#pragma once
// Work core's algorithms may spread over cores. Core starts no thread: whoever calls them (the
// recognizer's maker, for the recognizer) passes a runner that may run a batch of tasks at
// once (the cell's helper threads, realtime/rt/helper_threads.hpp) or one after another
// (SequentialTaskRunner, the default). An algorithm gives it only tasks that read shared
// inputs and each write their own slots, and merges the slots in task order afterwards, so its
// results are the same whichever runner runs them, on however many threads, in whatever order.
#include <functional>

namespace cosmos {

class TaskRunner {
 public:
  virtual ~TaskRunner() = default;
  // Runs task(0), ..., task(count - 1), each exactly once, in any order and on any thread, and
  // returns once all have ended. May be called from several threads at once.
  virtual void run(int count, const std::function<void(int task)>& task) const = 0;
  // How many tasks may run at once: with one, work done only because it could run beside
  // other work is not done.
  virtual int threads() const = 0;
};

class SequentialTaskRunner final : public TaskRunner {
 public:
  void run(int count, const std::function<void(int task)>& task) const override;
  int threads() const override { return 1; }
};

// The default runner of the functions that take one: every task on the calling thread.
const TaskRunner& one_after_another();

// The ranges [begin, end) of `count` items in `shares` contiguous shares, share `share`'s.
struct ShareRange {
  int begin = 0;
  int end = 0;
};
inline ShareRange share_range(int count, int shares, int share) {
  const auto at = [&](int s) {
    return static_cast<int>(static_cast<long long>(count) * s / shares);
  };
  return {at(share), at(share + 1)};
}

}  // namespace cosmos
