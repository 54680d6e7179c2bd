// Each fault the simulated source injects, once, in the middle of a four-part run of the
// cell: counted on COSMOS_STATUS with FAULT and its reason while it lasts, the loop alive to
// the end, the parts it hit published as ERROR (never as a wrong OK pose) and the others
// identified as without the fault.
#include "sim/source/source_fault_injector.hpp"

#include <gtest/gtest.h>

#include <memory>

#include "sim/source/simulated_source.hpp"
#include "tests/sim/fault_cell_run.hpp"

namespace cosmos {
namespace {

using testing::FaultCellRun;

struct SimulatedFaultRun {
  explicit SimulatedFaultRun(const std::function<void(FaultInjectionSettings&, std::int64_t)>& set,
                             int recognizer_delay_ms = 0, int builders = 8) {
    SimulatedSourceSettings settings;
    static_cast<SimulatedConveyorSettings&>(settings) = testing::fault_test_conveyor_settings();
    const SimulatedConveyor conveyor(testing::fault_test_catalog(), parameters, settings);
    last_profile = conveyor.last_profile();
    set(faults, last_profile);
    auto source = std::make_unique<SimulatedSource>(testing::fault_test_catalog(), parameters,
                                                    settings, faults);
    const SimulatedSource* simulated = source.get();
    run = testing::run_faulty_cell(
        std::move(source), parameters,
        [simulated](std::int64_t first, std::int64_t last) {
          const PlacedSimPart* part = simulated->placed_part_scanned_in(first, last);
          return part ? part->name : std::string();
        },
        recognizer_delay_ms, builders);
  }
  void expect_survived(int lost = 0) const {
    EXPECT_TRUE(run.summary.source_error.empty()) << run.summary.source_error;
    EXPECT_EQ(run.summary.profiles + lost, last_profile + 1);
    EXPECT_EQ(run.wrong_ok(), 0);
    EXPECT_GE(run.correct(), 3) << run.describe();  // the fault hits one part at most
    EXPECT_EQ(run.summary.last_status.state, CellState::kIdle);
  }

  ScannerParameters parameters;
  FaultInjectionSettings faults;
  std::int64_t last_profile = 0;
  FaultCellRun run;
};

TEST(SourceFaultInjector, FrameGapsAreLostProfiles) {
  const SimulatedFaultRun fault([](FaultInjectionSettings& f, std::int64_t last) {
    testing::inject_once(f, InjectedFault::kFrameGap, last, 5);
  });
  fault.expect_survived(5);
  EXPECT_EQ(fault.run.total("profiles_lost"), 5);
  EXPECT_TRUE(fault.run.faulted_with("5 frames lost"));
}

TEST(SourceFaultInjector, ACameraStallTimesOutThenTheStreamGoesOn) {
  const SimulatedFaultRun fault([](FaultInjectionSettings& f, std::int64_t last) {
    testing::inject_once(f, InjectedFault::kCameraStall, last, 40);
  });
  fault.expect_survived(40);
  EXPECT_EQ(fault.run.total("camera_timeouts"), 40);
  EXPECT_EQ(fault.run.total("profiles_lost"), 40);
  EXPECT_TRUE(fault.run.faulted_with("camera"));
}

TEST(SourceFaultInjector, AnEncoderGlitchIsTwoEncoderErrors) {
  const SimulatedFaultRun fault([](FaultInjectionSettings& f, std::int64_t last) {
    testing::inject_once(f, InjectedFault::kEncoderGlitch, last, 1);
  });
  fault.expect_survived();
  EXPECT_EQ(fault.run.total("encoder_errors"), 2);
  EXPECT_EQ(fault.run.total("encoder_reversals"), 0);
  EXPECT_TRUE(fault.run.faulted_with("encoder errors"));
}

TEST(SourceFaultInjector, AReversalIsTwoDirectionChanges) {
  const SimulatedFaultRun fault([](FaultInjectionSettings& f, std::int64_t last) {
    testing::inject_once(f, InjectedFault::kEncoderReversal, last, 10);
  });
  fault.expect_survived();
  EXPECT_EQ(fault.run.total("encoder_reversals"), 2);
  EXPECT_EQ(fault.run.total("encoder_errors"), 10);  // each backward step
  EXPECT_TRUE(fault.run.faulted_with("encoder reversals"));
}

TEST(SourceFaultInjector, AStuckEncoderIsFoundInTheData) {
  const SimulatedFaultRun fault([](FaultInjectionSettings& f, std::int64_t last) {
    testing::inject_once(f, InjectedFault::kEncoderStuck, last, 20);
  });
  fault.expect_survived();
  EXPECT_EQ(fault.run.total("encoder_stalls"), 20);
  EXPECT_EQ(fault.run.total("encoder_errors"), 0);
  EXPECT_TRUE(fault.run.faulted_with("encoder stuck"));
}

TEST(SourceFaultInjector, LaserOffIsFoundInTheData) {
  const SimulatedFaultRun fault([](FaultInjectionSettings& f, std::int64_t last) {
    testing::inject_once(f, InjectedFault::kLaserOff, last, 30);
  });
  EXPECT_TRUE(fault.run.summary.source_error.empty());
  EXPECT_EQ(fault.run.summary.profiles, fault.last_profile + 1);
  EXPECT_EQ(fault.run.wrong_ok(), 0);
  EXPECT_GE(fault.run.correct(), 3) << fault.run.describe();
  EXPECT_EQ(fault.run.total("laser_off_profiles"), 30);
  EXPECT_TRUE(fault.run.faulted_with("laser off"));
}

TEST(SourceFaultInjector, AnOverloadedRecognizerDropsPartsAndTheCellGoesOn) {
  const SimulatedFaultRun fault([](FaultInjectionSettings&, std::int64_t) {},
                                /*recognizer_delay_ms=*/3000, /*builders=*/1);
  EXPECT_TRUE(fault.run.summary.source_error.empty());
  EXPECT_EQ(fault.run.summary.profiles, fault.last_profile + 1);
  // One builder, held by the recognizer for 3 s a part: the parts that start meanwhile are
  // dropped and counted, the rest recognized.
  EXPECT_GE(fault.run.total("parts_dropped"), 1);
  EXPECT_GE(fault.run.correct(), 1);
  EXPECT_EQ(fault.run.wrong_ok(), 0);
  EXPECT_TRUE(fault.run.faulted_with("parts dropped"));
}

}  // namespace
}  // namespace cosmos
