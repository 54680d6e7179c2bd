// The stream checker finds in the data what a source cannot report (a stuck encoder, a dark
// laser, a replayed seq gap or encoder jump), merges what it does report without counting a
// fault twice, and records each faulty profile for the recognizer.
#include "realtime/sources/stream_checked_source.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include "tests/realtime/scripted_source.hpp"
#include "tests/realtime/source_stream.hpp"

namespace cosmos {
namespace {

using testing::belt_profiles;
using testing::ScriptedSource;

struct Checked {
  explicit Checked(std::vector<Profile> profiles)
      : scripted(new ScriptedSource(std::move(profiles))),
        source(std::unique_ptr<ScannerSource>(scripted), 4) {}
  testing::SourceStream run() {
    EXPECT_EQ(source.start(), SourceStatus::kOk);
    return testing::read_stream(source);
  }
  ScriptedSource* scripted;
  StreamCheckedSource source;
};

TEST(StreamCheckedSource, CountsNothingInACleanStreamAndAllocatesNothing) {
  Checked checked(belt_profiles(50));
  const testing::SourceStream stream = checked.run();
  EXPECT_EQ(stream.profiles.size(), 50u);
  EXPECT_EQ(stream.allocations_in_next, 0u);
  const SourceHealth health = checked.source.health();
  EXPECT_EQ(health.profiles_lost, 0u);
  EXPECT_EQ(health.encoder_errors, 0u);
  EXPECT_EQ(health.encoder_reversals, 0u);
  EXPECT_EQ(health.encoder_stalls, 0u);
  EXPECT_EQ(health.laser_off_profiles, 0u);
  EXPECT_EQ(checked.source.faults().recorded(), 0u);
}

TEST(StreamCheckedSource, TakesTheJitterOfAFreeRunningCamerasCountForNoFault) {
  std::vector<Profile> profiles = belt_profiles(60);
  // The count read when each frame arrives, up to a profile's ticks late: steps of 0 to 8,
  // never two zero steps in a row.
  const int lag[] = {0, 3, 4, 1, 2, 4, 0, 4};
  for (std::size_t k = 0; k < profiles.size(); ++k) profiles[k].encoder_ticks -= lag[k % 8];
  Checked checked(profiles);
  checked.run();
  EXPECT_EQ(checked.source.health().encoder_errors, 0u);
  EXPECT_EQ(checked.source.health().encoder_stalls, 0u);
  EXPECT_EQ(checked.source.health().encoder_reversals, 0u);
  EXPECT_EQ(checked.source.faults().recorded(), 0u);
}

TEST(StreamCheckedSource, BurstsOfFramesWithinTheWiderSettingsAreNoFault) {
  std::vector<Profile> profiles = belt_profiles(64);
  // Frames delivered four at a time: the count read for a burst is the same, then jumps.
  for (std::size_t k = 0; k < profiles.size(); ++k)
    profiles[k].encoder_ticks = static_cast<std::int64_t>(k / 4 * 16);
  auto* scripted = new ScriptedSource(profiles);
  StreamCheckedSource wide(std::unique_ptr<ScannerSource>(scripted), 4,
                           {.encoder_tolerance_profiles = 3, .stuck_profiles = 4});
  ASSERT_EQ(wide.start(), SourceStatus::kOk);
  testing::read_stream(wide);
  EXPECT_EQ(wide.health().encoder_errors, 0u);
  EXPECT_EQ(wide.health().encoder_stalls, 0u);

  Checked narrow(profiles);  // the defaults take the bursts for faults
  narrow.run();
  EXPECT_EQ(narrow.source.health().encoder_errors, 15u);  // every jump of 16 ticks
  EXPECT_EQ(narrow.source.health().encoder_stalls, 48u);  // every burst's three repeats
}

TEST(StreamCheckedSource, CountsASequenceGapOnceEvenWhenTheSourceReportedIt) {
  std::vector<Profile> profiles = belt_profiles(40);
  profiles.erase(profiles.begin() + 10, profiles.begin() + 17);  // 7 lost before seq 17
  profiles.erase(profiles.begin() + 20, profiles.begin() + 23);  // 3 lost before seq 30
  Checked checked(profiles);
  checked.scripted->lose_at = 21;  // the source says so itself for the second gap
  checked.scripted->lost_reported = 3;
  checked.run();
  EXPECT_EQ(checked.source.health().profiles_lost, 10u);
  EXPECT_EQ(checked.source.faults().recorded(), 2u);
  EXPECT_EQ(checked.source.faults().fault_in({5, 17, 17}), StreamFaultKind::kSequenceGap);
  // A part whose rows lie between the gaps, not beside them, lost nothing.
  EXPECT_EQ(checked.source.faults().fault_in({18, 25, 25}), StreamFaultKind::kNone);
  // Frames 27 to 29 lost in the empty rows the tracker kept after a part's data (to 25): not
  // the part's; right after its data (to 26) they may have held more of it.
  EXPECT_EQ(checked.source.faults().fault_in({18, 25, 31}), StreamFaultKind::kNone);
  EXPECT_EQ(checked.source.faults().fault_in({18, 26, 31}), StreamFaultKind::kSequenceGap);
}

TEST(StreamCheckedSource, AnEncoderSpikeIsTwoEncoderErrorsAndNoReversal) {
  std::vector<Profile> profiles = belt_profiles(30);
  profiles[12].encoder_ticks += 400'000;  // y = 40 m for one profile
  Checked checked(profiles);
  checked.run();
  EXPECT_EQ(checked.source.health().encoder_errors, 2u);
  EXPECT_EQ(checked.source.health().encoder_reversals, 0u);
  EXPECT_EQ(checked.source.faults().fault_in({0, 29, 29}), StreamFaultKind::kEncoderJump);
}

TEST(StreamCheckedSource, ABeltRunningBackIsTwoReversals) {
  std::vector<Profile> profiles = belt_profiles(30);
  for (int k = 10; k < 30; ++k)  // back over profiles 10..14, then forward again
    profiles[static_cast<std::size_t>(k)].encoder_ticks =
        k < 15 ? 36 - 4 * (k - 9) : 16 + 4 * (k - 15);
  Checked checked(profiles);
  checked.run();
  EXPECT_EQ(checked.source.health().encoder_reversals, 2u);
  EXPECT_EQ(checked.source.health().encoder_errors, 5u);  // the five backward steps
}

TEST(StreamCheckedSource, ACountThatStopsWhileFramesArriveIsAStuckEncoder) {
  std::vector<Profile> profiles = belt_profiles(30);
  for (int k = 10; k < 30; ++k)  // stuck for profiles 10..17, then on from there
    profiles[static_cast<std::size_t>(k)].encoder_ticks = k < 18 ? 36 : 36 + 4 * (k - 17);
  Checked checked(profiles);
  checked.run();
  EXPECT_EQ(checked.source.health().encoder_stalls, 8u);
  EXPECT_EQ(checked.source.health().encoder_errors, 0u);
  EXPECT_EQ(checked.source.faults().fault_in({12, 16, 16}), StreamFaultKind::kEncoderStuck);
  EXPECT_EQ(checked.source.faults().fault_in({18, 29, 29}), StreamFaultKind::kNone);
}

TEST(StreamCheckedSource, AProfileWithoutASinglePointIsLaserOff) {
  std::vector<Profile> profiles = belt_profiles(30);
  for (int k = 20; k < 24; ++k)
    for (float& z : profiles[static_cast<std::size_t>(k)].z_mm) z = Profile::kNoData;
  profiles[5].z_mm[3] = Profile::kNoData;  // one missing point is no laser fault
  Checked checked(profiles);
  checked.run();
  EXPECT_EQ(checked.source.health().laser_off_profiles, 4u);
  // A part that ended right before the dark profiles was cut short by them.
  EXPECT_EQ(checked.source.faults().fault_in({10, 19, 19}), StreamFaultKind::kLaserOff);
  EXPECT_EQ(checked.source.faults().fault_in({10, 18, 18}), StreamFaultKind::kNone);
}

TEST(StreamCheckedSource, TakesTheDecodersEncoderCountsWithoutAddingItsOwn) {
  std::vector<Profile> profiles = belt_profiles(30);
  for (int k = 12; k < 30; ++k) profiles[static_cast<std::size_t>(k)].encoder_ticks -= 4;
  Checked checked(profiles);
  checked.scripted->health_now.encoder_errors = 0;
  ASSERT_EQ(checked.source.start(), SourceStatus::kOk);
  Profile slot;
  checked.source.reserve(slot);
  for (int k = 0; k < 12; ++k) ASSERT_EQ(checked.source.next(slot), SourceStatus::kOk);
  checked.scripted->health_now.encoder_errors = 1;  // the decoder saw the missed edge
  while (checked.source.next(slot) == SourceStatus::kOk) {
  }
  EXPECT_EQ(checked.source.health().encoder_errors, 1u);
  EXPECT_EQ(checked.source.health().encoder_stalls, 0u);
}

}  // namespace
}  // namespace cosmos
