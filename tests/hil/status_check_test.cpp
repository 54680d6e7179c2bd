// COSMOS_STATUS's verdict on the cell run's faults: a stall must show as FAULT with the
// camera-timeout reason while the cell waits after the profiles before the gap, then
// SCANNING; the encoder's and the photo eye's faults must show in their totals.
#include "tests/hil/status_check.hpp"

#include <gtest/gtest.h>

namespace cosmos::hil {
namespace {

CellStatus status(CellState state, std::int64_t acquired, std::int64_t timeouts) {
  CellStatus s;
  s.state = state;
  s.state_text = state == CellState::kFault
                     ? "no frame from the camera within its watchdog (camera timeout)"
                     : "scanning";
  s.profiles_acquired = acquired;
  s.camera_timeouts = timeouts;
  return s;
}

struct StatusRunFixture {
  // Profiles 0..99 and 130..199: the stall's gap of 30 frames after 100 profiles.
  StatusRunFixture() {
    for (std::int64_t s = 0; s < 200; ++s)
      if (s < 100 || s >= 130) sequences.insert(s);
    tape.parts = {{"a", {}, 10, 40}, {"b", {}, 150, 180}};
    player.plan.lead_in_frames = 0;
    player.faults = {{"stall", 100, 1200, 30}, {"jiggle", 50, 3, -1}, {"glitch", 60, 0, -1}};
    player.counts = {
        {"jiggle_reversals", 2}, {"jiggles", 1}, {"glitches", 1}, {"bounced_arrivals", 1}};
    statuses = {status(CellState::kScanning, 50, 0), status(CellState::kFault, 100, 2),
                status(CellState::kFault, 100, 4), status(CellState::kScanning, 150, 5)};
    CellStatus last = status(CellState::kIdle, 170, 5);
    last.state_text = "the source has ended";
    last.encoder_reversals = 2;
    last.encoder_errors = 1;
    last.photo_eye_bounces = 2;
    statuses.push_back(last);
  }
  std::vector<ProbeCheck> check() {
    StatusRun run{&statuses, &player, &tape, &sequences, &identified, 0};
    return check_status_faults(run);
  }
  std::vector<CellStatus> statuses;
  PlayerLog player;
  TapeHeader tape;
  std::set<std::int64_t> sequences;
  std::vector<int> identified = {1, 1};
};

int failures(const std::vector<ProbeCheck>& checks) {
  int failed = 0;
  for (const ProbeCheck& check : checks) failed += check.ok ? 0 : 1;
  return failed;
}

TEST(StatusCheck, PassesAStallSeenLiveAndEveryFaultCounted) {
  StatusRunFixture run;
  const std::vector<ProbeCheck> checks = run.check();
  EXPECT_EQ(failures(checks), 0) << checks.front().line;
  EXPECT_EQ(checks.size(), 5u);
}

TEST(StatusCheck, FailsAStallThatNeverShowedAsFault) {
  StatusRunFixture run;
  run.statuses[1] = status(CellState::kScanning, 100, 2);
  run.statuses[2] = status(CellState::kScanning, 100, 4);
  EXPECT_EQ(failures(run.check()), 1);
}

TEST(StatusCheck, FailsAFaultThatDoesNotBelongToTheStall) {
  StatusRunFixture run;
  // FAULT while the loop had processed 99 profiles: not waiting after the gap's 100.
  run.statuses[1] = status(CellState::kFault, 99, 2);
  run.statuses[2] = status(CellState::kFault, 99, 4);
  EXPECT_EQ(failures(run.check()), 1);
}

TEST(StatusCheck, FailsACellThatNeverScannedAgain) {
  StatusRunFixture run;
  run.statuses[3] = status(CellState::kFault, 100, 5);
  EXPECT_GE(failures(run.check()), 1);
}

TEST(StatusCheck, FailsMissingEncoderAndPhotoEyeCounts) {
  StatusRunFixture run;
  run.statuses.back().encoder_errors = 0;  // the glitch neither an error nor 2 reversals
  EXPECT_EQ(failures(run.check()), 1);
  run.statuses.back().encoder_errors = 1;
  run.statuses.back().photo_eye_bounces = 0;
  EXPECT_EQ(failures(run.check()), 1);
}

TEST(StatusCheck, PassesAFaultThatThePlayedEncoderFaultsExplain) {
  StatusRunFixture run;
  CellStatus reversing = status(CellState::kFault, 60, 0);
  reversing.state_text = "2 encoder reversals since the last status";
  reversing.encoder_reversals = 2;
  run.statuses.insert(run.statuses.begin() + 1, reversing);
  for (std::size_t i = 2; i < run.statuses.size(); ++i) run.statuses[i].encoder_reversals = 2;
  EXPECT_EQ(failures(run.check()), 0);
}

TEST(StatusCheck, FailsAFaultNoPlayedFaultExplainsAndNamesIt) {
  StatusRunFixture run;
  CellStatus stuck = status(CellState::kFault, 60, 0);
  stuck.state_text = "7 profiles with the encoder stuck while the belt moves since the last status";
  stuck.encoder_stalls = 7;
  run.statuses.insert(run.statuses.begin() + 1, stuck);
  for (std::size_t i = 2; i < run.statuses.size(); ++i) run.statuses[i].encoder_stalls = 7;
  const std::vector<ProbeCheck> checks = run.check();
  ASSERT_EQ(failures(checks), 1);
  EXPECT_NE(checks.front().line.find("7 profiles with the encoder stuck"), std::string::npos)
      << checks.front().line;
}

TEST(StatusCheck, FailsAStallWhenNoneWasPlayed) {
  StatusRunFixture run;
  run.player.faults.erase(run.player.faults.begin());  // the stall
  EXPECT_GE(failures(run.check()), 1);
}

TEST(StatusCheck, FailsWhenTheLastStatusIsNotIdle) {
  StatusRunFixture run;
  run.statuses.back().state = CellState::kScanning;
  EXPECT_EQ(failures(run.check()), 1);
}

}  // namespace
}  // namespace cosmos::hil
