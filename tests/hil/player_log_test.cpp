// What the HIL player writes, its checks read back unchanged; a damaged log names its line.
#include "tests/hil/player_log.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace cosmos::hil {
namespace {

namespace fs = std::filesystem;

TEST(PlayerLog, ReadsBackWhatWasWritten) {
  PlayerLog log;
  log.plan = {240, 3507, 3746, 29.97, 4, 127.5};
  log.captures = {{0, 1'000'000, -1, false, 0},
                  {2, 67'000'000, -1, true, 7},
                  {241, 8'000'000'000, 1, false, 963}};
  log.merged = {17};
  log.faults = {{"skip", 900, 5, 5}, {"glitch", 1200, 0, -1}};
  log.counts = {{"captures", 3}, {"jiggles", 1}};
  const fs::path file = fs::temp_directory_path() / "cosmos-player-log-test.log";
  write_player_log(file, log);
  const PlayerLog read = read_player_log(file);
  EXPECT_EQ(read.plan.lead_in_frames, 240);
  EXPECT_EQ(read.plan.end_sequence, 3746);
  EXPECT_DOUBLE_EQ(read.plan.capture_rate_hz, 29.97);
  EXPECT_DOUBLE_EQ(read.plan.cell_duration_s, 127.5);
  ASSERT_EQ(read.captures.size(), 3u);
  EXPECT_EQ(read.captures[1].sequence, 2);
  EXPECT_TRUE(read.captures[1].stale);
  EXPECT_EQ(read.captures[2].t_ns, 8'000'000'000);
  EXPECT_EQ(read.captures[2].content, 1);
  EXPECT_EQ(read.captures[1].belt_tick, 7);
  EXPECT_EQ(read.captures[2].belt_tick, 963);
  ASSERT_EQ(read.faults.size(), 2u);
  EXPECT_EQ(read.faults[0].kind, "skip");
  EXPECT_EQ(read.faults[0].observed, 5);
  EXPECT_EQ(read.faults[1].observed, -1);
  EXPECT_EQ(read.merged, std::vector<std::int64_t>{17});
  EXPECT_EQ(read.count("jiggles"), 1);
  EXPECT_EQ(read.count("absent"), 0);
  fs::remove(file);
}

TEST(PlayerLog, NamesTheLineItCannotRead) {
  const fs::path file = fs::temp_directory_path() / "cosmos-player-log-bad.log";
  std::ofstream(file) << "plan 1 2 3 4 5 6\ncapture 1 two 3 0 4\n";
  try {
    read_player_log(file);
    FAIL() << "no error";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find(":2: not a player record"), std::string::npos)
        << error.what();
  }
  fs::remove(file);
}

}  // namespace
}  // namespace cosmos::hil
