#include "core/task_runner.hpp"

namespace cosmos {

void SequentialTaskRunner::run(int count, const std::function<void(int task)>& task) const {
  for (int k = 0; k < count; ++k) task(k);
}

const TaskRunner& one_after_another() {
  static const SequentialTaskRunner runner;
  return runner;
}

}  // namespace cosmos
