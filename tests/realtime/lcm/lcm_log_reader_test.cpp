// Log-file round trip: events written with lcm::LogFile (as lcm-logger writes them) read back
// through LcmLogReader as the structs that were encoded; damaged logs fail naming the file.
#include "realtime/lcm/lcm_log_reader.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <lcm/lcm-cpp.hpp>
#include <string>
#include <vector>

#include "core/input_error.hpp"
#include "realtime/lcm/lcm_channels.hpp"
#include "realtime/lcm/lcm_codec.hpp"
#include "realtime/lcm/lcm_message_conversion.hpp"
#include "realtime/lcm/profile_log_writer.hpp"
#include "tests/realtime/lcm_test_messages.hpp"

namespace cosmos {
namespace {

namespace fs = std::filesystem;

class LcmLogRoundTrip : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("cosmos_lcm_log_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // One event per call, time stamps 1 ms apart from a fixed start.
  template <class Input, class Message>
  void write(lcm::LogFile& log, const char* channel, const Input& input, Message message) {
    to_message(input, message);
    std::vector<std::uint8_t> bytes;
    ASSERT_TRUE(encode_message(message, bytes));
    write_raw(log, channel, bytes);
  }

  void write_raw(lcm::LogFile& log, const std::string& channel, std::vector<std::uint8_t> bytes) {
    lcm::LogEvent event;
    event.eventnum = next_event_;
    event.timestamp = 1'700'000'000'000'000 + 1000 * next_event_;
    event.channel = channel;
    event.datalen = static_cast<std::int32_t>(bytes.size());
    event.data = bytes.data();
    ASSERT_EQ(log.writeEvent(&event), 0);
    ++next_event_;
  }

  fs::path dir_;
  std::int64_t next_event_ = 0;
};

TEST_F(LcmLogRoundTrip, PosesProfilesAndStatusComeBackInOrder) {
  const fs::path path = dir_ / "cell.lcmlog";
  const std::vector<Profile> profiles = {testing::sample_profile(0), testing::sample_profile(1),
                                         testing::sample_profile(2, 0),
                                         testing::sample_profile(3, 320)};
  const std::vector<PartPose> poses = {testing::sample_pose(0), testing::sample_pose(1)};
  {
    lcm::LogFile log(path.string(), "w");
    ASSERT_TRUE(log.good());
    write(log, kProfileChannel, profiles[0], cosmos_lcm::range_profile_t{});
    write(log, kProfileChannel, profiles[1], cosmos_lcm::range_profile_t{});
    write(log, kPoseChannel, poses[0], cosmos_lcm::part_pose_t{});
    write_raw(log, "SOMEONE_ELSES_CHANNEL", {1, 2, 3});
    write(log, kProfileChannel, profiles[2], cosmos_lcm::range_profile_t{});
    write(log, kStatusChannel, testing::sample_status("scanning"), cosmos_lcm::cell_status_t{});
    write(log, kProfileChannel, profiles[3], cosmos_lcm::range_profile_t{});
    write(log, kPoseChannel, poses[1], cosmos_lcm::part_pose_t{});
  }

  // One reused Profile, as the replay source will use it: the empty profile between two wide
  // ones must come back empty, not with the previous heights.
  LcmLogReader reader(path);
  Profile profile;
  for (std::size_t i = 0; i < profiles.size(); ++i) {
    SCOPED_TRACE(i);
    ASSERT_TRUE(reader.next_profile(profile));
    testing::expect_same_profile(profiles[i], profile);
  }
  EXPECT_EQ(reader.event_timestamp_us(), 1'700'000'000'000'000 + 1000 * 6);
  EXPECT_FALSE(reader.next_profile(profile));

  const std::vector<PartPose> read_poses = read_logged_poses(path);
  ASSERT_EQ(read_poses.size(), 2U);
  testing::expect_same_pose(poses[0], read_poses[0]);
  testing::expect_same_pose(poses[1], read_poses[1]);

  const std::vector<CellStatus> statuses = read_logged_statuses(path);
  ASSERT_EQ(statuses.size(), 1U);
  testing::expect_same_status(testing::sample_status("scanning"), statuses[0]);
  EXPECT_EQ(read_logged_profiles(path).size(), 4U);
}

// write_profile_log, the reader's counterpart: what it writes reads back, in order, on its
// channel and stamped with each profile's time; a log it cannot create is named.
TEST_F(LcmLogRoundTrip, WrittenProfilesReadBackAndAnUnwritableLogIsNamed) {
  std::vector<Profile> profiles;
  for (std::uint64_t seq = 7; seq < 10; ++seq) profiles.push_back(testing::sample_profile(seq, 96));
  const fs::path path = dir_ / "written.lcmlog";
  write_profile_log(path, profiles, "RECORDED_PROFILES");
  EXPECT_TRUE(read_logged_profiles(path).empty());  // nothing on the default channel
  const std::vector<Profile> read = read_logged_profiles(path, "RECORDED_PROFILES");
  ASSERT_EQ(read.size(), profiles.size());
  for (std::size_t i = 0; i < read.size(); ++i) {
    EXPECT_EQ(read[i].seq, profiles[i].seq);
    EXPECT_EQ(read[i].t_us, profiles[i].t_us);
    EXPECT_EQ(read[i].encoder_ticks, profiles[i].encoder_ticks);
    ASSERT_EQ(read[i].width(), profiles[i].width());
    for (std::size_t k = 0; k < read[i].width(); ++k)
      if (std::isnan(profiles[i].z_mm[k]))
        EXPECT_TRUE(std::isnan(read[i].z_mm[k])) << i << " " << k;
      else
        EXPECT_EQ(read[i].z_mm[k], profiles[i].z_mm[k]) << i << " " << k;
  }
  const fs::path unwritable = dir_ / "no-such-dir" / "x.lcmlog";
  try {
    write_profile_log(unwritable, profiles);
    FAIL() << "no error for an unwritable log";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()),
              unwritable.string() + ": cannot create an LCM log (No such file or directory)");
  }
}

TEST_F(LcmLogRoundTrip, MissingFileIsNamed) {
  const fs::path path = dir_ / "absent.lcmlog";
  try {
    LcmLogReader reader(path);
    FAIL() << "no error for a missing log";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()),
              path.string() + ": cannot open as an LCM log (No such file or directory)");
  }
}

