// Frames for the calibrations taken from the cell's own devices: the hardware twins' camera
// and encoder (whose laser follows laser_enable), and a camera that stays silent.
#include "calibration/frame_capture.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <opencv2/core.hpp>

#include "calibration/frame_list.hpp"
#include "core/input_error.hpp"
#include "sim/twins/hardware_twin_source.hpp"
#include "tests/apps/cosmos_cli.hpp"
#include "tests/sim/twins/twin_test_conveyor.hpp"

namespace cosmos {
namespace {

namespace fs = std::filesystem;

HardwareConfig twin_config() {
  HardwareConfig config;
  config.camera = testing::simulator_camera();
  config.gpio = testing::simulated_gpio();
  return config;
}

int lit_pixels(const cv::Mat& image) { return cv::countNonZero(image > 128); }

class FrameCaptureOnTwins : public ::testing::Test {
 protected:
  void SetUp() override { ASSERT_EQ(twins_.start(), SourceStatus::kOk); }
  std::vector<StripeFrame> capture(FrameCaptureSettings settings) {
    settings.device = "simulated";
    return capture_frames(twins_.hardware().camera(), twins_.hardware().gpio(), settings);
  }
  HardwareTwinSource twins_{twin_config(), testing::twin_test_conveyor(), SimulatedGpioSettings{},
                            FaultInjectionSettings{}};
};

TEST_F(FrameCaptureOnTwins, BoardFramesAreDarkAndStripeFramesLit) {
  FrameCaptureSettings settings;
  settings.frames = 3;
  settings.laser_on = false;
  const std::vector<StripeFrame> dark = capture(settings);
  settings.laser_on = true;
  const std::vector<StripeFrame> lit = capture(settings);
  ASSERT_EQ(dark.size(), 3U);
  ASSERT_EQ(lit.size(), 3U);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(lit_pixels(dark[i].image), 0) << i;
    EXPECT_GT(lit_pixels(lit[i].image), 1000) << i;  // the stripe across 1280 columns
    EXPECT_EQ(lit[i].image.rows, twin_config().camera.height_px);
    EXPECT_EQ(lit[i].roi_top_px, twin_config().camera.roi_top_px);
  }
  EXPECT_TRUE(twins_.gpio().output_active(GpioOutput::kLaserEnable));
}

TEST_F(FrameCaptureOnTwins, FramesAreKeptEveryTicksAfterTheSettlingOnes) {
  FrameCaptureSettings settings;
  settings.frames = 6;
  settings.laser_on = true;
  settings.settle_frames = 3;
  settings.every_ticks = 20;  // five frames of 4 ticks
  const std::vector<StripeFrame> frames = capture(settings);
  ASSERT_EQ(frames.size(), 6U);
  // Frame k arrives with the count 4 k; frames 0 to 2 settle.
  EXPECT_EQ(frames.front().encoder_ticks, 12);
  for (std::size_t i = 1; i < frames.size(); ++i)
    EXPECT_EQ(frames[i].encoder_ticks - frames[i - 1].encoder_ticks, 20) << i;
}

TEST_F(FrameCaptureOnTwins, ACameraThatEndsIsAnErrorNamingTheDevice) {
  FrameCaptureSettings settings;
  settings.frames = 1'000'000;
  try {
    capture(settings);
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("simulated: capture: the camera ended after"),
              std::string::npos)
        << error.what();
  }
}

// A camera whose watchdog always expires.
class SilentCamera final : public Camera {
 public:
  CameraStatus start() noexcept override { return CameraStatus::kOk; }
  CameraStatus stop() noexcept override { return CameraStatus::kOk; }
  CameraStatus next_frame(std::int64_t, FrameView&) noexcept override {
    ++waits;
    return CameraStatus::kTimeout;
  }
  CameraStatus release_frame(const FrameView&) noexcept override { return CameraStatus::kOk; }
  CameraStatus set_exposure_us(int) noexcept override { return CameraStatus::kOk; }
  CameraStatus set_gain(int) noexcept override { return CameraStatus::kOk; }
  CameraStats stats() const noexcept override { return {}; }
  std::string_view last_error() const noexcept override { return {}; }
  int waits = 0;
};

TEST(FrameCapture, ASilentCameraFailsAfterItsWatchdogsInOneLine) {
  SimulatedBeltClock clock(ScannerParameters{});
  const std::unique_ptr<SimulatedConveyor> conveyor = testing::twin_test_conveyor();
  SimulatedGpioLines gpio(*conveyor, clock, testing::simulated_gpio());
  ASSERT_EQ(gpio.start(), GpioStatus::kOk);
  SilentCamera camera;
  FrameCaptureSettings settings;
  settings.device = "/dev/video3";
  settings.max_consecutive_timeouts = 7;
  settings.frame_timeout_us = 50'000;
  try {
    capture_frames(camera, gpio, settings);
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_STREQ(error.what(), "/dev/video3: capture: no frame within 7 watchdogs of 50 ms");
  }
  EXPECT_EQ(camera.waits, 7);
}

TEST(CalibrateCaptureCommand, WritesAFrameDirectoryTheCalibrationsReadAndNeverOverwritesIt) {
  const fs::path dir = fs::path(::testing::TempDir()) / "calibrate_capture_frames";
  fs::remove_all(dir);
  const std::string command = "calibrate capture frames --frames 5 --every-mm 2 --hardware '" +
                              (fs::path(COSMOS_SOURCE_DIR) / "config/hardware-sim.yaml").string() +
                              "' --config '" +
                              (fs::path(COSMOS_SOURCE_DIR) / "config/cell.yaml").string() +
                              "' --out '" + (dir / "belt").string() + "'";
  const testing::CliRun first = testing::run_cosmos(command, dir.parent_path());
  ASSERT_EQ(first.exit_code, 0) << first.err;
  const std::vector<StripeFrame> frames = read_frame_list(dir / "belt");
  ASSERT_EQ(frames.size(), 5U);
  for (std::size_t i = 1; i < frames.size(); ++i)
    EXPECT_EQ(frames[i].encoder_ticks - frames[i - 1].encoder_ticks, 20) << i;  // 0.1 mm ticks
  EXPECT_GT(lit_pixels(frames.front().image), 1000);
  const testing::CliRun again = testing::run_cosmos(command, dir.parent_path());
  testing::expect_one_line_failure(
      again, "frames.csv: already there (a frame directory holds one capture; nothing written)");
}

}  // namespace
}  // namespace cosmos
