#include "realtime/web/background_thread_pool.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>

namespace cosmos {

bool lower_this_thread_priority(int nice) {
  // Linux: PRIO_PROCESS with a thread id reads and sets that thread's nice value alone.
  const auto thread = static_cast<id_t>(::gettid());
  const int current = ::getpriority(PRIO_PROCESS, thread);  // a thread already lower stays
  return ::setpriority(PRIO_PROCESS, thread, std::max(current, nice)) == 0;
}

BackgroundThreadPool::BackgroundThreadPool(int threads) {
  for (int i = 0; i < threads; ++i) threads_.emplace_back([this] { work(); });
}

BackgroundThreadPool::~BackgroundThreadPool() { shutdown(); }

void BackgroundThreadPool::enqueue(std::function<void()> task) {
  {
    const std::lock_guard lock(mutex_);
    tasks_.push_back(std::move(task));
  }
  ready_.notify_one();
}

void BackgroundThreadPool::shutdown() {
  {
    const std::lock_guard lock(mutex_);
    shutting_down_ = true;
  }
  ready_.notify_all();
  for (std::thread& thread : threads_)
    if (thread.joinable()) thread.join();
}

void BackgroundThreadPool::work() {
  lower_this_thread_priority(kNice);  // best effort: at worst the threads keep nice 0
  for (;;) {
    std::function<void()> task;
    {
      std::unique_lock lock(mutex_);
      ready_.wait(lock, [this] { return shutting_down_ || !tasks_.empty(); });
      if (tasks_.empty()) return;  // shutting down with nothing left
      task = std::move(tasks_.front());
      tasks_.pop_front();
    }
    task();
  }
}

}  // namespace cosmos
