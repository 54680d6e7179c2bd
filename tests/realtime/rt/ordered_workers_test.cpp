// Jobs on several workers come back in the order they were submitted: a later job that ends
// first waits for the earlier ones, none is lost, and the sequence the submitter sees is the
// same for one worker or many. The ordering is forced with gates, not timed.
#include "realtime/rt/ordered_workers.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <future>
#include <random>
#include <vector>

namespace cosmos {
namespace {

constexpr std::int64_t kAMillisecondNs = 1'000'000;

// Takes every result as it becomes ready, in order, until `count` came back.
template <class Result>
std::vector<typename OrderedWorkers<Result>::Finished> take_all(OrderedWorkers<Result>& workers,
                                                                WakeSignal& done, int count) {
  std::vector<typename OrderedWorkers<Result>::Finished> taken;
  while (static_cast<int>(taken.size()) < count) {
    const std::uint32_t seen = done.epoch();
    if (auto finished = workers.take_oldest()) {
      taken.push_back(std::move(*finished));
      continue;
    }
    done.wait(seen, kAMillisecondNs);
  }
  return taken;
}

TEST(OrderedWorkers, ALaterJobThatEndsFirstWaitsForTheEarlierOnes) {
  std::promise<void> release_first;
  std::shared_future<void> first_released = release_first.get_future().share();
  std::atomic<int> ended{0};
  std::vector<int> end_order(3, -1);
  WakeSignal done;
  OrderedWorkers<int> workers(
      3,
      [&](int job) {
        if (job == 0) first_released.wait();
        end_order[static_cast<std::size_t>(ended.fetch_add(1))] = job;
        return 10 * job;
      },
      done);
  for (int job = 0; job < 3; ++job) {
    ASSERT_TRUE(workers.can_submit());
    workers.submit(job);
  }
  EXPECT_FALSE(workers.can_submit());
  while (ended.load() < 2) {
    const std::uint32_t seen = done.epoch();
    if (ended.load() < 2) done.wait(seen, kAMillisecondNs);
  }
  // Jobs 1 and 2 are done, job 0 is not: nothing may be handed back yet.
  EXPECT_FALSE(workers.take_oldest().has_value());
  EXPECT_EQ(workers.in_flight(), 3);
  release_first.set_value();
  const auto taken = take_all(workers, done, 3);
  ASSERT_EQ(taken.size(), 3u);
  for (int job = 0; job < 3; ++job) {
    EXPECT_EQ(taken[static_cast<std::size_t>(job)].job, job);
    EXPECT_EQ(taken[static_cast<std::size_t>(job)].result, 10 * job);
  }
  EXPECT_EQ(end_order.back(), 0);  // it really did end last
  EXPECT_EQ(workers.in_flight(), 0);
}

// The submitter's loop of the cell's recognizer: submit while there is room, take in order.
std::vector<std::uint64_t> run_jobs(int threads, int jobs) {
  WakeSignal done;
  OrderedWorkers<std::uint64_t> workers(
      threads,
      [](int job) {
        // A job's own seeded amount of work: results differ per job, ends come in any order.
        std::mt19937_64 random(static_cast<std::uint64_t>(job));
        std::uint64_t sum = 0;
        for (int i = 0, n = static_cast<int>(random() % 20000); i < n; ++i) sum += random() >> 40;
        return sum ^ static_cast<std::uint64_t>(job);
      },
      done);
  std::vector<std::uint64_t> results;
  int submitted = 0;
  while (static_cast<int>(results.size()) < jobs) {
    const std::uint32_t seen = done.epoch();
    while (submitted < jobs && workers.can_submit()) workers.submit(submitted++);
    if (auto finished = workers.take_oldest()) {
      EXPECT_EQ(finished->job, static_cast<int>(results.size()));
      results.push_back(finished->result);
      continue;
    }
    done.wait(seen, kAMillisecondNs);
  }
  return results;
}

TEST(OrderedWorkers, OneWorkerOrManyHandBackTheSameSequence) {
  const std::vector<std::uint64_t> one = run_jobs(1, 300);
  ASSERT_EQ(one.size(), 300u);
  for (int threads : {2, 3, 8}) {
    SCOPED_TRACE(threads);
    EXPECT_EQ(run_jobs(threads, 300), one);
  }
}

TEST(OrderedWorkers, JobsStillRunningWhenTheWorkersGoAreFinishedFirst) {
  std::atomic<int> ran{0};
  WakeSignal done;
  {
    OrderedWorkers<int> workers(
        2,
        [&](int job) {
          ran.fetch_add(1);
          return job;
        },
        done);
    for (int job = 0; job < 5; ++job) workers.submit(job);
  }  // joins: every submitted job has run
  EXPECT_EQ(ran.load(), 5);
}

}  // namespace
}  // namespace cosmos