TEST_F(LcmLogRoundTrip, ForeignFileIsNotALog) {
  const fs::path path = dir_ / "notes.txt";
  std::ofstream(path) << "these are not LCM events\n";
  LcmLogReader reader(path);
  PartPose pose;
  try {
    reader.next_pose(pose);
    FAIL() << "no error for a text file";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()), path.string() + ": not an LCM log (no event found)");
  }
}

TEST_F(LcmLogRoundTrip, WrongTypeOnAChannelNamesTheEvent) {
  const fs::path path = dir_ / "mixed.lcmlog";
  {
    lcm::LogFile log(path.string(), "w");
    write(log, kPoseChannel, testing::sample_pose(0), cosmos_lcm::part_pose_t{});
    write(log, kPoseChannel, testing::sample_status("not a pose"), cosmos_lcm::cell_status_t{});
  }
  LcmLogReader reader(path);
  PartPose pose;
  EXPECT_TRUE(reader.next_pose(pose));
  try {
    reader.next_pose(pose);
    FAIL() << "no error for a status on COSMOS_POSE";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()),
              path.string() + ": event 1 on COSMOS_POSE does not decode as part_pose_t");
  }
}

TEST_F(LcmLogRoundTrip, ProfilesOutOfBoundsAreSkippedAndCounted) {
  const fs::path path = dir_ / "hostile.lcmlog";
  {
    lcm::LogFile log(path.string(), "w");
    write(log, kProfileChannel, testing::sample_profile(0, 64), cosmos_lcm::range_profile_t{});
    // A 139-byte profile claiming 2^29 samples (4 * width wraps the generated decode's int).
    cosmos_lcm::range_profile_t message{};
    to_message(testing::sample_profile(1, 22), message);
    std::vector<std::uint8_t> bytes;
    ASSERT_TRUE(encode_message(message, bytes));
    bytes.resize(139);
    const std::uint8_t two_to_the_29[] = {0x20, 0x00, 0x00, 0x00};
    std::memcpy(bytes.data() + kRangeProfileWidthOffset, two_to_the_29, 4);
    write_raw(log, kProfileChannel, bytes);
    Profile no_spacing = testing::sample_profile(2, 64);
    no_spacing.dx_mm = 1e-300;
    write(log, kProfileChannel, no_spacing, cosmos_lcm::range_profile_t{});
    write(log, kProfileChannel, testing::sample_profile(3, 64), cosmos_lcm::range_profile_t{});
  }
  LcmLogReader reader(path, {}, 640);
  Profile profile;
  ASSERT_TRUE(reader.next_profile(profile));
  EXPECT_EQ(profile.seq, 0U);
  ASSERT_TRUE(reader.next_profile(profile));
  EXPECT_EQ(profile.seq, 3U);
  EXPECT_FALSE(reader.next_profile(profile));
  EXPECT_EQ(reader.rejected_profiles(), 2);
  EXPECT_EQ(reader.first_rejection(),
            "event 1 on COSMOS_PROFILE is wider than the profile width (536870912 > 640)");
  EXPECT_EQ(reader.damaged_bytes(), 0);
}

