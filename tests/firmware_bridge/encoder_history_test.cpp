// The encoder count at a past instant: the count after the last step stamped at or before
// it, the starting count before the first step, a late-settled step kept in time order, and
// an instant older than the kept steps answered with the oldest count and said to be so.
#include "firmware_bridge/encoder_history.hpp"

#include <gtest/gtest.h>

#include <memory>

namespace cosmos {
namespace {

TEST(EncoderHistory, TheCountAtAnInstantIsTheLastStepAtOrBeforeIt) {
  EncoderHistory history;
  history.reset(100, 1'000);
  for (int k = 1; k <= 10; ++k) history.record(1'000 + 100 * k, 100 + k);
  EXPECT_EQ(history.ticks_at(1'000).ticks, 100);  // the start, before any step
  EXPECT_EQ(history.ticks_at(1'099).ticks, 100);
  EXPECT_EQ(history.ticks_at(1'100).ticks, 101);  // a step counts from its own stamp on
  EXPECT_EQ(history.ticks_at(1'550).ticks, 105);
  EXPECT_EQ(history.ticks_at(5'000).ticks, 110);
  EXPECT_TRUE(history.ticks_at(1'550).covered);
  const EncoderHistory::Count before = history.ticks_at(999);
  EXPECT_FALSE(before.covered);  // before the count was known
  EXPECT_EQ(before.ticks, 100);
}

TEST(EncoderHistory, AStepStampedBeforeTheLatestIsKeptAtTheLatestsTime) {
  EncoderHistory history;
  history.reset(0, 0);
  history.record(500, 1);
  history.record(400, 2);  // a debounced edge settled after a later one was counted
  history.record(700, 3);
  EXPECT_EQ(history.ticks_at(450).ticks, 0);
  EXPECT_EQ(history.ticks_at(500).ticks, 2);
  EXPECT_EQ(history.ticks_at(699).ticks, 2);
  EXPECT_EQ(history.ticks_at(700).ticks, 3);
}

TEST(EncoderHistory, AnInstantOlderThanTheKeptStepsIsAnsweredWithTheOldestCount) {
  auto history = std::make_unique<EncoderHistory>();
  history->reset(0, 0);
  const auto steps = static_cast<std::int64_t>(EncoderHistory::kCapacity) + 100;
  for (std::int64_t k = 1; k <= steps; ++k) history->record(10 * k, k);
  EXPECT_EQ(history->size(), EncoderHistory::kCapacity);
  // The oldest kept step is 101 (stamped 1010); step 100 (1000) became the origin.
  const EncoderHistory::Count lost = history->ticks_at(999);
  EXPECT_FALSE(lost.covered);
  EXPECT_EQ(lost.ticks, 100);
  EXPECT_TRUE(history->ticks_at(1'000).covered);
  EXPECT_EQ(history->ticks_at(1'005).ticks, 100);
  EXPECT_EQ(history->ticks_at(1'010).ticks, 101);
  EXPECT_EQ(history->ticks_at(10 * steps).ticks, steps);
}

}  // namespace
}  // namespace cosmos
