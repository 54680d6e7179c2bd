// V4l2Camera's lifecycle and set-up errors, against the fake device (and, for a missing
// node, the real system calls).
#include "firmware_bridge/v4l2_camera.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "tests/firmware_bridge/fake_video_device.hpp"

namespace cosmos {
namespace {

using test::FakeVideoDevice;
using test::small_config;

TEST(V4l2Camera, StreamOnBeforeBuffersIsRefusedWithTheStepToCall) {
  FakeVideoDevice device;
  V4l2Camera camera(small_config(), device);
  ASSERT_EQ(camera.open(), CameraStatus::kOk);
  ASSERT_EQ(camera.set_format(), CameraStatus::kOk);
  EXPECT_EQ(camera.stream_on(), CameraStatus::kWrongState);
  EXPECT_EQ(camera.last_error(),
            "/dev/video0: stream_on: camera is format set, call allocate_buffers first");
  EXPECT_FALSE(device.streaming);

  FrameView frame;
  EXPECT_EQ(camera.next_frame(1000, frame), CameraStatus::kWrongState);
  EXPECT_EQ(camera.last_error(),
            "/dev/video0: next_frame: camera is format set, call stream_on first");
  EXPECT_EQ(camera.open(), CameraStatus::kWrongState);
  EXPECT_EQ(camera.last_error(), "/dev/video0: open: camera is already format set");
}

TEST(V4l2Camera, EveryStepBeforeOpenIsRefused) {
  FakeVideoDevice device;
  V4l2Camera camera(small_config(), device);
  EXPECT_EQ(camera.set_format(), CameraStatus::kWrongState);
  EXPECT_EQ(camera.allocate_buffers(), CameraStatus::kWrongState);
  EXPECT_EQ(camera.set_exposure_us(500), CameraStatus::kWrongState);
  EXPECT_EQ(camera.last_error(), "/dev/video0: set_exposure_us: camera is closed, call open first");
  EXPECT_TRUE(device.calls.empty());  // nothing reached the device
}

TEST(V4l2Camera, MissingDeviceNodeGivesOneLine) {
  CameraConfig config = small_config();
  config.device = "/dev/video-cosmos-missing";
  V4l2Camera camera(config);  // the real system calls
  EXPECT_EQ(camera.start(), CameraStatus::kError);
  EXPECT_EQ(camera.last_error(), "/dev/video-cosmos-missing: open: No such file or directory");
  EXPECT_EQ(camera.state(), V4l2Camera::State::kClosed);
}

TEST(V4l2Camera, NonV4l2FileIsNamedAsSuch) {
  CameraConfig config = small_config();
  config.device = "/dev/null";
  V4l2Camera camera(config);
  EXPECT_EQ(camera.open(), CameraStatus::kError);
  EXPECT_EQ(camera.last_error(), "/dev/null: VIDIOC_QUERYCAP: not a V4L2 device");
}

TEST(V4l2Camera, DeviceWithoutStreamingIsRefused) {
  FakeVideoDevice device;
  device.device_caps = V4L2_CAP_VIDEO_CAPTURE | V4L2_CAP_READWRITE;
  V4l2Camera camera(small_config(), device);
  EXPECT_EQ(camera.open(), CameraStatus::kError);
  EXPECT_EQ(camera.last_error(),
            "/dev/video0: VIDIOC_QUERYCAP: does not support streaming I/O (driver fake)");
  EXPECT_EQ(device.open_fds, 0);
}

TEST(V4l2Camera, SubstitutedPixelFormatIsReportedNotAccepted) {
  FakeVideoDevice device;
  device.pixel_formats = {V4L2_PIX_FMT_GREY};
  V4l2Camera camera(small_config(PixelFormat::kY16), device);
  ASSERT_EQ(camera.open(), CameraStatus::kOk);
  EXPECT_EQ(camera.set_format(), CameraStatus::kError);
  EXPECT_EQ(camera.last_error(),
            "/dev/video0: VIDIOC_S_FMT: pixel format Y16 not supported (driver offers GREY)");
  EXPECT_EQ(camera.state(), V4l2Camera::State::kOpen);
}

TEST(V4l2Camera, RoiNeedsCroppingUnlessAtTheOrigin) {
  FakeVideoDevice device;
  device.supports_crop = false;
  {
    V4l2Camera camera(small_config(), device);
    EXPECT_EQ(camera.start(), CameraStatus::kOk);  // ROI (0, 0): the driver's own size will do
  }
  CameraConfig config = small_config();
  config.roi_top_px = 384;
  V4l2Camera camera(config, device);
  EXPECT_EQ(camera.start(), CameraStatus::kError);
  EXPECT_EQ(camera.last_error(),
            "/dev/video0: VIDIOC_S_SELECTION: ROI top 384 left 0: Inappropriate ioctl for device");
  EXPECT_EQ(device.open_fds, 0);  // a failed start unwinds
}

TEST(V4l2Camera, RoiTheDriverMovesIsRefusedWithOneLine) {
  // vivid, like most drivers, moves a crop rectangle that leaves the sensor back inside it
  // and reports success: the camera would stream rows the config did not ask for.
  FakeVideoDevice device;
  device.clamps_crop = true;
  CameraConfig config = small_config();
  config.roi_top_px = 1024 - config.height_px + 16;
  V4l2Camera camera(config, device);
  EXPECT_EQ(camera.start(), CameraStatus::kError);
  EXPECT_EQ(camera.last_error(),
            "/dev/video0: VIDIOC_S_SELECTION: ROI top " + std::to_string(config.roi_top_px) +
                " left 0 " + std::to_string(config.width_px) + "x" +
                std::to_string(config.height_px) + " not supported (driver offers top " +
                std::to_string(1024 - config.height_px) + " left 0 " +
                std::to_string(config.width_px) + "x" + std::to_string(config.height_px) + ")");
  EXPECT_EQ(device.open_fds, 0);
  config.roi_top_px = 1024 - config.height_px;  // inside: taken as it is
  V4l2Camera inside(config, device);
  EXPECT_EQ(inside.start(), CameraStatus::kOk) << inside.last_error();
}

TEST(V4l2Camera, LifecycleRunsInOrderAndUnwindsCompletely) {
  FakeVideoDevice device;
  CameraConfig config = small_config();
  config.roi_top_px = 400;
  V4l2Camera camera(config, device);
  ASSERT_EQ(camera.start(), CameraStatus::kOk) << camera.last_error();
  EXPECT_EQ(camera.state(), V4l2Camera::State::kStreaming);
  EXPECT_EQ(device.crop.top, 400);
  EXPECT_EQ(camera.buffer_count(), 4);
  EXPECT_EQ(device.mapped, 4);
  EXPECT_EQ(device.queued(), 4u);

  ASSERT_EQ(camera.stop(), CameraStatus::kOk);
  EXPECT_EQ(camera.state(), V4l2Camera::State::kClosed);
  EXPECT_EQ(device.mapped, 0);
  EXPECT_EQ(device.open_fds, 0);
  const std::vector<std::string> expected = {"open",
                                             "VIDIOC_QUERYCAP",
                                             "VIDIOC_S_SELECTION",
                                             "VIDIOC_S_FMT",
                                             "VIDIOC_REQBUFS",
                                             "VIDIOC_QUERYBUF",
                                             "VIDIOC_QUERYBUF",
                                             "VIDIOC_QUERYBUF",
                                             "VIDIOC_QUERYBUF",
                                             "VIDIOC_QBUF",
                                             "VIDIOC_QBUF",
                                             "VIDIOC_QBUF",
                                             "VIDIOC_QBUF",
                                             "VIDIOC_STREAMON",
                                             "VIDIOC_STREAMOFF",
                                             "VIDIOC_REQBUFS",
                                             "close"};
  EXPECT_EQ(device.calls, expected);
}

TEST(V4l2Camera, DestructorClosesAStreamingCamera) {
  FakeVideoDevice device;
  {
    V4l2Camera camera(small_config(), device);
    ASSERT_EQ(camera.start(), CameraStatus::kOk);
  }
  EXPECT_FALSE(device.streaming);
  EXPECT_EQ(device.mapped, 0);
  EXPECT_EQ(device.open_fds, 0);
}

}  // namespace
}  // namespace cosmos
