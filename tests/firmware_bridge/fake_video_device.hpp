#pragma once
// A V4L2 capture device played in memory: answers the ioctls V4l2Camera makes the way a
// driver does (substituting formats rather than refusing them, FIFO buffer queue, EAGAIN
// when nothing is ready) and delivers frames from a script of sequence numbers, time stamps
// and timeouts, so camera lifecycle, dropped-frame and watchdog logic run without hardware.
#include <linux/videodev2.h>
#include <sys/mman.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <deque>
#include <functional>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "firmware_bridge/camera_config.hpp"
#include "firmware_bridge/video_device_io.hpp"

namespace cosmos::test {

class FakeVideoDevice final : public VideoDeviceIo {
 public:
  struct Delivery {
    bool timeout = false;
    std::uint32_t sequence = 0;
    std::int64_t t_us = 0;
    std::uint32_t flags = V4L2_BUF_FLAG_TIMESTAMP_MONOTONIC;
  };

  // --- what the device is
  std::string path = "/dev/video0";
  std::uint32_t device_caps = V4L2_CAP_VIDEO_CAPTURE | V4L2_CAP_STREAMING;
  std::vector<std::uint32_t> pixel_formats = {V4L2_PIX_FMT_GREY, V4L2_PIX_FMT_Y16};
  bool supports_crop = true;
  bool clamps_crop = false;  // moves a crop rectangle inside the sensor instead of taking it
  std::uint32_t sensor_width = 1280;
  std::uint32_t sensor_height = 1024;
  std::uint32_t row_padding_bytes = 0;
  std::uint32_t max_buffers = 8;
  std::set<std::uint32_t> controls = {V4L2_CID_EXPOSURE_AUTO, V4L2_CID_EXPOSURE_ABSOLUTE,
                                      V4L2_CID_GAIN};
  // Paints a frame into a buffer before it is dequeued (the sensor's exposure).
  std::function<void(std::uint8_t* data, const v4l2_pix_format& format, const Delivery& delivery)>
      draw;

  // --- what happens on each poll(); an empty script times out
  std::deque<Delivery> script;
  void deliver(std::uint32_t sequence, std::int64_t t_us, std::uint32_t extra_flags = 0) {
    script.push_back({false, sequence, t_us, V4L2_BUF_FLAG_TIMESTAMP_MONOTONIC | extra_flags});
  }
  void time_out() { script.push_back({true, 0, 0, 0}); }

  // --- what the camera did (recording allocates: off while counting allocations)
  bool record_calls = true;
  std::vector<std::string> calls;
  std::map<std::uint32_t, std::int32_t> control_values;
  v4l2_rect crop{};
  int open_fds = 0;
  int mapped = 0;
  bool streaming = false;
  std::size_t queued() const { return queue_.size(); }
  std::size_t buffers() const { return buffers_.size(); }

  int open(const char* device, int) noexcept override {
    record("open");
    if (device != path) {
      errno = ENOENT;
      return -1;
    }
    ++open_fds;
    return kFd;
  }

  int close(int) noexcept override {
    record("close");
    --open_fds;
    return 0;
  }

