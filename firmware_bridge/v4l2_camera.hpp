#pragma once
// The scanner camera through Video4Linux2, memory-mapped streaming I/O.
//
// Lifecycle, one step per call, each checking that the previous one happened:
//   open (open + VIDIOC_QUERYCAP: capture and streaming required)
//   → set_format (ROI by VIDIOC_S_SELECTION, then VIDIOC_S_FMT: GREY / Y10 / Y12 / Y16)
//   → allocate_buffers (VIDIOC_REQBUFS, VIDIOC_QUERYBUF, mmap)
//   → stream_on (VIDIOC_QBUF every buffer, VIDIOC_STREAMON)
//   → next_frame / release_frame (poll with a watchdog, VIDIOC_DQBUF / VIDIOC_QBUF)
//   → stream_off → release_buffers → close.
// close() and the destructor unwind from any state. Every failure leaves one line in
// last_error() naming the device, the step and the reason.
//
// next_frame() and release_frame() run on the acquisition thread: fixed arrays, no
// allocation, no exceptions, no locks. The device is opened non-blocking so a frame is only
// ever waited for in poll(), where the watchdog timeout applies.
#include <array>
#include <cstdint>

#include "firmware_bridge/camera.hpp"
#include "firmware_bridge/camera_config.hpp"
#include "firmware_bridge/error_line.hpp"
#include "firmware_bridge/frame_sequence_tracker.hpp"
#include "firmware_bridge/video_device_io.hpp"

namespace cosmos {

class V4l2Camera final : public Camera {
 public:
  enum class State : std::uint8_t { kClosed, kOpen, kFormatSet, kBuffersAllocated, kStreaming };
  static constexpr int kMaxBuffers = 16;

  explicit V4l2Camera(CameraConfig config, VideoDeviceIo& io = system_video_device_io());
  ~V4l2Camera() override;
  V4l2Camera(const V4l2Camera&) = delete;
  V4l2Camera& operator=(const V4l2Camera&) = delete;

  CameraStatus open() noexcept;
  CameraStatus set_format() noexcept;
  CameraStatus allocate_buffers() noexcept;
  CameraStatus stream_on() noexcept;
  CameraStatus stream_off() noexcept;
  CameraStatus release_buffers() noexcept;
  CameraStatus close() noexcept;

  // open → set_format → exposure and gain from the config → allocate_buffers → stream_on.
  CameraStatus start() noexcept override;
  CameraStatus stop() noexcept override { return close(); }
  CameraStatus next_frame(std::int64_t timeout_us, FrameView& frame) noexcept override;
  CameraStatus release_frame(const FrameView& frame) noexcept override;
  CameraStatus set_exposure_us(int exposure_us) noexcept override;
  CameraStatus set_gain(int gain) noexcept override;
  CameraStats stats() const noexcept override { return stats_; }
  std::string_view last_error() const noexcept override { return error_.view(); }

  State state() const noexcept { return state_; }
  int buffer_count() const noexcept { return buffer_count_; }
  // The exposure the driver was given, after rounding to its 100 µs unit.
  int applied_exposure_us() const noexcept { return applied_exposure_us_; }

 private:
  enum class BufferOwner : std::uint8_t { kApplication, kDriver, kCaller };
  struct MappedBuffer {
    void* address = nullptr;
    std::size_t length = 0;
    BufferOwner owner = BufferOwner::kApplication;
  };

  bool require(State needed, const char* step) noexcept;
  CameraStatus fail(const char* step, int error_number) noexcept;
  [[gnu::format(printf, 2, 3)]] CameraStatus fail_with(const char* format, ...) noexcept;
  CameraStatus queue_buffer(int index) noexcept;
  CameraStatus set_control(std::uint32_t id, std::int32_t value, const char* name) noexcept;
  void unmap_buffers() noexcept;
  void close_device() noexcept;

  CameraConfig config_;
  VideoDeviceIo& io_;
  State state_ = State::kClosed;
  int fd_ = -1;
  std::array<MappedBuffer, kMaxBuffers> buffers_{};
  int buffer_count_ = 0;
  int queued_ = 0;
  // The format as the driver accepted it.
  int width_px_ = 0;
  int height_px_ = 0;
  int bytes_per_line_ = 0;
  int roi_top_px_ = 0;
  int roi_left_px_ = 0;
  bool manual_exposure_set_ = false;
  int applied_exposure_us_ = 0;
  FrameSequenceTracker sequence_;
  CameraStats stats_;
  ErrorLine error_;
};

}  // namespace cosmos
