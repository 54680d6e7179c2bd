#pragma once
// Work core's algorithms may spread over cores. Core starts no thread: whoever calls them (the
// recognizer's maker, for the recognizer) passes a runner that may run a batch of tasks at
// once (the cell's helper threads, realtime/rt/helper_threads.hpp) or one after another
// (SequentialTaskRunner, the default). An algorithm gives it only tasks that read shared
// inputs and each write their own slots, and merges the slots in task order afterwards, so its
// results are the same whichever runner runs them, on however many threads, in whatever order.
#include <algorithm>
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

// The range [begin, end) of share `share` of `count` items in `shares` contiguous shares.
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

// How many shares `count` items make on `tasks`, none of fewer than `min_per_share` items
// (a smaller share is not worth handing to another thread): at least one.
inline int share_count(const TaskRunner& tasks, int count, int min_per_share) {
  return std::clamp(count / std::max(min_per_share, 1), 1, std::max(tasks.threads(), 1));
}

// each(share, begin, end) for the `shares` contiguous shares of [0, count): as tasks on
// `tasks`, or on the calling thread when there is one share.
template <class Each>
void run_in_shares(const TaskRunner& tasks, int count, int shares, const Each& each) {
  if (shares <= 1) return each(0, 0, count);
  tasks.run(shares, [&](int share) {
    const ShareRange range = share_range(count, shares, share);
    each(share, range.begin, range.end);
  });
}

}  // namespace cosmos
