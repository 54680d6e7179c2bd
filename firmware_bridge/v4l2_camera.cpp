#include "firmware_bridge/v4l2_camera.hpp"

#include <fcntl.h>
#include <linux/videodev2.h>
#include <sys/mman.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstdarg>
#include <utility>

#include "firmware_bridge/v4l2_fourcc.hpp"

namespace cosmos {

namespace {

// Indexed by V4l2Camera::State: its name, and the step that reaches it.
constexpr std::array<const char*, 5> kStateNames = {"closed", "open", "format set",
                                                    "buffers allocated", "streaming"};
constexpr std::array<const char*, 5> kStepReaching = {"close", "open", "set_format",
                                                      "allocate_buffers", "stream_on"};

const char* state_name(V4l2Camera::State state) noexcept {
  const auto i = static_cast<std::size_t>(state);
  return i < kStateNames.size() ? kStateNames[i] : "?";
}

const char* step_reaching(V4l2Camera::State state) noexcept {
  const auto i = static_cast<std::size_t>(state);
  return i < kStepReaching.size() ? kStepReaching[i] : "?";
}

}  // namespace

V4l2Camera::V4l2Camera(CameraConfig config, VideoDeviceIo& io)
    : config_(std::move(config)), io_(io) {}

V4l2Camera::~V4l2Camera() { close(); }

bool V4l2Camera::require(State needed, const char* step) noexcept {
  if (state_ == needed) return true;
  if (state_ < needed) {
    error_.set("%s: %s: camera is %s, call %s first", config_.device.c_str(), step,
               state_name(state_), step_reaching(needed));
  } else {
    error_.set("%s: %s: camera is already %s", config_.device.c_str(), step, state_name(state_));
  }
  return false;
}

CameraStatus V4l2Camera::fail(const char* step, int error_number) noexcept {
  error_.set("%s: %s: %s", config_.device.c_str(), step, errno_text(error_number));
  ++stats_.errors;
  return CameraStatus::kError;
}

CameraStatus V4l2Camera::fail_with(const char* format, ...) noexcept {
  char reason[ErrorLine::kCapacity];
  va_list arguments;
  va_start(arguments, format);
  std::vsnprintf(reason, sizeof reason, format, arguments);
  va_end(arguments);
  error_.set("%s: %s", config_.device.c_str(), reason);
  ++stats_.errors;
  return CameraStatus::kError;
}

CameraStatus V4l2Camera::open() noexcept {
  if (!require(State::kClosed, "open")) return CameraStatus::kWrongState;
  fd_ = io_.open(config_.device.c_str(), O_RDWR | O_NONBLOCK);
  if (fd_ < 0) return fail("open", errno);

  v4l2_capability capability{};
  if (io_.ioctl(fd_, VIDIOC_QUERYCAP, &capability) < 0) {
    const int error_number = errno;
    close_device();
    if (error_number == ENOTTY) return fail_with("VIDIOC_QUERYCAP: not a V4L2 device");
    return fail("VIDIOC_QUERYCAP", error_number);
  }
  // device_caps describes this node; capabilities covers the whole physical device.
  const std::uint32_t caps = (capability.capabilities & V4L2_CAP_DEVICE_CAPS) != 0
                                 ? capability.device_caps
                                 : capability.capabilities;
  const char* missing = nullptr;
  if ((caps & V4L2_CAP_VIDEO_CAPTURE) == 0) {
    missing = (caps & V4L2_CAP_VIDEO_CAPTURE_MPLANE) != 0
                  ? "is a multi-planar capture device (not supported)"
                  : "is not a video capture device";
  } else if ((caps & V4L2_CAP_STREAMING) == 0) {
    missing = "does not support streaming I/O";
  }
  if (missing != nullptr) {
    close_device();
    return fail_with("VIDIOC_QUERYCAP: %s (driver %s)", missing,
                     reinterpret_cast<const char*>(capability.driver));
  }
  state_ = State::kOpen;
  return CameraStatus::kOk;
}

CameraStatus V4l2Camera::set_format() noexcept {
  // Setting the format again before buffers exist is allowed: it is how a caller retries.
  if (state_ != State::kFormatSet && !require(State::kOpen, "set_format"))
    return CameraStatus::kWrongState;
  state_ = State::kOpen;  // until the driver has accepted the new format
  const PixelFormat format = config_.pixel_format;
  const bool roi_at_origin = config_.roi_top_px == 0 && config_.roi_left_px == 0;

  // Crop first: the V4L2 selection API defines the format as applying to the crop rectangle.
  v4l2_selection selection{};
  selection.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  selection.target = V4L2_SEL_TGT_CROP;
  selection.r = {config_.roi_left_px, config_.roi_top_px,
                 static_cast<std::uint32_t>(config_.width_px),
                 static_cast<std::uint32_t>(config_.height_px)};
  if (io_.ioctl(fd_, VIDIOC_S_SELECTION, &selection) == 0) {
    // Drivers move a crop rectangle inside their bounds (and to their alignment) instead of
    // refusing it: frames of rows other than the configured band would reach triangulation.
    const v4l2_rect& got = selection.r;
    if (got.top != config_.roi_top_px || got.left != config_.roi_left_px ||
        static_cast<int>(got.width) != config_.width_px ||
        static_cast<int>(got.height) != config_.height_px) {
      return fail_with(
          "VIDIOC_S_SELECTION: ROI top %d left %d %dx%d not supported (driver offers top %d left "
          "%d %ux%u)",
          config_.roi_top_px, config_.roi_left_px, config_.width_px, config_.height_px, got.top,
          got.left, got.width, got.height);
    }
    roi_top_px_ = got.top;
    roi_left_px_ = got.left;
  } else if (roi_at_origin && (errno == ENOTTY || errno == EINVAL || errno == ENODATA)) {
    roi_top_px_ = 0;  // no cropping on this driver, and none needed
    roi_left_px_ = 0;
  } else {
    return fail_with("VIDIOC_S_SELECTION: ROI top %d left %d: %s", config_.roi_top_px,
                     config_.roi_left_px, errno_text(errno));
  }

  v4l2_format requested{};
  requested.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  requested.fmt.pix.width = static_cast<std::uint32_t>(config_.width_px);
  requested.fmt.pix.height = static_cast<std::uint32_t>(config_.height_px);
  requested.fmt.pix.pixelformat = fourcc_of(format);
  requested.fmt.pix.field = V4L2_FIELD_NONE;
  if (io_.ioctl(fd_, VIDIOC_S_FMT, &requested) < 0) return fail("VIDIOC_S_FMT", errno);
  // Drivers do not refuse a format, they substitute the nearest one they have: compare.
  const v4l2_pix_format& got = requested.fmt.pix;
  if (got.pixelformat != fourcc_of(format)) {
    return fail_with("VIDIOC_S_FMT: pixel format %s not supported (driver offers %s)",
                     pixel_format_name(format), FourccText(got.pixelformat).text);
  }
  if (static_cast<int>(got.width) != config_.width_px ||
      static_cast<int>(got.height) != config_.height_px) {
    return fail_with("VIDIOC_S_FMT: size %dx%d not supported (driver offers %ux%u)",
                     config_.width_px, config_.height_px, got.width, got.height);
  }
  if (got.field != V4L2_FIELD_NONE)
    return fail_with("VIDIOC_S_FMT: interlaced output (field %u)", got.field);
  width_px_ = config_.width_px;
  height_px_ = config_.height_px;
  bytes_per_line_ =
      std::max(static_cast<int>(got.bytesperline), width_px_ * bytes_per_pixel(format));
  state_ = State::kFormatSet;
  return CameraStatus::kOk;
}

CameraStatus V4l2Camera::allocate_buffers() noexcept {
  if (!require(State::kFormatSet, "allocate_buffers")) return CameraStatus::kWrongState;
  v4l2_requestbuffers request{};
  request.count = static_cast<std::uint32_t>(std::clamp(config_.buffer_count, 2, kMaxBuffers));
  request.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  request.memory = V4L2_MEMORY_MMAP;
  if (io_.ioctl(fd_, VIDIOC_REQBUFS, &request) < 0) {
    if (errno == EINVAL) return fail_with("VIDIOC_REQBUFS: memory-mapped buffers not supported");
    return fail("VIDIOC_REQBUFS", errno);
  }
  if (request.count < 2 || request.count > static_cast<std::uint32_t>(kMaxBuffers)) {
    const std::uint32_t granted = request.count;
    request.count = 0;
    io_.ioctl(fd_, VIDIOC_REQBUFS, &request);
    return fail_with("VIDIOC_REQBUFS: driver grants %u buffers, 2 to %d are usable", granted,
                     kMaxBuffers);
  }
  buffer_count_ = static_cast<int>(request.count);
  const std::size_t frame_bytes =
      static_cast<std::size_t>(bytes_per_line_) * static_cast<std::size_t>(height_px_);
  for (int i = 0; i < buffer_count_; ++i) {
    v4l2_buffer buffer{};
    buffer.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    buffer.memory = V4L2_MEMORY_MMAP;
    buffer.index = static_cast<std::uint32_t>(i);
    CameraStatus status = CameraStatus::kOk;
    if (io_.ioctl(fd_, VIDIOC_QUERYBUF, &buffer) < 0) {
      status = fail("VIDIOC_QUERYBUF", errno);
    } else if (buffer.length < frame_bytes) {
      status = fail_with("VIDIOC_QUERYBUF: buffer %d holds %u bytes, a frame needs %zu", i,
                         buffer.length, frame_bytes);
    } else {
      void* address =
          io_.mmap(buffer.length, PROT_READ | PROT_WRITE, MAP_SHARED, fd_, buffer.m.offset);
      if (address == MAP_FAILED) {
        status = fail("mmap", errno);
      } else {
        buffers_[i] = {address, buffer.length, BufferOwner::kApplication};
      }
    }
    if (status != CameraStatus::kOk) {
      unmap_buffers();
      return status;
    }
  }
  state_ = State::kBuffersAllocated;
  return CameraStatus::kOk;
}

CameraStatus V4l2Camera::stream_on() noexcept {
  if (!require(State::kBuffersAllocated, "stream_on")) return CameraStatus::kWrongState;
  for (int i = 0; i < buffer_count_; ++i) {
    if (buffers_[i].owner != BufferOwner::kApplication) continue;
    if (const CameraStatus status = queue_buffer(i); status != CameraStatus::kOk) return status;
  }
  int type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  if (io_.ioctl(fd_, VIDIOC_STREAMON, &type) < 0) return fail("VIDIOC_STREAMON", errno);
  sequence_.restart();
  stats_.consecutive_timeouts = 0;
  state_ = State::kStreaming;
  return CameraStatus::kOk;
}

CameraStatus V4l2Camera::stream_off() noexcept {
  if (!require(State::kStreaming, "stream_off")) return CameraStatus::kWrongState;
  int type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  if (io_.ioctl(fd_, VIDIOC_STREAMOFF, &type) < 0) return fail("VIDIOC_STREAMOFF", errno);
  // STREAMOFF takes every buffer back from the driver, and frames still lent to the caller
  // are dead too: the next stream_on queues them all again.
  for (int i = 0; i < buffer_count_; ++i) buffers_[i].owner = BufferOwner::kApplication;
  queued_ = 0;
  state_ = State::kBuffersAllocated;
  return CameraStatus::kOk;
}

void V4l2Camera::unmap_buffers() noexcept {
  for (MappedBuffer& buffer : buffers_) {
    if (buffer.address != nullptr) io_.munmap(buffer.address, buffer.length);
    buffer = {};
  }
  buffer_count_ = 0;
  queued_ = 0;
  // Frees the driver's buffers; the request for zero is how V4L2 spells "release".
  v4l2_requestbuffers request{};
  request.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  request.memory = V4L2_MEMORY_MMAP;
  io_.ioctl(fd_, VIDIOC_REQBUFS, &request);
}

CameraStatus V4l2Camera::release_buffers() noexcept {
  if (!require(State::kBuffersAllocated, "release_buffers")) return CameraStatus::kWrongState;
  unmap_buffers();
  state_ = State::kFormatSet;
  return CameraStatus::kOk;
}

void V4l2Camera::close_device() noexcept {
  if (fd_ >= 0) io_.close(fd_);
  fd_ = -1;
  state_ = State::kClosed;
}

CameraStatus V4l2Camera::close() noexcept {
  // Unwinds whatever is left even when a step fails: a camera being torn down must not
  // keep its buffers mapped or the device open. The first failure is reported.
  CameraStatus result = CameraStatus::kOk;
  if (state_ == State::kStreaming) {
    result = stream_off();
    if (state_ == State::kStreaming)
      state_ = State::kBuffersAllocated;  // closing the fd stops it anyway
  }
  if (state_ == State::kBuffersAllocated) unmap_buffers();
  close_device();
  manual_exposure_set_ = false;
  return result;
}

CameraStatus V4l2Camera::start() noexcept {
  const auto step = [this](CameraStatus status) {
    if (status != CameraStatus::kOk) close();
    return status;
  };
  if (state_ == State::kStreaming) return CameraStatus::kOk;
  if (state_ == State::kClosed) {
    if (const CameraStatus status = step(open()); status != CameraStatus::kOk) return status;
  }
  if (state_ == State::kOpen) {
    if (const CameraStatus status = step(set_format()); status != CameraStatus::kOk) return status;
    if (config_.exposure_us > 0) {
      if (const CameraStatus status = step(set_exposure_us(config_.exposure_us));
          status != CameraStatus::kOk)
        return status;
    }
    if (config_.gain >= 0) {
      if (const CameraStatus status = step(set_gain(config_.gain)); status != CameraStatus::kOk)
        return status;
    }
  }
  if (state_ == State::kFormatSet) {
    if (const CameraStatus status = step(allocate_buffers()); status != CameraStatus::kOk)
      return status;
  }
  return step(stream_on());
}

}  // namespace cosmos