// lcm_eventlog's framing, big-endian: sync, event number, time stamp, channel and data lengths.
void append_event_header(std::vector<std::uint8_t>& file, std::int32_t channel_bytes,
                         std::int32_t data_bytes) {
  auto put = [&file](std::uint64_t value, int bytes) {
    for (int i = bytes - 1; i >= 0; --i)
      file.push_back(static_cast<std::uint8_t>(value >> (8 * i)));
  };
  put(0xEDA1DA01, 4);
  put(7, 8);
  put(1'700'000'000'000'000, 8);
  put(static_cast<std::uint32_t>(channel_bytes), 4);
  put(static_cast<std::uint32_t>(data_bytes), 4);
}

TEST_F(LcmLogRoundTrip, AnEventClaimingMoreThanTheFileIsSkippedAsDamage) {
  const fs::path path = dir_ / "claims.lcmlog";
  {
    lcm::LogFile log(path.string(), "w");
    write(log, kProfileChannel, testing::sample_profile(0, 16), cosmos_lcm::range_profile_t{});
  }
  const auto good_bytes = static_cast<std::int64_t>(fs::file_size(path));
  // A header claiming 2 GB of data (lcm_eventlog allocates length + 1 in int: null, then
  // reads into it), then a whole event after it.
  std::vector<std::uint8_t> damage;
  append_event_header(damage, 14, 0x7FFFFFFF);
  for (const char c : std::string(kProfileChannel)) damage.push_back(static_cast<std::uint8_t>(c));
  {
    std::ofstream out(path, std::ios::binary | std::ios::app);
    out.write(reinterpret_cast<const char*>(damage.data()),
              static_cast<std::streamsize>(damage.size()));
  }
  {
    lcm::LogFile log(path.string(), "a");
    write(log, kProfileChannel, testing::sample_profile(1, 16), cosmos_lcm::range_profile_t{});
  }
  LcmLogReader reader(path);
  Profile profile;
  ASSERT_TRUE(reader.next_profile(profile));
  ASSERT_TRUE(reader.next_profile(profile));
  EXPECT_EQ(profile.seq, 1U);  // resynchronized on the event after the damage
  EXPECT_FALSE(reader.next_profile(profile));
  EXPECT_EQ(reader.first_damage_offset(), good_bytes);
  EXPECT_EQ(reader.damaged_bytes(), static_cast<std::int64_t>(damage.size()));
}

TEST_F(LcmLogRoundTrip, ATruncatedLastEventIsCountedAsDamage) {
  const fs::path path = dir_ / "cut.lcmlog";
  {
    lcm::LogFile log(path.string(), "w");
    write(log, kProfileChannel, testing::sample_profile(0, 16), cosmos_lcm::range_profile_t{});
  }
  const auto one_event = static_cast<std::int64_t>(fs::file_size(path));
  {
    lcm::LogFile log(path.string(), "a");
    write(log, kProfileChannel, testing::sample_profile(1, 16), cosmos_lcm::range_profile_t{});
  }
  fs::resize_file(path, static_cast<std::uintmax_t>(one_event + 40));
  LcmLogReader reader(path);
  Profile profile;
  ASSERT_TRUE(reader.next_profile(profile));
  EXPECT_FALSE(reader.next_profile(profile));
  EXPECT_EQ(reader.first_damage_offset(), one_event);
  EXPECT_EQ(reader.damaged_bytes(), 40);
}

}  // namespace
}  // namespace cosmos
