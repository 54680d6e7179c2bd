// The repeated stream goes on where each pass ended, and its health adds up over passes.
#include "realtime/sources/repeating_source.hpp"

#include <gtest/gtest.h>

#include <memory>

#include "tests/realtime/scripted_source.hpp"
#include "tests/realtime/source_stream.hpp"

namespace cosmos {
namespace {

TEST(RepeatingSource, PlaysTheSourceAgainAsOneContinuousStream) {
  auto* scripted = new testing::ScriptedSource(testing::belt_profiles(10));
  scripted->health_now.camera_timeouts = 2;
  RepeatingSource source(std::unique_ptr<ScannerSource>(scripted), 4, 400);
  ASSERT_EQ(source.start(), SourceStatus::kOk);
  Profile slot;
  source.reserve(slot);
  for (std::uint64_t k = 0; k < 35; ++k) {
    ASSERT_EQ(source.next(slot), SourceStatus::kOk);
    EXPECT_EQ(slot.seq, k);
    EXPECT_EQ(slot.encoder_ticks, static_cast<std::int64_t>(4 * k));
    EXPECT_EQ(slot.t_us, static_cast<std::int64_t>(400 * k));
  }
  EXPECT_EQ(source.passes(), 3u);
  EXPECT_EQ(scripted->starts, 4);
  // The scripted source's counts run on over restarts, as a camera's statistics do: a pass
  // that added nothing adds nothing.
  EXPECT_EQ(source.health().camera_timeouts, 0u);
}

TEST(RepeatingSource, AddsWhatEachPassAdded) {
  auto* scripted = new testing::ScriptedSource(testing::belt_profiles(10));
  scripted->lose_at = 5;  // every pass loses 3 profiles after its fifth
  scripted->lost_reported = 3;
  RepeatingSource source(std::unique_ptr<ScannerSource>(scripted), 4, 400);
  ASSERT_EQ(source.start(), SourceStatus::kOk);
  Profile slot;
  source.reserve(slot);
  for (int k = 0; k < 35; ++k) ASSERT_EQ(source.next(slot), SourceStatus::kOk);
  EXPECT_EQ(scripted->health().profiles_lost, 12u);  // cumulative in the source
  EXPECT_EQ(source.health().profiles_lost, 12u);     // four passes of 3, not a sum of sums
}

}  // namespace
}  // namespace cosmos
