// Each fault the hardware twins inject at the devices, once, in a four-part run of the cell on
// the hardware path: what the camera and the decoder report and what the stream checker
// finds, counted on COSMOS_STATUS with FAULT while it lasts, the loop alive to the end, and
// no wrong OK pose.
#include <gtest/gtest.h>

#include <filesystem>
#include <memory>

#include "realtime/config/hardware_config.hpp"
#include "sim/twins/hardware_twin_source.hpp"
#include "tests/sim/fault_cell_run.hpp"

namespace cosmos {
namespace {

using testing::FaultCellRun;

struct TwinFaultRun {
  explicit TwinFaultRun(const std::function<void(FaultInjectionSettings&, std::int64_t)>& set,
                        std::int64_t frame_timeout_us = 100'000) {
    HardwareConfig config =
        read_hardware_config(std::filesystem::path(COSMOS_SOURCE_DIR) / "config/hardware-sim.yaml");
    config.frame_timeout_us = frame_timeout_us;
    auto conveyor = std::make_unique<SimulatedConveyor>(testing::fault_test_catalog(), parameters,
                                                        testing::fault_test_conveyor_settings());
    last_profile = conveyor->last_profile();
    set(faults, last_profile);
    auto source = std::make_unique<HardwareTwinSource>(config, std::move(conveyor),
                                                       SimulatedGpioSettings{}, faults);
    twins = source.get();
    run = testing::run_faulty_cell(
        std::move(source), parameters, [this](std::int64_t first, std::int64_t last) {
          const PlacedSimPart* part = twins->placed_part_scanned_in(first, last);
          return part ? part->name : std::string();
        });
  }
  void expect_survived(int lost = 0) const {
    EXPECT_TRUE(run.summary.source_error.empty()) << run.summary.source_error;
    EXPECT_EQ(run.summary.profiles + lost, last_profile + 1);
    EXPECT_EQ(run.wrong_ok(), 0);
    EXPECT_GE(run.correct(), 3) << run.describe();
  }

  ScannerParameters parameters;
  FaultInjectionSettings faults;
  std::int64_t last_profile = 0;
  HardwareTwinSource* twins = nullptr;  // owned by the run's checker, gone after it
  FaultCellRun run;
};

TEST(HardwareTwinFaults, LostFramesAreCountedOnce) {
  const TwinFaultRun fault([](FaultInjectionSettings& f, std::int64_t last) {
    testing::inject_once(f, InjectedFault::kFrameGap, last, 6);
  });
  fault.expect_survived(6);
  EXPECT_EQ(fault.run.total("profiles_lost"), 6);
  EXPECT_TRUE(fault.run.faulted_with("6 frames lost"));
}

TEST(HardwareTwinFaults, AStallLongerThanTheWatchdogTimesOutAndFaults) {
  // A 10 ms watchdog is 25 frames: a stall of 60 frames is two timeouts, and the frame after
  // the stall arrives within the third wait. (60 frames are 24 mm of belt, less than the gap
  // between parts: the stall must not join two parts.)
  const TwinFaultRun fault(
      [](FaultInjectionSettings& f, std::int64_t last) {
        testing::inject_once(f, InjectedFault::kCameraStall, last, 60);
      },
      10'000);
  fault.expect_survived(60);
  EXPECT_EQ(fault.run.total("camera_timeouts"), 2);
  EXPECT_EQ(fault.run.total("profiles_lost"), 60);
  EXPECT_TRUE(fault.run.faulted_with("camera"));
}

TEST(HardwareTwinFaults, AMissedEncoderEdgeIsAnEncoderError) {
  const TwinFaultRun fault([](FaultInjectionSettings& f, std::int64_t last) {
    testing::inject_once(f, InjectedFault::kEncoderGlitch, last, 1);
  });
  fault.expect_survived();
  EXPECT_GE(fault.run.total("encoder_errors"), 1);
  EXPECT_TRUE(fault.run.faulted_with("encoder errors"));
}

TEST(HardwareTwinFaults, AReversalIsCountedByTheDecoder) {
  const TwinFaultRun fault([](FaultInjectionSettings& f, std::int64_t last) {
    testing::inject_once(f, InjectedFault::kEncoderReversal, last, 5);
  });
  fault.expect_survived();
  EXPECT_EQ(fault.run.total("encoder_reversals"), 2);
  EXPECT_TRUE(fault.run.faulted_with("encoder reversals"));
}

TEST(HardwareTwinFaults, AStuckEncoderIsFoundInTheData) {
  const TwinFaultRun fault([](FaultInjectionSettings& f, std::int64_t last) {
    testing::inject_once(f, InjectedFault::kEncoderStuck, last, 20);
  });
  fault.expect_survived();
  EXPECT_EQ(fault.run.total("encoder_stalls"), 20);
  EXPECT_EQ(fault.run.total("encoder_errors"), 0);
  EXPECT_TRUE(fault.run.faulted_with("encoder stuck"));
}

TEST(HardwareTwinFaults, LaserOffIsFoundInTheFrames) {
  const TwinFaultRun fault([](FaultInjectionSettings& f, std::int64_t last) {
    testing::inject_once(f, InjectedFault::kLaserOff, last, 30);
  });
  EXPECT_TRUE(fault.run.summary.source_error.empty());
  EXPECT_EQ(fault.run.wrong_ok(), 0);
  EXPECT_GE(fault.run.correct(), 3) << fault.run.describe();
  EXPECT_EQ(fault.run.total("laser_off_profiles"), 30);
  EXPECT_TRUE(fault.run.faulted_with("laser off"));
}

TEST(HardwareTwinFaults, PhotoEyeBounceIsRejectedAndCounted) {
  const TwinFaultRun fault([](FaultInjectionSettings& f, std::int64_t last) {
    // Every edge of the middle third bounces.
    testing::inject_once(f, InjectedFault::kPhotoEyeBounce, last, static_cast<int>((last + 1) / 3));
  });
  fault.expect_survived();
  EXPECT_GE(fault.run.total("photo_eye_bounces"), 1);
  EXPECT_TRUE(fault.run.faulted_with("photo-eye bounces"));
}

}  // namespace
}  // namespace cosmos
