// The web server's worker threads: every task enqueued runs, shutting down first finishes
// the queued ones, and the tasks run at the lowered priority.
#include "realtime/web/background_thread_pool.hpp"

#include <gtest/gtest.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <mutex>
#include <set>

namespace cosmos {
namespace {

TEST(BackgroundThreadPool, RunsEveryTaskBeforeShuttingDown) {
  std::atomic<int> done{0};
  BackgroundThreadPool pool(3);
  for (int i = 0; i < 50; ++i) pool.enqueue([&done] { done.fetch_add(1); });
  pool.shutdown();
  EXPECT_EQ(done.load(), 50);
}

TEST(BackgroundThreadPool, RunsTasksAtTheLoweredPriority) {
  const int caller_nice = ::getpriority(PRIO_PROCESS, static_cast<id_t>(::gettid()));
  std::mutex mutex;
  std::set<int> nice_values;
  {
    BackgroundThreadPool pool(2);
    for (int i = 0; i < 8; ++i) {
      pool.enqueue([&] {
        const int nice = ::getpriority(PRIO_PROCESS, static_cast<id_t>(::gettid()));
        const std::lock_guard lock(mutex);
        nice_values.insert(nice);
      });
    }
  }  // the destructor shuts down
  // Raised to kNice (a process already niced beyond it stays where it was).
  EXPECT_EQ(nice_values, std::set<int>{std::max(caller_nice, BackgroundThreadPool::kNice)});
  // The caller's own priority is untouched.
  EXPECT_EQ(::getpriority(PRIO_PROCESS, static_cast<id_t>(::gettid())), caller_nice);
}

}  // namespace
}  // namespace cosmos