  int ioctl(int fd, unsigned long request, void* argument) noexcept override {
    if (fd != kFd) return fail(EBADF);
    switch (request) {
      case VIDIOC_QUERYCAP: {
        record("VIDIOC_QUERYCAP");
        auto& cap = *static_cast<v4l2_capability*>(argument);
        std::strcpy(reinterpret_cast<char*>(cap.driver), "fake");
        cap.capabilities = device_caps | V4L2_CAP_DEVICE_CAPS;
        cap.device_caps = device_caps;
        return 0;
      }
      case VIDIOC_S_SELECTION: {
        record("VIDIOC_S_SELECTION");
        if (!supports_crop) return fail(ENOTTY);
        auto& selection = *static_cast<v4l2_selection*>(argument);
        if (clamps_crop) {
          // As vivid and most drivers do: the rectangle is moved inside the sensor, not refused.
          v4l2_rect& r = selection.r;
          r.width = std::min(r.width, sensor_width);
          r.height = std::min(r.height, sensor_height);
          r.left = std::clamp(r.left, 0, static_cast<std::int32_t>(sensor_width - r.width));
          r.top = std::clamp(r.top, 0, static_cast<std::int32_t>(sensor_height - r.height));
        }
        crop = selection.r;
        return 0;
      }
      case VIDIOC_S_FMT: {
        record("VIDIOC_S_FMT");
        v4l2_pix_format& pix = static_cast<v4l2_format*>(argument)->fmt.pix;
        if (std::find(pixel_formats.begin(), pixel_formats.end(), pix.pixelformat) ==
            pixel_formats.end()) {
          pix.pixelformat = pixel_formats.front();
        }
        pix.width = std::min(pix.width, sensor_width);
        pix.height = std::min(pix.height, sensor_height);
        pix.field = V4L2_FIELD_NONE;
        const std::uint32_t bytes = pix.pixelformat == V4L2_PIX_FMT_GREY ? 1 : 2;
        pix.bytesperline = pix.width * bytes + row_padding_bytes;
        pix.sizeimage = pix.bytesperline * pix.height;
        format_ = pix;
        return 0;
      }
      case VIDIOC_REQBUFS: {
        record("VIDIOC_REQBUFS");
        auto& request_buffers = *static_cast<v4l2_requestbuffers*>(argument);
        if (request_buffers.memory != V4L2_MEMORY_MMAP) return fail(EINVAL);
        if (streaming) return fail(EBUSY);
        request_buffers.count = std::min(request_buffers.count, max_buffers);
        buffers_.assign(request_buffers.count, std::vector<std::uint8_t>(format_.sizeimage));
        queue_.clear();
        queue_.reserve(request_buffers.count);  // QBUF/DQBUF then never allocate
        return 0;
      }
      case VIDIOC_QUERYBUF: {
        record("VIDIOC_QUERYBUF");
        auto& buffer = *static_cast<v4l2_buffer*>(argument);
        if (buffer.index >= buffers_.size()) return fail(EINVAL);
        buffer.length = static_cast<std::uint32_t>(buffers_[buffer.index].size());
        buffer.m.offset = buffer.index * kOffsetStride;
        return 0;
      }
      case VIDIOC_QBUF: {
        record("VIDIOC_QBUF");
        const auto& buffer = *static_cast<v4l2_buffer*>(argument);
        if (buffer.index >= buffers_.size()) return fail(EINVAL);
        if (std::find(queue_.begin(), queue_.end(), buffer.index) != queue_.end())
          return fail(EINVAL);
        queue_.push_back(buffer.index);
        return 0;
      }
      case VIDIOC_DQBUF:
        return dequeue(*static_cast<v4l2_buffer*>(argument));
      case VIDIOC_STREAMON:
        record("VIDIOC_STREAMON");
        streaming = true;
        return 0;
      case VIDIOC_STREAMOFF:
        record("VIDIOC_STREAMOFF");
        streaming = false;
        queue_.clear();
        ready_ = false;
        return 0;
      case VIDIOC_S_CTRL: {
        record("VIDIOC_S_CTRL");
        const auto& control = *static_cast<v4l2_control*>(argument);
        if (controls.count(control.id) == 0) return fail(EINVAL);
        control_values[control.id] = control.value;
        return 0;
      }
      default:
        return fail(ENOTTY);
    }
  }

  void* mmap(std::size_t length, int, int, int fd, off_t offset) noexcept override {
    const auto index = static_cast<std::size_t>(offset / kOffsetStride);
    if (fd != kFd || index >= buffers_.size() || length > buffers_[index].size()) {
      errno = EINVAL;
      return MAP_FAILED;
    }
    ++mapped;
    return buffers_[index].data();
  }

  int munmap(void*, std::size_t) noexcept override {
    --mapped;
    return 0;
  }

  int poll(pollfd* fds, nfds_t, std::int64_t) noexcept override {
    fds[0].revents = 0;
    if (!streaming || queue_.empty()) {
      fds[0].revents = POLLERR;
      return 1;
    }
    if (ready_) {
      fds[0].revents = POLLIN;
      return 1;
    }
    if (script.empty()) return 0;
    const Delivery next = script.front();
    script.pop_front();
    if (next.timeout) return 0;
    pending_ = next;
    ready_ = true;
    fds[0].revents = POLLIN;
    return 1;
  }

 private:
  static constexpr int kFd = 42;
  static constexpr off_t kOffsetStride = 1 << 24;

  void record(const char* call) {
    if (record_calls) calls.push_back(call);
  }

  static int fail(int error_number) {
    errno = error_number;
    return -1;
  }

  int dequeue(v4l2_buffer& buffer) {
    if (!ready_ || queue_.empty()) return fail(EAGAIN);
    const std::uint32_t index = queue_.front();
    queue_.erase(queue_.begin());
    ready_ = false;
    if (draw) draw(buffers_[index].data(), format_, pending_);
    buffer.index = index;
    buffer.sequence = pending_.sequence;
    buffer.timestamp.tv_sec = static_cast<time_t>(pending_.t_us / 1'000'000);
    buffer.timestamp.tv_usec = static_cast<suseconds_t>(pending_.t_us % 1'000'000);
    buffer.flags = pending_.flags;
    buffer.bytesused = format_.sizeimage;
    return 0;
  }

  v4l2_pix_format format_{};
  std::vector<std::vector<std::uint8_t>> buffers_;
  std::vector<std::uint32_t> queue_;  // FIFO of queued buffers
  Delivery pending_{};
  bool ready_ = false;
};

// The camera the fake device serves: 64 x 32 pixels, four buffers.
inline CameraConfig small_config(PixelFormat format = PixelFormat::kGrey8) {
  CameraConfig config;
  config.device = "/dev/video0";
  config.pixel_format = format;
  config.width_px = 64;
  config.height_px = 32;
  config.buffer_count = 4;
  return config;
}

}  // namespace cosmos::test
