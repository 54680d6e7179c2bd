// The task runner (task_runner.hpp): the sequential one runs a batch in order, shares cover a
// range once, and a recognition's results do not depend on the runner (a backwards runner,
// backwards_task_runner.hpp, stands in for threads that finish in any order).
#include "core/task_runner.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "core/recognition/recognizer.hpp"
#include "tests/core/backwards_task_runner.hpp"
#include "tests/core/recognition/recognizer_fixture.hpp"

namespace cosmos {
namespace {

TEST(ShareRange, SharesCoverARangeOnceInOrderAndEvenly) {
  for (const int count : {0, 1, 7, 100, 721})
    for (const int shares : {1, 2, 3, 8}) {
      int next = 0;
      for (int share = 0; share < shares; ++share) {
        const ShareRange range = share_range(count, shares, share);
        EXPECT_EQ(range.begin, next) << count << " " << shares;
        EXPECT_GE(range.end, range.begin);
        EXPECT_LE(range.end - range.begin, count / shares + 1);
        next = range.end;
      }
      EXPECT_EQ(next, count);
    }
}

TEST(ShareRange, ItemsAreSharedOnlyInSharesWorthAThreadAndEachRunsOnce) {
  const SequentialTaskRunner one;
  const BackwardsTaskRunner two;
  EXPECT_EQ(share_count(one, 1000, 10), 1);
  EXPECT_EQ(share_count(two, 1000, 10), 2);
  EXPECT_EQ(share_count(two, 19, 10), 1);
  EXPECT_EQ(share_count(two, 0, 10), 1);
  std::vector<int> seen(9, 0);
  run_in_shares(two, 9, 2, [&](int share, int begin, int end) {
    EXPECT_EQ(begin, share == 0 ? 0 : 4);
    for (int k = begin; k < end; ++k) ++seen[static_cast<std::size_t>(k)];
  });
  EXPECT_EQ(seen, std::vector<int>(9, 1));
  EXPECT_EQ(two.batches, 1);
  run_in_shares(two, 9, 1, [&](int, int begin, int end) {
    for (int k = begin; k < end; ++k) ++seen[static_cast<std::size_t>(k)];
  });
  EXPECT_EQ(seen, std::vector<int>(9, 2));
  EXPECT_EQ(two.batches, 1);  // one share runs on the calling thread
}

TEST(SequentialTaskRunner, RunsEveryTaskOnceInOrder) {
  const SequentialTaskRunner runner;
  EXPECT_EQ(runner.threads(), 1);
  std::vector<int> ran;
  runner.run(5, [&](int task) { ran.push_back(task); });
  EXPECT_EQ(ran, (std::vector<int>{0, 1, 2, 3, 4}));
  runner.run(0, [&](int task) { ran.push_back(task); });
  EXPECT_EQ(ran.size(), 5u);
}

void expect_same(const RecognitionResult& a, const RecognitionResult& b, std::uint64_t seed) {
  EXPECT_EQ(a.status, b.status) << seed;
  EXPECT_EQ(a.reason, b.reason) << seed;
  EXPECT_EQ(a.part, b.part) << seed;
  EXPECT_EQ(a.view, b.view) << seed;
  EXPECT_EQ(a.score, b.score) << seed;
  EXPECT_EQ(a.inlier_fraction, b.inlier_fraction) << seed;
  EXPECT_EQ(a.runner_up_part, b.runner_up_part) << seed;
  EXPECT_EQ(a.T_scanner_part.rotation, b.T_scanner_part.rotation) << seed;
  EXPECT_EQ(a.T_scanner_part.translation_mm, b.T_scanner_part.translation_mm) << seed;
  EXPECT_EQ(a.views_examined, b.views_examined) << seed;
  ASSERT_EQ(a.candidates.size(), b.candidates.size()) << seed;
  for (std::size_t k = 0; k < a.candidates.size(); ++k) {
    EXPECT_EQ(a.candidates[k].part, b.candidates[k].part) << seed;
    EXPECT_EQ(a.candidates[k].view, b.candidates[k].view) << seed;
    EXPECT_EQ(a.candidates[k].score, b.candidates[k].score) << seed;
  }
  ASSERT_EQ(a.quick_fits.size(), b.quick_fits.size()) << seed;
  for (std::size_t k = 0; k < a.quick_fits.size(); ++k) {
    EXPECT_EQ(a.quick_fits[k].part, b.quick_fits[k].part) << seed;
    EXPECT_EQ(a.quick_fits[k].fit_mm2, b.quick_fits[k].fit_mm2) << seed;
  }
}

// Seeded scans of the base's parts in turn, with and without a runner: the same part, pose,
// candidates and quick-fit order to the last bit, in scans that the first selected views
// explain and in scans that go on to the search over every part.
TEST_F(RecognizerOnRegressionBase, ResultsDoNotDependOnTheTaskRunner) {
  const BackwardsTaskRunner backwards;
  const Recognizer with_runner(*base_, CosmosParameters{}, RecognitionParameters{}, &backwards);
  int ranked_quickly = 0, verified_first = 0;
  for (std::uint64_t seed = 201; seed < 211; ++seed) {
    const std::string& name = base_->parts[seed % base_->parts.size()].name;
    const RangeImage image = scan(name, seed);
    const int tasks_before = backwards.tasks;
    const RecognitionResult alone = recognizer_->recognize(image);
    const RecognitionResult run = with_runner.recognize(image);
    expect_same(alone, run, seed);
    ranked_quickly += run.quick_fits.empty() ? 0 : 1;
    verified_first += backwards.tasks - tasks_before >= 2 ? 1 : 0;
  }
  EXPECT_GE(ranked_quickly, 2);
  EXPECT_GE(verified_first, 8);
}

}  // namespace
}  // namespace cosmos
