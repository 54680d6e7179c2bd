// Replay of an lcm-logger log: the COSMOS_PROFILE events come back bit-identical and in
// order, other channels are skipped, too-wide profiles are dropped and counted, and a bad
// file fails start() with one line naming it.
#include "realtime/sources/replay_source.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <lcm/lcm-cpp.hpp>
#include <string>
#include <vector>

#include "realtime/lcm/lcm_channels.hpp"
#include "realtime/lcm/lcm_codec.hpp"
#include "realtime/lcm/lcm_message_conversion.hpp"
#include "tests/realtime/lcm_test_messages.hpp"
#include "tests/realtime/source_stream.hpp"

namespace cosmos {
namespace {

namespace fs = std::filesystem;

class ReplaySourceTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("cosmos_replay_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // The profiles on COSMOS_PROFILE with a pose on COSMOS_POSE between the first two.
  fs::path write_log(const std::vector<Profile>& profiles,
                     const char* profile_channel = kProfileChannel) {
    const fs::path path = dir_ / "scan.lcmlog";
    lcm::LogFile log(path.string(), "w");
    EXPECT_TRUE(log.good());
    for (std::size_t i = 0; i < profiles.size(); ++i) {
      cosmos_lcm::range_profile_t message{};
      to_message(profiles[i], message);
      write(log, profile_channel, message);
      if (i == 0) {
        cosmos_lcm::part_pose_t pose{};
        to_message(testing::sample_pose(0), pose);
        write(log, kPoseChannel, pose);
      }
    }
    return path;
  }

  template <class Message>
  void write(lcm::LogFile& log, const char* channel, const Message& message) {
    std::vector<std::uint8_t> bytes;
    ASSERT_TRUE(encode_message(message, bytes));
    lcm::LogEvent event;
    event.eventnum = next_event_++;
    event.timestamp = 1'700'000'000'000'000 + 1000 * event.eventnum;
    event.channel = channel;
    event.datalen = static_cast<std::int32_t>(bytes.size());
    event.data = bytes.data();
    ASSERT_EQ(log.writeEvent(&event), 0);
  }

  fs::path dir_;
  std::int64_t next_event_ = 0;
};

TEST_F(ReplaySourceTest, ProfilesComeBackBitIdenticalAndOtherChannelsAreSkipped) {
  const std::vector<Profile> recorded = {testing::sample_profile(0), testing::sample_profile(1),
                                         testing::sample_profile(2, 320)};
  ReplaySource source(write_log(recorded));
  ASSERT_EQ(source.start(), SourceStatus::kOk) << source.last_error();
  EXPECT_EQ(source.profile_count(), 3u);
  const testing::SourceStream stream = testing::read_stream(source);
  EXPECT_EQ(stream.end, SourceStatus::kEndOfStream);
  EXPECT_EQ(stream.allocations_in_next, 0u);
  ASSERT_EQ(stream.profiles.size(), recorded.size());
  for (std::size_t i = 0; i < recorded.size(); ++i) {
    testing::expect_same_profile(recorded[i], stream.profiles[i]);
  }
  Profile slot;
  source.reserve(slot);
  EXPECT_EQ(slot.z_mm.capacity(), 640u);
  EXPECT_EQ(source.next(slot), SourceStatus::kEndOfStream);
  EXPECT_EQ(source.health().profiles_lost, 0u);

  // start() rewinds.
  ASSERT_EQ(source.start(), SourceStatus::kOk);
  ASSERT_EQ(source.next(slot), SourceStatus::kOk);
  testing::expect_same_profile(recorded[0], slot);
}

TEST_F(ReplaySourceTest, ProfilesWiderThanTheSlotAreDroppedAndCounted) {
  const std::vector<Profile> recorded = {testing::sample_profile(0, 100),
                                         testing::sample_profile(1, 300),
                                         testing::sample_profile(2, 200)};
  ReplaySourceSettings settings;
  settings.max_profile_width = 256;
  settings.mm_per_profile = 0.25;
  ReplaySource source(write_log(recorded), settings);
  ASSERT_EQ(source.start(), SourceStatus::kOk) << source.last_error();
  EXPECT_EQ(source.mm_per_profile(), 0.25);
  Profile slot;
  source.reserve(slot);
  ASSERT_EQ(source.next(slot), SourceStatus::kOk);
  EXPECT_EQ(slot.seq, 0u);
  ASSERT_EQ(source.next(slot), SourceStatus::kOk);
  testing::expect_same_profile(recorded[2], slot);
  EXPECT_EQ(source.health().profiles_lost, 1u);
  EXPECT_EQ(source.next(slot), SourceStatus::kEndOfStream);

  // A slot that was never reserved cannot take a profile without allocating: dropped too.
  ASSERT_EQ(source.start(), SourceStatus::kOk);
  Profile unreserved;
  EXPECT_EQ(source.next(unreserved), SourceStatus::kEndOfStream);
  EXPECT_EQ(source.health().profiles_lost, 3u);
}

TEST_F(ReplaySourceTest, ProfilesWithoutAUsableSpacingAreDroppedAndCounted) {
  std::vector<Profile> recorded = {testing::sample_profile(0, 100), testing::sample_profile(1, 100),
                                   testing::sample_profile(2, 100)};
  recorded[1].dx_mm = 0.0;  // the conditioner divides by it
  ReplaySource source(write_log(recorded));
  ASSERT_EQ(source.start(), SourceStatus::kOk) << source.last_error();
  EXPECT_EQ(source.health().profiles_lost, 1u);
  Profile slot;
  source.reserve(slot);
  ASSERT_EQ(source.next(slot), SourceStatus::kOk);
  ASSERT_EQ(source.next(slot), SourceStatus::kOk);
  EXPECT_EQ(slot.seq, 2u);
  EXPECT_EQ(source.next(slot), SourceStatus::kEndOfStream);

  // Nothing usable at all: refused, naming the first bad event.
  ReplaySource none(write_log({recorded[1]}));
  EXPECT_EQ(none.start(), SourceStatus::kError);
  EXPECT_EQ(none.last_error(), (dir_ / "scan.lcmlog").string() +
                                   ": no COSMOS_PROFILE events to replay (1 rejected, first: "
                                   "event 0 on COSMOS_PROFILE has x0_mm or dx_mm out of range)");
}

TEST_F(ReplaySourceTest, ATruncatedLogIsRefusedNotReplayedShort) {
  const fs::path full = write_log({testing::sample_profile(0), testing::sample_profile(1)});
  const fs::path cut = dir_ / "cut.lcmlog";
  fs::copy_file(full, cut);
  fs::resize_file(cut, fs::file_size(full) - 100);
  ReplaySource source(cut);
  EXPECT_EQ(source.start(), SourceStatus::kError);
  EXPECT_NE(source.last_error().find(cut.string() + ": truncated or damaged at byte "),
            std::string_view::npos)
      << source.last_error();
}

TEST_F(ReplaySourceTest, AConfiguredProfileChannelIsTheOneReplayed) {
  const fs::path log =
      write_log({testing::sample_profile(0), testing::sample_profile(1)}, "CELL2_PROFILE");
  ReplaySource by_default(log);
  EXPECT_EQ(by_default.start(), SourceStatus::kError);
  EXPECT_EQ(by_default.last_error(), log.string() + ": no COSMOS_PROFILE events to replay");
  ReplaySourceSettings settings;
  settings.channel = "CELL2_PROFILE";
  ReplaySource renamed(log, settings);
  ASSERT_EQ(renamed.start(), SourceStatus::kOk) << renamed.last_error();
  EXPECT_EQ(renamed.profile_count(), 2u);
}

TEST_F(ReplaySourceTest, MissingForeignAndEmptyFilesFailWithOneLineNamingThem) {
  const fs::path missing = dir_ / "absent.lcmlog";
  ReplaySource absent(missing);
  EXPECT_EQ(absent.start(), SourceStatus::kError);
  EXPECT_EQ(absent.last_error(),
            missing.string() + ": cannot open as an LCM log (No such file or directory)");

  const fs::path text = dir_ / "notes.txt";
  std::ofstream(text) << "not an event log\n";
  ReplaySource foreign(text);
  EXPECT_EQ(foreign.start(), SourceStatus::kError);
  EXPECT_EQ(foreign.last_error(), text.string() + ": not an LCM log (no event found)");

  // Truncated inside its only event: no complete event is left.
  const fs::path full = write_log({testing::sample_profile(0)});
  const fs::path truncated = dir_ / "truncated.lcmlog";
  fs::copy_file(full, truncated);
  fs::resize_file(truncated, fs::file_size(full) / 2);
  ReplaySource cut(truncated);
  EXPECT_EQ(cut.start(), SourceStatus::kError);
  EXPECT_EQ(cut.last_error(), truncated.string() + ": not an LCM log (no event found)");

  const fs::path empty = dir_ / "empty.lcmlog";
  std::ofstream(empty).flush();
  ReplaySource nothing(empty);
  EXPECT_EQ(nothing.start(), SourceStatus::kError);
  EXPECT_EQ(nothing.last_error(), empty.string() + ": no COSMOS_PROFILE events to replay");
  Profile slot;
  EXPECT_EQ(nothing.next(slot), SourceStatus::kError);
}

}  // namespace
}  // namespace cosmos
