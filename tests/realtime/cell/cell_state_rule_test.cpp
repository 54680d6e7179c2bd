#include "realtime/cell/cell_state_rule.hpp"

#include <gtest/gtest.h>

#include <string>

namespace cosmos {
namespace {

TEST(CellStateRule, ScanningWhileNoFaultTotalGrows) {
  CellStatus previous, status;
  previous.profiles_acquired = 10;
  status.profiles_acquired = 500;
  decide_cell_state({}, previous, status);
  EXPECT_EQ(status.state, CellState::kScanning);
  EXPECT_EQ(status.state_text, "scanning");
}

TEST(CellStateRule, EveryFaultTotalThatGrowsIsAFaultNamedWithItsCount) {
  for (const FaultTotal& fault : fault_totals()) {
    CellStatus previous, status;
    previous.*fault.total = 4;
    status.*fault.total = 7;
    decide_cell_state({}, previous, status);
    EXPECT_EQ(status.state, CellState::kFault) << fault.what;
    EXPECT_EQ(status.state_text, std::string("3 ") + fault.what + " since the last status");
  }
}

TEST(CellStateRule, AStallAndLostFramesAreOneFaultNamingBoth) {
  CellStatus previous, status;
  status.camera_timeouts = 2;
  status.profiles_lost = 5;
  SourceCondition source;
  source.stalled = true;
  decide_cell_state(source, previous, status);
  EXPECT_EQ(status.state, CellState::kFault);
  EXPECT_EQ(status.state_text, std::string(kCameraStallReason) +
                                   "; 2 camera timeouts; 5 frames lost since the last status");
}

TEST(CellStateRule, ASourceFailureOutranksTheEndAndTheEndOutranksGrownTotals) {
  CellStatus previous, status;
  status.encoder_errors = 1;
  SourceCondition source;
  source.ended = true;
  decide_cell_state(source, previous, status);
  EXPECT_EQ(status.state, CellState::kIdle);
  source.failed = true;
  source.failure = "/dev/video0: device removed";
  decide_cell_state(source, previous, status);
  EXPECT_EQ(status.state, CellState::kFault);
  EXPECT_EQ(status.state_text, "the scanner source failed: /dev/video0: device removed");
}

TEST(CellStateRule, TheFaultEndsWithThePeriodThatHadIt) {
  CellStatus first, second, third;
  second.laser_off_profiles = 12;
  third.laser_off_profiles = 12;
  decide_cell_state({}, first, second);
  decide_cell_state({}, second, third);
  EXPECT_EQ(second.state, CellState::kFault);
  EXPECT_EQ(third.state, CellState::kScanning);
}

}  // namespace
}  // namespace cosmos
