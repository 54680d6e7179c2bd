// The live source without live hardware: a missing camera fails start() with one line naming
// the device and its config key; a V4L2 camera played by the fake device (a synthetic stripe
// over a 20 mm step) and fake GPIO lines give profiles with the step's heights, the frame
// indices, time stamps and encoder counts, and the frames the camera lost; the encoder count
// is asked for at the frame's time stamp, a count that could not be settled is counted, and a
// corrupted frame is a lost profile as a dropped one is; the photo eye's transitions are
// counted and each announced result is one result_ready pulse.
#include "realtime/sources/hardware_source.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <deque>
#include <string>
#include <utility>
#include <vector>

#include "firmware_bridge/v4l2_camera.hpp"
#include "tests/firmware_bridge/fake_video_device.hpp"
#include "tests/firmware_bridge/synthetic_stripe.hpp"
#include "tests/realtime/source_stream.hpp"

namespace cosmos {
namespace {

constexpr double kStepHeightMm = 20.0;
constexpr double kStepHalfWidthMm = 30.0;

class FakeGpioLines final : public GpioLines {
 public:
  GpioStatus start() noexcept override {
    started = start_status == GpioStatus::kOk;
    return start_status;
  }
  GpioStatus stop() noexcept override {
    started = false;
    return GpioStatus::kOk;
  }
  // The belt moves one profile's worth of encoder counts between frames.
  GpioStatus poll_inputs(std::int64_t) noexcept override {
    ticks += 4;
    return GpioStatus::kTimeout;
  }
  EncoderReading encoder() const noexcept override {
    EncoderReading reading = encoder_faults;
    reading.ticks = ticks;
    return reading;
  }
  GpioStatus encoder_at(std::int64_t t_ns, std::int64_t wait_ns,
                        EncoderAtTime& at) noexcept override {
    poll_inputs(0);
    asked_t_ns = t_ns;
    asked_wait_ns = wait_ns;
    at = {ticks, settled};
    return GpioStatus::kOk;
  }
  bool part_present() const noexcept override { return false; }
  bool next_photo_eye_event(PhotoEyeEvent& event) noexcept override {
    if (photo_eye_events.empty()) return false;
    event = photo_eye_events.front();
    photo_eye_events.pop_front();
    return true;
  }
  GpioStatus set_output(GpioOutput output, bool active) noexcept override {
    if (output == GpioOutput::kLaserEnable) laser_on = active;
    if (output == GpioOutput::kResultReady) result_ready.emplace_back(ticks, active);
    return GpioStatus::kOk;
  }
  std::string_view last_error() const noexcept override { return error; }
  GpioInputHealth input_health() const noexcept override { return health; }

  GpioStatus start_status = GpioStatus::kOk;
  std::string error;
  bool started = false;
  bool laser_on = false;
  std::int64_t ticks = 1000;
  bool settled = true;  // what encoder_at() says of its count
  std::int64_t asked_t_ns = -1;
  std::int64_t asked_wait_ns = -1;
  EncoderReading encoder_faults;  // invalid transitions and reversals to report
  GpioInputHealth health;
  std::deque<PhotoEyeEvent> photo_eye_events;
  std::vector<std::pair<std::int64_t, bool>> result_ready;  // (ticks, level) per write
};

// Where the camera sees the laser line on a flat surface at z_mm in sensor column u: the
// line's points (x, 0, z) move monotonically across the columns with x, so bisect on x.
Eigen::Vector2d line_image(const TriangulationGeometry& geometry, double u_px, double z_mm,
                           double& x_mm) {
  double low = -400.0;
  double high = 400.0;
  Eigen::Vector2d uv;
  for (int i = 0; i < 80; ++i) {
    x_mm = 0.5 * (low + high);
    geometry.project_to_image({x_mm, 0.0, z_mm}, uv);
    (uv.x() < u_px ? low : high) = x_mm;
  }
  return uv;
}

// Stripe centre rows (within the ROI) of a 20 mm high, 60 mm wide step on the belt; NaN
// where neither the step's top nor the belt is seen in the column.
std::vector<double> step_stripe_rows(const TriangulationGeometry& geometry, int columns) {
  std::vector<double> rows(static_cast<std::size_t>(columns));
  for (int u = 0; u < columns; ++u) {
    double x_top = 0.0;
    double x_belt = 0.0;
    const Eigen::Vector2d top = line_image(geometry, u, kStepHeightMm, x_top);
    const Eigen::Vector2d belt = line_image(geometry, u, 0.0, x_belt);
    double row = std::nan("");
    if (std::abs(x_top) < kStepHalfWidthMm) {
      row = top.y();
    } else if (std::abs(x_belt) >= kStepHalfWidthMm) {
      row = belt.y();
    }
    rows[static_cast<std::size_t>(u)] = row - geometry.roi_row_offset_px;
  }
  return rows;
}

class HardwareSourceTest : public ::testing::Test {
 protected:
  void SetUp() override {
    geometry_ = scanner_triangulation_geometry(parameters_);
    config_.file = "hw.yaml";
    config_.camera.device = device_.path;
    config_.camera.width_px = parameters_.sensor_width_px;
    config_.camera.height_px = geometry_.roi_height_px;
    config_.camera.roi_top_px = geometry_.roi_row_offset_px;
    config_.frame_timeout_us = 10'000;
    frame_ = test::render_stripe<std::uint8_t>(step_stripe_rows(geometry_, config_.camera.width_px),
                                               config_.camera.height_px, {1.5, 200.0});
    device_.draw = [this](std::uint8_t* data, const v4l2_pix_format& format,
                          const test::FakeVideoDevice::Delivery&) {
      for (int r = 0; r < frame_.rows; ++r) {
        std::memcpy(data + static_cast<std::size_t>(r) * format.bytesperline, frame_.ptr(r),
                    static_cast<std::size_t>(frame_.cols));
      }
    };
  }

