#include "realtime/rt/helper_threads.hpp"

#include <algorithm>

namespace cosmos {

HelperThreads::HelperThreads(int helpers) {
  for (int k = 0; k < helpers; ++k) threads_.emplace_back([this] { serve(); });
}

HelperThreads::~HelperThreads() {
  {
    const std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  work_ready_.notify_all();
  for (std::thread& thread : threads_) thread.join();
}

void HelperThreads::run_next(Batch& batch, std::unique_lock<std::mutex>& lock) const {
  const int task = batch.next++;
  if (batch.next == batch.count) std::erase(batches_, &batch);
  ++batch.running;
  lock.unlock();
  std::exception_ptr failure;
  try {
    (*batch.task)(task);
  } catch (...) {
    failure = std::current_exception();
  }
  lock.lock();
  if (failure && !batch.failure) batch.failure = failure;
  --batch.running;
}

void HelperThreads::run(int count, const std::function<void(int task)>& task) const {
  if (count <= 0) return;
  if (threads_.empty() || count == 1) {
    for (int k = 0; k < count; ++k) task(k);
    return;
  }
  Batch batch;
  batch.task = &task;
  batch.count = count;
  std::unique_lock lock(mutex_);
  batches_.push_back(&batch);
  work_ready_.notify_all();
  while (batch.next < batch.count) run_next(batch, lock);
  // The caller's own tasks ended with their calls; wait for those the helpers took.
  task_ended_.wait(lock, [&] { return batch.running == 0; });
  if (batch.failure) std::rethrow_exception(batch.failure);
}

void HelperThreads::serve() {
  std::unique_lock lock(mutex_);
  for (;;) {
    work_ready_.wait(lock, [this] { return stopping_ || !batches_.empty(); });
    if (stopping_) return;
    Batch& batch = *batches_.front();
    run_next(batch, lock);
    if (batch.running == 0) task_ended_.notify_all();
  }
}

}  // namespace cosmos
