// The simulated camera: frames in sequence on the belt clock, byte for byte the simulator's
// camera-mode frames, the stripe where the ray caster predicts it in the config's ROI and
// pixel format, the lifecycle's order enforced, and next_frame without allocation.
#include "sim/twins/simulated_camera.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/core.hpp>
#include <string>

#include "firmware_bridge/frame_view_mat.hpp"
#include "firmware_bridge/profile_resampling.hpp"
#include "sim/simulated_scanner.hpp"
#include "tests/common/allocation_counter.hpp"
#include "tests/sim/twins/twin_test_conveyor.hpp"

namespace cosmos {
namespace {

using testing::simulator_camera;
using testing::twin_test_conveyor;

// The frame of profile k as SimulatedScanner's camera mode draws it.
cv::Mat camera_mode_frame(const SimulatedConveyor& conveyor, std::int64_t k) {
  SimulatedScanner scanner(conveyor.scene(), conveyor.parameters(), ScanMode::kCamera);
  Profile profile;
  scanner.reserve(profile);
  scanner.acquire(k, profile);
  return scanner.last_frame().clone();
}

std::int64_t middle_profile(const PlacedSimPart& part) {
  return (part.first_profile + part.last_profile) / 2;
}

// Takes frames up to frame k, giving back every earlier one; frame k stays lent.
void take_frames_up_to(SimulatedCamera& camera, std::uint64_t k, FrameView& frame) {
  for (;;) {
    ASSERT_EQ(camera.next_frame(1000, frame), CameraStatus::kOk) << camera.last_error();
    if (frame.frame_index == k) return;
    ASSERT_EQ(camera.release_frame(frame), CameraStatus::kOk);
  }
}

struct StripeAgreement {
  int predicted_columns = 0;  // columns the line's drawn segments cross
  int found_columns = 0;      // of those, with an extracted stripe
  int raised_columns = 0;     // found ones on a part (well above the belt's row)
  double max_error_px = 0.0;  // extracted vs predicted row
  double mean_error_px = 0.0;
};

// The stripe extracted from `frame` against the laser line's prediction (sensor rows of the
// segments joining consecutive drawn samples on one surface, as the renderer draws them).
StripeAgreement compare_stripe(const FrameView& frame, const LaserLine& line,
                               const StripeExtractionParameters& extraction) {
  LaserStripeExtractor extractor(extraction);
  StripePeaks peaks;
  extractor.reserve(frame.width_px, peaks);
  EXPECT_EQ(extractor.extract(frame_as_mat(frame), frame_roi(frame), peaks),
            StripeExtractionStatus::kOk);
  const double max_jump_mm = ProfileResamplingParameters{}.max_z_jump_mm;
  const double belt_row_px = line.v_px[0];  // sample 0 lies on the belt in these scenes
  StripeAgreement agreement;
  for (int i = 0; i + 1 < line.width(); ++i) {
    const auto s = static_cast<std::size_t>(i);
    const bool drawn = line.state[s] == LaserSampleState::kMeasured &&
                       line.state[s + 1] == LaserSampleState::kMeasured &&
                       std::abs(line.z_mm[s + 1] - line.z_mm[s]) <= max_jump_mm;
    if (!drawn) continue;
    const double ua = line.u_px[s];
    const double ub = line.u_px[s + 1];
    for (int u = static_cast<int>(std::ceil(std::min(ua, ub))); u < std::max(ua, ub); ++u) {
      const int column = u - frame.roi_left_px;
      if (column < 0 || column >= frame.width_px) continue;
      const double t = (u - ua) / (ub - ua);
      const double predicted = line.v_px[s] + t * (line.v_px[s + 1] - line.v_px[s]);
      ++agreement.predicted_columns;
      const float found = peaks.row_px[static_cast<std::size_t>(column)];
      if (std::isnan(found)) continue;
      ++agreement.found_columns;
      agreement.raised_columns += predicted < belt_row_px - 10.0 ? 1 : 0;
      const double error_px = std::abs(found - predicted);
      agreement.max_error_px = std::max(agreement.max_error_px, error_px);
      agreement.mean_error_px += error_px;
    }
  }
  agreement.mean_error_px /= std::max(agreement.found_columns, 1);
  return agreement;
}

StripeExtractionParameters drawing_extraction(const ScannerParameters& parameters, int bit_depth) {
  ScannerParameters drawing = parameters;
  drawing.camera.bit_depth = bit_depth;
  return CameraFrameRenderer(drawing, scanner_triangulation_geometry(drawing))
      .extraction_parameters();
}

TEST(SimulatedCamera, FramesAreCameraModesFramesInSequenceOnTheBeltClock) {
  const ScannerParameters parameters;
  const auto conveyor = twin_test_conveyor(parameters);
  SimulatedBeltClock clock(parameters);
  SimulatedCamera camera(*conveyor, clock, simulator_camera(parameters));
  ASSERT_EQ(camera.start(), CameraStatus::kOk) << camera.last_error();
  const std::int64_t compared[] = {0, middle_profile(conveyor->placed_parts()[0]),
                                   middle_profile(conveyor->placed_parts()[1]),
                                   conveyor->placed_parts()[2].last_profile};
  int frames_compared = 0;
  FrameView frame;
  for (std::int64_t k = 0; k <= conveyor->last_profile(); ++k) {
    ASSERT_EQ(camera.next_frame(1000, frame), CameraStatus::kOk) << camera.last_error();
    ASSERT_EQ(frame.frame_index, static_cast<std::uint64_t>(k));
    ASSERT_EQ(frame.dropped_before, 0u);
    ASSERT_EQ(frame.t_us, parameters.time_us_of_profile(k));
    ASSERT_EQ(clock.frame(), k);
    if (std::find(std::begin(compared), std::end(compared), k) != std::end(compared)) {
      EXPECT_EQ(frame.format, PixelFormat::kGrey8);
      EXPECT_EQ(frame.width_px, 1280);
      EXPECT_EQ(frame.height_px, 512);
      EXPECT_EQ(frame.roi_top_px, 51);
      EXPECT_EQ(frame.roi_left_px, 0);
      EXPECT_TRUE(frame.t_is_start_of_exposure);
      const cv::Mat expected = camera_mode_frame(*conveyor, k);
      EXPECT_EQ(cv::norm(frame_as_mat(frame), expected, cv::NORM_INF), 0.0) << "frame " << k;
      ++frames_compared;
    }
    ASSERT_EQ(camera.release_frame(frame), CameraStatus::kOk);
  }
  EXPECT_EQ(frames_compared, 4);
  EXPECT_EQ(camera.next_frame(1000, frame), CameraStatus::kEndOfStream);
  EXPECT_EQ(camera.next_frame(1000, frame), CameraStatus::kEndOfStream);
  EXPECT_EQ(camera.stats().frames, static_cast<std::uint64_t>(conveyor->last_profile() + 1));
  EXPECT_EQ(camera.stats().errors, 0u);
}

TEST(SimulatedCamera, FramesDeliveredInBurstsRunTheBeltAheadAndKeepTheirExposureTimes) {
  const ScannerParameters parameters;
  const auto conveyor = twin_test_conveyor(parameters);
  SimulatedBeltClock clock(parameters);
  SimulatedCamera camera(*conveyor, clock, simulator_camera(parameters));
  camera.deliver_in_bursts(4);
  ASSERT_EQ(camera.start(), CameraStatus::kOk) << camera.last_error();
  FrameView frame;
  for (std::int64_t k = 0; k < 12; ++k) {
    ASSERT_EQ(camera.next_frame(1000, frame), CameraStatus::kOk) << camera.last_error();
    ASSERT_EQ(frame.frame_index, static_cast<std::uint64_t>(k));
    EXPECT_EQ(frame.t_us, parameters.time_us_of_profile(k));
    EXPECT_EQ(clock.frame(), k / 4 * 4 + 3) << "frame " << k;  // the burst's last exposure
    ASSERT_EQ(camera.release_frame(frame), CameraStatus::kOk);
  }
}

TEST(SimulatedCamera, StripeLiesWhereTheSimulatorPredictsIt) {
  const ScannerParameters parameters;
  const auto conveyor = twin_test_conveyor(parameters);
  SimulatedBeltClock clock(parameters);
  SimulatedCamera camera(*conveyor, clock, simulator_camera(parameters));
  ASSERT_EQ(camera.start(), CameraStatus::kOk);
  const StripeExtractionParameters extraction = drawing_extraction(parameters, 8);
  FrameView frame;
  for (const PlacedSimPart& part : conveyor->placed_parts()) {
    take_frames_up_to(camera, static_cast<std::uint64_t>(middle_profile(part)), frame);
    const StripeAgreement agreement = compare_stripe(frame, camera.last_line(), extraction);
    SCOPED_TRACE(part.name);
    EXPECT_GT(agreement.predicted_columns, 1100);
    EXPECT_GE(agreement.found_columns, agreement.predicted_columns - 10);
    EXPECT_GT(agreement.raised_columns, 80);
    EXPECT_LT(agreement.max_error_px, 0.35);
    EXPECT_LT(agreement.mean_error_px, 0.1);
    ASSERT_EQ(camera.release_frame(frame), CameraStatus::kOk);
  }
}

TEST(SimulatedCamera, DeliversTheConfigsRoiAndPixelFormat) {
  const ScannerParameters parameters;
  const auto conveyor = twin_test_conveyor(parameters);
  SimulatedBeltClock clock(parameters);
  CameraConfig config = simulator_camera(parameters);
  config.pixel_format = PixelFormat::kY12;
  config.roi_left_px = 100;
  config.width_px = 1000;
  config.roi_top_px += 64;
  config.height_px = 448;  // down to the end of the measuring range: the belt's line is in
  SimulatedCamera camera(*conveyor, clock, config);
  ASSERT_EQ(camera.start(), CameraStatus::kOk) << camera.last_error();
  FrameView frame;
  take_frames_up_to(camera, static_cast<std::uint64_t>(middle_profile(conveyor->placed_parts()[1])),
                    frame);
  EXPECT_EQ(frame.format, PixelFormat::kY12);
  EXPECT_EQ(frame.bytes_per_pixel(), 2);
  EXPECT_EQ(frame.width_px, 1000);
  EXPECT_EQ(frame.height_px, 448);
  EXPECT_EQ(frame.roi_left_px, 100);
  EXPECT_EQ(frame.roi_top_px, 51 + 64);
  double max_level = 0.0;
  cv::minMaxLoc(frame_as_mat(frame), nullptr, &max_level);
  EXPECT_GT(max_level, 255.0);  // drawn at 12 bits, not 8
  EXPECT_LE(max_level, 4095.0);
  const StripeAgreement agreement =
      compare_stripe(frame, camera.last_line(), drawing_extraction(parameters, 12));
  EXPECT_GT(agreement.predicted_columns, 950);
  EXPECT_GE(agreement.found_columns, agreement.predicted_columns - 10);
  EXPECT_LT(agreement.max_error_px, 0.35);
  EXPECT_LT(agreement.mean_error_px, 0.1);
}

TEST(SimulatedCamera, RoiOutsideTheSimulatedSensorIsRefusedInOneLine) {
  const ScannerParameters parameters;
  const auto conveyor = twin_test_conveyor(parameters);
  SimulatedBeltClock clock(parameters);
  CameraConfig rows = simulator_camera(parameters);
  rows.roi_top_px = 0;
  SimulatedCamera above(*conveyor, clock, rows);
  EXPECT_EQ(above.start(), CameraStatus::kError);
  EXPECT_EQ(above.last_error(),
            "simulated camera: camera.roi_top, camera.height: rows [0, 512) leave the simulated "
            "scanner's measuring range, sensor rows [51, 563) (roi_top 51, height 512 cover it)");
  CameraConfig columns = simulator_camera(parameters);
  columns.roi_left_px = 8;
  SimulatedCamera wide(*conveyor, clock, columns);
  EXPECT_EQ(wide.start(), CameraStatus::kError);
  EXPECT_EQ(wide.last_error(),
            "simulated camera: camera.width: roi_left + width = 1288 exceeds the sensor's 1280 "
            "columns");
}

TEST(SimulatedCamera, LifecycleStepsOutOfOrderAreRefused) {
  const ScannerParameters parameters;
  const auto conveyor = twin_test_conveyor(parameters);
  SimulatedBeltClock clock(parameters);
  CameraConfig config = simulator_camera(parameters);
  config.buffer_count = 3;
  SimulatedCamera camera(*conveyor, clock, config);
  FrameView frame;
  EXPECT_EQ(camera.next_frame(1000, frame), CameraStatus::kWrongState);
  EXPECT_EQ(camera.last_error(), "simulated camera: next_frame: camera not started");
  EXPECT_EQ(camera.release_frame(frame), CameraStatus::kWrongState);
  EXPECT_EQ(camera.set_exposure_us(300), CameraStatus::kWrongState);
  EXPECT_EQ(camera.set_gain(2), CameraStatus::kWrongState);

  ASSERT_EQ(camera.start(), CameraStatus::kOk);
  EXPECT_EQ(camera.start(), CameraStatus::kWrongState);
  EXPECT_EQ(camera.rewind(), CameraStatus::kWrongState);
  EXPECT_EQ(camera.set_exposure_us(300), CameraStatus::kOk);
  EXPECT_EQ(camera.exposure_us(), 300);
  FrameView held[3];
  for (FrameView& view : held) ASSERT_EQ(camera.next_frame(1000, view), CameraStatus::kOk);
  const cv::Mat first_frame = frame_as_mat(held[0]).clone();
  EXPECT_EQ(camera.lent_frames(), 3);
  EXPECT_EQ(camera.next_frame(1000, frame), CameraStatus::kError);
  EXPECT_EQ(camera.last_error(),
            "simulated camera: next_frame: all 3 buffers are held by the caller, release_frame "
            "one first");
  ASSERT_EQ(camera.release_frame(held[1]), CameraStatus::kOk);
  EXPECT_EQ(camera.release_frame(held[1]), CameraStatus::kError);
  EXPECT_EQ(camera.last_error(), "simulated camera: release_frame: buffer 1 is not lent out");
  ASSERT_EQ(camera.next_frame(1000, frame), CameraStatus::kOk);
  EXPECT_EQ(frame.frame_index, 3u);
  EXPECT_EQ(frame.buffer_index, 1);  // the buffer just given back

  // Stopping takes every frame back; a restart goes on down the belt.
  ASSERT_EQ(camera.stop(), CameraStatus::kOk);
  EXPECT_EQ(camera.lent_frames(), 0);
  ASSERT_EQ(camera.start(), CameraStatus::kOk);
  ASSERT_EQ(camera.next_frame(1000, frame), CameraStatus::kOk);
  EXPECT_EQ(frame.frame_index, 4u);
  EXPECT_EQ(frame.t_us, parameters.time_us_of_profile(4));
  // Rewound, it replays the same frames.
  ASSERT_EQ(camera.stop(), CameraStatus::kOk);
  ASSERT_EQ(camera.rewind(), CameraStatus::kOk);
  EXPECT_EQ(clock.frame(), 0);
  ASSERT_EQ(camera.start(), CameraStatus::kOk);
  ASSERT_EQ(camera.next_frame(1000, frame), CameraStatus::kOk);
  EXPECT_EQ(frame.frame_index, 0u);
  EXPECT_EQ(cv::norm(frame_as_mat(frame), first_frame, cv::NORM_INF), 0.0);
}

TEST(SimulatedCamera, NextFrameAllocatesNothing) {
  const ScannerParameters parameters;
  const auto conveyor = twin_test_conveyor(parameters);
  SimulatedBeltClock clock(parameters);
  SimulatedCamera camera(*conveyor, clock, simulator_camera(parameters));
  ASSERT_EQ(camera.start(), CameraStatus::kOk);
  std::uint64_t allocations = 0;
  FrameView frame;
  // Across the first part and the belt after it.
  const std::int64_t last = conveyor->placed_parts()[0].last_profile + 20;
  for (std::int64_t k = 0; k <= last; ++k) {
    const std::uint64_t before = test::allocations_on_this_thread();
    ASSERT_EQ(camera.next_frame(1000, frame), CameraStatus::kOk);
    ASSERT_EQ(camera.release_frame(frame), CameraStatus::kOk);
    allocations += test::allocations_on_this_thread() - before;
  }
  EXPECT_EQ(allocations, 0u);
}

}  // namespace
}  // namespace cosmos
