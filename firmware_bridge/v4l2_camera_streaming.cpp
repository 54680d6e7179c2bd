// V4l2Camera's acquisition-thread half: waiting for, handing out and taking back frames, and
// the controls the loop may adjust while streaming (exposure, gain). Kept apart from the
// set-up half so the code that must not allocate, throw or block past its watchdog can be
// audited on its own: only ioctl/poll on fixed structs and the fixed-size error line.
#include <linux/videodev2.h>
#include <poll.h>

#include <algorithm>
#include <cerrno>

#include "firmware_bridge/kernel_timestamp.hpp"
#include "firmware_bridge/v4l2_camera.hpp"

namespace cosmos {

CameraStatus V4l2Camera::queue_buffer(int index) noexcept {
  v4l2_buffer buffer{};
  buffer.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  buffer.memory = V4L2_MEMORY_MMAP;
  buffer.index = static_cast<std::uint32_t>(index);
  if (io_.ioctl(fd_, VIDIOC_QBUF, &buffer) < 0) return fail("VIDIOC_QBUF", errno);
  buffers_[index].owner = BufferOwner::kDriver;
  ++queued_;
  return CameraStatus::kOk;
}

CameraStatus V4l2Camera::next_frame(std::int64_t timeout_us, FrameView& frame) noexcept {
  if (!require(State::kStreaming, "next_frame")) return CameraStatus::kWrongState;
  if (queued_ == 0) {
    // The driver has nowhere to write: poll() would report POLLERR. Say why instead.
    return fail_with("next_frame: all %d buffers are held by the caller, release_frame one first",
                     buffer_count_);
  }
  pollfd request{fd_, POLLIN, 0};
  const int ready = io_.poll(&request, 1, timeout_us);
  if (ready < 0) return errno == EINTR ? CameraStatus::kNoFrame : fail("poll", errno);
  if (ready == 0) {
    ++stats_.timeouts;
    ++stats_.consecutive_timeouts;
    error_.set("%s: poll: no frame within %lld us (%llu consecutive timeouts)",
               config_.device.c_str(), static_cast<long long>(timeout_us),
               static_cast<unsigned long long>(stats_.consecutive_timeouts));
    return CameraStatus::kTimeout;
  }
  if ((request.revents & POLLERR) != 0) return fail_with("poll: device reports an error (POLLERR)");

  v4l2_buffer buffer{};
  buffer.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  buffer.memory = V4L2_MEMORY_MMAP;
  if (io_.ioctl(fd_, VIDIOC_DQBUF, &buffer) < 0) {
    return errno == EAGAIN ? CameraStatus::kNoFrame : fail("VIDIOC_DQBUF", errno);
  }
  const int index = static_cast<int>(buffer.index);
  if (index < 0 || index >= buffer_count_ || buffers_[index].owner != BufferOwner::kDriver) {
    return fail_with("VIDIOC_DQBUF: driver returned buffer %u, which it did not own", buffer.index);
  }
  buffers_[index].owner = BufferOwner::kApplication;
  --queued_;
  stats_.consecutive_timeouts = 0;

  // Sequence numbers count every frame the sensor made, so the gap is taken before the
  // corruption check: a corrupted frame is not a dropped one.
  const FrameSequenceResult sequence = sequence_.on_frame(buffer.sequence);
  stats_.dropped_frames = sequence_.dropped_frames();
  stats_.sequence_resets = sequence_.sequence_resets();

  const std::size_t frame_bytes =
      static_cast<std::size_t>(bytes_per_line_) * static_cast<std::size_t>(height_px_);
  const bool short_frame = buffer.bytesused != 0 && buffer.bytesused < frame_bytes;
  if ((buffer.flags & V4L2_BUF_FLAG_ERROR) != 0 || short_frame) {
    ++stats_.corrupted_frames;
    error_.set("%s: VIDIOC_DQBUF: frame %u %s, skipped", config_.device.c_str(), buffer.sequence,
               short_frame ? "is short" : "flagged corrupted by the driver");
    const CameraStatus requeued = queue_buffer(index);
    return requeued == CameraStatus::kOk ? CameraStatus::kNoFrame : requeued;
  }

  const FrameTimestamp timestamp = decode_v4l2_timestamp(buffer.timestamp, buffer.flags);
  buffers_[index].owner = BufferOwner::kCaller;
  frame.data = static_cast<const std::uint8_t*>(buffers_[index].address);
  frame.width_px = width_px_;
  frame.height_px = height_px_;
  frame.bytes_per_line = bytes_per_line_;
  frame.format = config_.pixel_format;
  frame.roi_top_px = roi_top_px_;
  frame.roi_left_px = roi_left_px_;
  frame.frame_index = sequence.frame_index;
  frame.dropped_before = sequence.dropped_before;
  frame.t_us = timestamp.t_us;
  frame.t_is_start_of_exposure = timestamp.start_of_exposure;
  frame.buffer_index = index;
  ++stats_.frames;
  return CameraStatus::kOk;
}

CameraStatus V4l2Camera::release_frame(const FrameView& frame) noexcept {
  if (!require(State::kStreaming, "release_frame")) return CameraStatus::kWrongState;
  const int index = frame.buffer_index;
  if (index < 0 || index >= buffer_count_ || buffers_[index].owner != BufferOwner::kCaller) {
    return fail_with("release_frame: buffer %d is not lent out", index);
  }
  return queue_buffer(index);
}

CameraStatus V4l2Camera::set_control(std::uint32_t id, std::int32_t value,
                                     const char* name) noexcept {
  v4l2_control control{id, value};
  if (io_.ioctl(fd_, VIDIOC_S_CTRL, &control) < 0) {
    return fail_with("VIDIOC_S_CTRL %s=%d: %s", name, value, errno_text(errno));
  }
  return CameraStatus::kOk;
}

CameraStatus V4l2Camera::set_exposure_us(int exposure_us) noexcept {
  if (state_ == State::kClosed) {
    require(State::kOpen, "set_exposure_us");
    return CameraStatus::kWrongState;
  }
  if (!manual_exposure_set_) {
    // Auto exposure would fight the stripe-intensity loop; cameras without the control have
    // manual exposure only, so its absence is not an error.
    v4l2_control control{V4L2_CID_EXPOSURE_AUTO, V4L2_EXPOSURE_MANUAL};
    if (io_.ioctl(fd_, VIDIOC_S_CTRL, &control) < 0 && errno != EINVAL) {
      return fail_with("VIDIOC_S_CTRL exposure_auto=manual: %s", errno_text(errno));
    }
    manual_exposure_set_ = true;
  }
  // V4L2_CID_EXPOSURE_ABSOLUTE counts 100 µs units; never round a short exposure to zero.
  const std::int32_t units = std::max(1, (exposure_us + 50) / 100);
  if (const CameraStatus status =
          set_control(V4L2_CID_EXPOSURE_ABSOLUTE, units, "exposure_absolute");
      status != CameraStatus::kOk) {
    return status;
  }
  applied_exposure_us_ = units * 100;
  return CameraStatus::kOk;
}

CameraStatus V4l2Camera::set_gain(int gain) noexcept {
  if (state_ == State::kClosed) {
    require(State::kOpen, "set_gain");
    return CameraStatus::kWrongState;
  }
  return set_control(V4L2_CID_GAIN, gain, "gain");
}

}  // namespace cosmos