  ScannerParameters parameters_;
  TriangulationGeometry geometry_;
  HardwareConfig config_;
  test::FakeVideoDevice device_;
  cv::Mat frame_;
  FakeGpioLines gpio_;
};

TEST(HardwareSource, MissingCameraFailsWithOneLineNamingTheDeviceAndItsKey) {
  HardwareConfig config;
  config.file = "hw.yaml";
  config.camera.device = "/dev/video-cosmos-missing";
  HardwareSource source(config, ScannerParameters{});
  EXPECT_EQ(source.start(), SourceStatus::kError);
  EXPECT_EQ(source.last_error(),
            "/dev/video-cosmos-missing: open: No such file or directory "
            "(camera.device in hw.yaml)");
  Profile slot;
  source.reserve(slot);
  EXPECT_EQ(source.next(slot), SourceStatus::kError);
}

TEST_F(HardwareSourceTest, FramesBecomeProfilesOfTheStep) {
  V4l2Camera camera(config_.camera, device_);
  HardwareSource source(config_, parameters_, camera, gpio_);
  ASSERT_EQ(source.start(), SourceStatus::kOk) << source.last_error();
  EXPECT_TRUE(gpio_.laser_on);
  EXPECT_DOUBLE_EQ(source.mm_per_profile(), 0.4);
  device_.deliver(0, 7'000'100);
  device_.deliver(1, 7'000'500);
  device_.deliver(3, 7'001'300);  // frame 2 lost
  device_.time_out();

  device_.record_calls = false;  // the fake's call log allocates, the camera does not

  // The scripted frames, then the watchdog.
  const testing::SourceStream stream = testing::read_stream(source);
  EXPECT_EQ(stream.end, SourceStatus::kTimeout);
  EXPECT_EQ(stream.allocations_in_next, 0u);
  ASSERT_EQ(stream.profiles.size(), 3u);
  const std::vector<Profile>& profiles = stream.profiles;
  EXPECT_EQ(source.last_error(),
            "/dev/video0: poll: no frame within 10000 us (1 consecutive timeouts)");
  EXPECT_EQ(source.health().profiles_lost, 1u);
  EXPECT_EQ(source.health().camera_timeouts, 1u);
  EXPECT_EQ(profiles[0].seq, 0u);
  EXPECT_EQ(profiles[2].seq, 3u);
  EXPECT_EQ(profiles[0].encoder_ticks, 1004);
  EXPECT_EQ(profiles[2].encoder_ticks, 1012);
  EXPECT_EQ(profiles[1].t_us, 7'000'500);

  const Profile& profile = profiles[0];
  ASSERT_EQ(profile.width(), 640u);
  EXPECT_DOUBLE_EQ(profile.x0_mm, -127.8);
  EXPECT_DOUBLE_EQ(profile.dx_mm, 0.4);
  int top = 0;
  int belt = 0;
  for (std::size_t i = 0; i < profile.width(); ++i) {
    const double x = std::abs(profile.x_mm(i));
    SCOPED_TRACE(profile.x_mm(i));
    if (x < kStepHalfWidthMm - 2.0) {
      ASSERT_TRUE(profile.has_data(i));
      EXPECT_NEAR(profile.z_mm[i], kStepHeightMm, 0.05);
      ++top;
    } else if (x > kStepHalfWidthMm + 2.0 && x < 110.0) {
      ASSERT_TRUE(profile.has_data(i));
      EXPECT_NEAR(profile.z_mm[i], 0.0, 0.05);
      ++belt;
    }
  }
  EXPECT_EQ(top, 140);
  EXPECT_EQ(belt, 390);

  source.stop();
  EXPECT_FALSE(gpio_.laser_on);
  EXPECT_FALSE(gpio_.started);
  EXPECT_EQ(device_.open_fds, 0);
}

TEST_F(HardwareSourceTest, PhotoEyeTransitionsAreCountedAndResultsPulseResultReady) {
  V4l2Camera camera(config_.camera, device_);
  HardwareSource source(config_, parameters_, camera, gpio_);
  source.announce_result();  // before start: its part belonged to an earlier run
  ASSERT_EQ(source.start(), SourceStatus::kOk) << source.last_error();
  for (int k = 0; k < 6; ++k) device_.deliver(static_cast<std::uint32_t>(k), 7'000'000 + 400 * k);
  device_.time_out();
  gpio_.photo_eye_events = {{true, 6'000'000, 1002}, {false, 6'100'000, 1010}};
  source.announce_result();
  source.announce_result();  // two results at once: two separate pulses
  const testing::SourceStream stream = testing::read_stream(source);
  ASSERT_EQ(stream.profiles.size(), 6u);
  EXPECT_EQ(source.photo_eye().arrivals, 1u);
  EXPECT_EQ(source.photo_eye().departures, 1u);
  EXPECT_FALSE(source.photo_eye().last.present);
  EXPECT_EQ(source.photo_eye().last.encoder_ticks, 1010);
  EXPECT_EQ(source.result_pulses(), 2u);
  // High at frames 0 and 2 (encoder 1004, 1012), low at frames 1 and 3.
  const std::vector<std::pair<std::int64_t, bool>> expected = {
      {1004, true}, {1008, false}, {1012, true}, {1016, false}};
  EXPECT_EQ(gpio_.result_ready, expected);
  source.announce_result();
  Profile slot;
  source.reserve(slot);
  device_.deliver(6, 7'002'400);
  ASSERT_EQ(source.next(slot), SourceStatus::kOk);
  source.stop();  // a pulse in progress ends with the source
  ASSERT_EQ(gpio_.result_ready.size(), 6u);
  EXPECT_FALSE(gpio_.result_ready.back().second);
}

TEST_F(HardwareSourceTest, EncoderAndGpioFaultsShowInItsHealth) {
  V4l2Camera camera(config_.camera, device_);
  HardwareSource source(config_, parameters_, camera, gpio_);
  ASSERT_EQ(source.start(), SourceStatus::kOk) << source.last_error();
  gpio_.encoder_faults.invalid_transitions = 3;
  gpio_.encoder_faults.reversals = 2;
  gpio_.health = {.edges_lost = 5, .photo_eye_bounces = 7};
  const SourceHealth health = source.health();
  EXPECT_EQ(health.encoder_errors, 3u);
  EXPECT_EQ(health.encoder_reversals, 2u);
  EXPECT_EQ(health.gpio_edges_lost, 5u);
  EXPECT_EQ(health.photo_eye_bounces, 7u);
  EXPECT_EQ(health.camera_timeouts, 0u);
  EXPECT_EQ(health.profiles_lost, 0u);
}

TEST_F(HardwareSourceTest, CountsAreAskedAtTheFrameTimeAndCorruptedFramesAreLostProfiles) {
  config_.gpio.frame_edges_wait_us = 3'000;
  V4l2Camera camera(config_.camera, device_);
  HardwareSource source(config_, parameters_, camera, gpio_);
  ASSERT_EQ(source.start(), SourceStatus::kOk) << source.last_error();
  device_.deliver(0, 7'000'100);
  device_.deliver(1, 7'000'500, V4L2_BUF_FLAG_ERROR);
  device_.deliver(2, 7'000'900);
  gpio_.settled = false;
  Profile slot;
  source.reserve(slot);
  ASSERT_EQ(source.next(slot), SourceStatus::kOk) << source.last_error();
  EXPECT_EQ(gpio_.asked_t_ns, 7'000'100'000);
  EXPECT_EQ(gpio_.asked_wait_ns, 3'000'000);
  EXPECT_EQ(source.next(slot), SourceStatus::kTimeout);  // the corrupted frame, requeued
  ASSERT_EQ(source.next(slot), SourceStatus::kOk) << source.last_error();
  EXPECT_EQ(slot.seq, 2u);
  EXPECT_EQ(gpio_.asked_t_ns, 7'000'900'000);
  const SourceHealth health = source.health();
  EXPECT_EQ(camera.stats().corrupted_frames, 1u);
  EXPECT_EQ(camera.stats().dropped_frames, 0u);
  // The loss the source reports equals the gap in the profiles' seq (0, 2).
  EXPECT_EQ(health.profiles_lost, 1u);
  EXPECT_EQ(health.encoder_counts_unsettled, 2u);
}

TEST_F(HardwareSourceTest, GpioAndSensorMismatchFailuresNameTheirKeys) {
  V4l2Camera camera(config_.camera, device_);
  gpio_.start_status = GpioStatus::kError;
  gpio_.error = "gpiochip7: cannot open GPIO chip: No such file or directory";
  HardwareSource source(config_, parameters_, camera, gpio_);
  EXPECT_EQ(source.start(), SourceStatus::kError);
  EXPECT_EQ(source.last_error(),
            "gpiochip7: cannot open GPIO chip: No such file or directory (gpio.chip in hw.yaml)");
  EXPECT_EQ(device_.open_fds, 0) << "the camera must be closed again";

  config_.camera.roi_left_px = 200;
  HardwareSource misfit(config_, parameters_, camera, gpio_);
  EXPECT_EQ(misfit.start(), SourceStatus::kError);
  EXPECT_EQ(misfit.last_error(),
            "hw.yaml: camera.width: roi_left + width = 1480 exceeds scanner.sensor_width_px 1280");
}

}  // namespace
}  // namespace cosmos
