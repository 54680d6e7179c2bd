// HelperThreads (realtime/rt/helper_threads.hpp): every task of a batch runs once, helpers take
// a share of it, several callers and nested batches end, and a task's exception reaches its
// caller. Waits are on conditions with long time limits, never on a timing.
#include "realtime/rt/helper_threads.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

namespace cosmos {
namespace {

TEST(HelperThreads, RunsEveryTaskOnce) {
  const HelperThreads helpers(3);
  EXPECT_EQ(helpers.threads(), 4);
  for (int count : {0, 1, 2, 7, 1000}) {
    std::vector<std::atomic<int>> runs(static_cast<std::size_t>(count));
    helpers.run(count, [&](int task) { ++runs[static_cast<std::size_t>(task)]; });
    for (int task = 0; task < count; ++task)
      EXPECT_EQ(runs[static_cast<std::size_t>(task)].load(), 1) << count << " " << task;
  }
}

// Two tasks that each wait until both have started can only end if a helper took one.
TEST(HelperThreads, AHelperTakesATaskWhileTheCallerRunsAnother) {
  const HelperThreads helpers(1);
  std::mutex mutex;
  std::condition_variable started;
  int running = 0;
  bool together = true;
  std::set<std::thread::id> threads;
  helpers.run(2, [&](int) {
    std::unique_lock lock(mutex);
    threads.insert(std::this_thread::get_id());
    ++running;
    started.notify_all();
    together &= started.wait_for(lock, std::chrono::seconds(30), [&] { return running == 2; });
  });
  EXPECT_TRUE(together);
  EXPECT_EQ(threads.size(), 2u);
}

TEST(HelperThreads, WithoutHelpersTheCallerRunsEveryTask) {
  const HelperThreads none(0);
  EXPECT_EQ(none.threads(), 1);
  std::set<std::thread::id> threads;
  none.run(10, [&](int) { threads.insert(std::this_thread::get_id()); });
  EXPECT_EQ(threads, (std::set<std::thread::id>{std::this_thread::get_id()}));
}

TEST(HelperThreads, SeveralCallersAndNestedBatchesEnd) {
  const HelperThreads helpers(2);
  std::atomic<int> inner_runs{0};
  std::vector<std::thread> callers;
  for (int c = 0; c < 3; ++c)
    callers.emplace_back([&] {
      for (int batch = 0; batch < 50; ++batch)
        helpers.run(4, [&](int) { helpers.run(3, [&](int) { ++inner_runs; }); });
    });
  for (std::thread& caller : callers) caller.join();
  EXPECT_EQ(inner_runs.load(), 3 * 50 * 4 * 3);
}

TEST(HelperThreads, ATaskExceptionReachesTheCallerAfterEveryTaskEnded) {
  const HelperThreads helpers(2);
  std::atomic<int> ended{0};
  EXPECT_THROW(helpers.run(20,
                           [&](int task) {
                             ++ended;
                             if (task == 3) throw std::runtime_error("task 3");
                           }),
               std::runtime_error);
  EXPECT_EQ(ended.load(), 20);
}

}  // namespace
}  // namespace cosmos
