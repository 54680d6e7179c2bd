#include "core/recognition/task_runner.hpp"

namespace cosmos {

void SequentialTaskRunner::run(int count, const std::function<void(int task)>& task) const {
  for (int k = 0; k < count; ++k) task(k);
}

}  // namespace cosmos
