#pragma once
// A runner that claims two threads and runs every batch backwards: it stands in for threads
// that finish in any order, without timing, so a test can ask whether results depend on the
// runner (core/task_runner.hpp).
#include <functional>

#include "core/task_runner.hpp"

namespace cosmos {

class BackwardsTaskRunner final : public TaskRunner {
 public:
  void run(int count, const std::function<void(int task)>& task) const override {
    ++batches;
    tasks += count;
    for (int k = count - 1; k >= 0; --k) task(k);
  }
  int threads() const override { return 2; }
  mutable int batches = 0;
  mutable int tasks = 0;
};

}  // namespace cosmos
