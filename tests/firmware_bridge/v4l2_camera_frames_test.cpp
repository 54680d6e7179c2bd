// V4l2Camera's acquisition path against the fake device: lent frames, sequence gaps,
// watchdog timeouts, corrupted frames, restarts, controls, and the frame feeding the stripe
// extractor.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string_view>
#include <vector>

#include "firmware_bridge/frame_view_mat.hpp"
#include "firmware_bridge/laser_stripe_extraction.hpp"
#include "firmware_bridge/v4l2_camera.hpp"
#include "tests/firmware_bridge/fake_video_device.hpp"

namespace cosmos {
namespace {

using test::FakeVideoDevice;
using test::small_config;

bool one_line(std::string_view text) {
  return !text.empty() && text.find('\n') == std::string_view::npos;
}

TEST(V4l2Camera, FramesAreLentWithTimestampsAndDroppedFramesCounted) {
  FakeVideoDevice device;
  device.row_padding_bytes = 16;
  V4l2Camera camera(small_config(PixelFormat::kY16), device);
  ASSERT_EQ(camera.start(), CameraStatus::kOk) << camera.last_error();
  device.deliver(0, 5'000'000'100);
  device.deliver(1, 5'000'000'300, V4L2_BUF_FLAG_TSTAMP_SRC_SOE);
  device.deliver(4, 5'000'000'900);  // 2 and 3 lost
  device.deliver(5, 5'000'001'100);

  std::vector<std::uint64_t> indices;
  for (int i = 0; i < 4; ++i) {
    FrameView frame;
    ASSERT_EQ(camera.next_frame(10'000, frame), CameraStatus::kOk) << camera.last_error();
    EXPECT_EQ(frame.width_px, 64);
    EXPECT_EQ(frame.height_px, 32);
    EXPECT_EQ(frame.bytes_per_line, 64 * 2 + 16);
    EXPECT_EQ(frame.bytes_per_pixel(), 2);
    EXPECT_NE(frame.data, nullptr);
    if (i == 1) {
      EXPECT_EQ(frame.t_us, 5'000'000'300);
      EXPECT_TRUE(frame.t_is_start_of_exposure);
    }
    if (i == 2) {
      EXPECT_EQ(frame.dropped_before, 2u);
    }
    indices.push_back(frame.frame_index);
    ASSERT_EQ(camera.release_frame(frame), CameraStatus::kOk);
  }
  EXPECT_EQ(indices, (std::vector<std::uint64_t>{0, 1, 4, 5}));
  EXPECT_EQ(camera.stats().frames, 4u);
  EXPECT_EQ(camera.stats().dropped_frames, 2u);
  EXPECT_EQ(device.queued(), 4u);
}

TEST(V4l2Camera, WatchdogTimeoutIsReportedAndCounted) {
  FakeVideoDevice device;
  V4l2Camera camera(small_config(), device);
  ASSERT_EQ(camera.start(), CameraStatus::kOk);
  device.time_out();
  device.time_out();
  device.deliver(0, 1000);
  FrameView frame;
  EXPECT_EQ(camera.next_frame(2500, frame), CameraStatus::kTimeout);
  EXPECT_EQ(camera.next_frame(2500, frame), CameraStatus::kTimeout);
  EXPECT_EQ(camera.last_error(),
            "/dev/video0: poll: no frame within 2500 us (2 consecutive timeouts)");
  EXPECT_EQ(camera.stats().timeouts, 2u);
  EXPECT_EQ(camera.stats().consecutive_timeouts, 2u);
  ASSERT_EQ(camera.next_frame(2500, frame), CameraStatus::kOk);
  EXPECT_EQ(camera.stats().consecutive_timeouts, 0u);
  EXPECT_EQ(camera.stats().timeouts, 2u);
}

TEST(V4l2Camera, HoldingEveryBufferIsAnErrorNotAHang) {
  FakeVideoDevice device;
  CameraConfig config = small_config();
  config.buffer_count = 2;
  V4l2Camera camera(config, device);
  ASSERT_EQ(camera.start(), CameraStatus::kOk);
  for (std::uint32_t s = 0; s < 3; ++s) device.deliver(s, 100 * s);
  FrameView first, second, third;
  ASSERT_EQ(camera.next_frame(1000, first), CameraStatus::kOk);
  ASSERT_EQ(camera.next_frame(1000, second), CameraStatus::kOk);
  EXPECT_NE(first.buffer_index, second.buffer_index);
  EXPECT_EQ(camera.next_frame(1000, third), CameraStatus::kError);
  EXPECT_EQ(
      camera.last_error(),
      "/dev/video0: next_frame: all 2 buffers are held by the caller, release_frame one first");
  ASSERT_EQ(camera.release_frame(first), CameraStatus::kOk);
  EXPECT_EQ(camera.release_frame(first), CameraStatus::kError);  // not lent any more
  EXPECT_TRUE(one_line(camera.last_error()));
  EXPECT_EQ(camera.next_frame(1000, third), CameraStatus::kOk);
}

TEST(V4l2Camera, CorruptedFrameIsRequeuedUnseenButNotCountedDropped) {
  FakeVideoDevice device;
  V4l2Camera camera(small_config(), device);
  ASSERT_EQ(camera.start(), CameraStatus::kOk);
  device.deliver(7, 100);
  device.deliver(8, 200, V4L2_BUF_FLAG_ERROR);
  device.deliver(9, 300);
  FrameView frame;
  ASSERT_EQ(camera.next_frame(1000, frame), CameraStatus::kOk);
  ASSERT_EQ(camera.release_frame(frame), CameraStatus::kOk);
  EXPECT_EQ(camera.next_frame(1000, frame), CameraStatus::kNoFrame);
  ASSERT_EQ(camera.next_frame(1000, frame), CameraStatus::kOk);
  EXPECT_EQ(frame.frame_index, 2u);
  EXPECT_EQ(frame.dropped_before, 0u);
  EXPECT_EQ(camera.stats().corrupted_frames, 1u);
  EXPECT_EQ(camera.stats().dropped_frames, 0u);
  EXPECT_EQ(device.queued(), 3u);
}

TEST(V4l2Camera, RestartAfterStreamOffContinuesTheFrameIndex) {
  FakeVideoDevice device;
  V4l2Camera camera(small_config(), device);
  ASSERT_EQ(camera.start(), CameraStatus::kOk);
  device.deliver(0, 100);
  device.deliver(1, 200);
  FrameView frame;
  for (int i = 0; i < 2; ++i) {
    ASSERT_EQ(camera.next_frame(1000, frame), CameraStatus::kOk);
    ASSERT_EQ(camera.release_frame(frame), CameraStatus::kOk);
  }
  ASSERT_EQ(camera.stream_off(), CameraStatus::kOk);
  EXPECT_EQ(camera.release_frame(frame), CameraStatus::kWrongState);
  ASSERT_EQ(camera.stream_on(), CameraStatus::kOk);
  EXPECT_EQ(device.queued(), 4u);
  device.deliver(0, 900);  // the driver restarts its counter at STREAMON
  ASSERT_EQ(camera.next_frame(1000, frame), CameraStatus::kOk);
  EXPECT_EQ(frame.frame_index, 2u);
  EXPECT_EQ(camera.stats().dropped_frames, 0u);
  EXPECT_EQ(camera.stats().sequence_resets, 0u);
}

TEST(V4l2Camera, ExposureIsSetManuallyInHundredMicrosecondUnits) {
  FakeVideoDevice device;
  CameraConfig config = small_config();
  config.exposure_us = 1240;
  config.gain = 7;
  V4l2Camera camera(config, device);
  ASSERT_EQ(camera.start(), CameraStatus::kOk);
  EXPECT_EQ(device.control_values[V4L2_CID_EXPOSURE_AUTO], V4L2_EXPOSURE_MANUAL);
  EXPECT_EQ(device.control_values[V4L2_CID_EXPOSURE_ABSOLUTE], 12);
  EXPECT_EQ(device.control_values[V4L2_CID_GAIN], 7);
  EXPECT_EQ(camera.applied_exposure_us(), 1200);
  ASSERT_EQ(camera.set_exposure_us(30), CameraStatus::kOk);  // while streaming
  EXPECT_EQ(device.control_values[V4L2_CID_EXPOSURE_ABSOLUTE], 1);

  device.controls.erase(V4L2_CID_GAIN);
  EXPECT_EQ(camera.set_gain(3), CameraStatus::kError);
  EXPECT_EQ(camera.last_error(), "/dev/video0: VIDIOC_S_CTRL gain=3: Invalid argument");
}

// The lent frame goes straight into the stripe extractor as a cv::Mat header, ROI offset
// carried along: no copy between the driver's buffer and the peak finder.
TEST(V4l2Camera, LentY16FrameFeedsTheStripeExtractorWithSensorRows) {
  FakeVideoDevice device;
  device.row_padding_bytes = 32;
  device.draw = [](std::uint8_t* data, const v4l2_pix_format& format,
                   const FakeVideoDevice::Delivery&) {
    std::memset(data, 0, format.sizeimage);
    for (std::uint32_t r = 0; r < format.height; ++r) {
      const double d = static_cast<double>(r) - 12.25;
      const auto value = static_cast<std::uint16_t>(3000.0 * std::exp(-0.5 * d * d / 2.0));
      auto* row = reinterpret_cast<std::uint16_t*>(data + r * format.bytesperline);
      for (std::uint32_t c = 0; c < format.width; ++c) row[c] = value;
    }
  };
  CameraConfig config = small_config(PixelFormat::kY16);
  config.roi_top_px = 500;
  V4l2Camera camera(config, device);
  ASSERT_EQ(camera.start(), CameraStatus::kOk);
  device.deliver(0, 100);
  FrameView frame;
  ASSERT_EQ(camera.next_frame(1000, frame), CameraStatus::kOk);

  StripeExtractionParameters parameters;
  parameters.method = StripePeakMethod::kGaussianThreePoint;
  parameters.threshold = 100;
  parameters.min_peak_intensity = 200;
  LaserStripeExtractor extractor(parameters);
  StripePeaks peaks;
  ASSERT_EQ(extractor.extract(frame_as_mat(frame), frame_roi(frame), peaks),
            StripeExtractionStatus::kOk);
  EXPECT_EQ(peaks.valid_columns, 64);
  EXPECT_NEAR(peaks.row_px[0], 512.25, 0.02);
  EXPECT_NEAR(peaks.row_px[63], 512.25, 0.02);
  EXPECT_EQ(camera.release_frame(frame), CameraStatus::kOk);
}

}  // namespace
}  // namespace cosmos
