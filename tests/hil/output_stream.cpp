#include "tests/hil/output_stream.hpp"

#include <sys/mman.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <stdexcept>

#include "firmware_bridge/kernel_timestamp.hpp"

namespace cosmos::hil {

OutputStream::OutputStream(const V4l2Node& node, int count) : node_(node) {
  v4l2_requestbuffers request{};
  request.count = static_cast<std::uint32_t>(count);
  request.type = V4L2_BUF_TYPE_VIDEO_OUTPUT;
  request.memory = V4L2_MEMORY_MMAP;
  node_.call(VIDIOC_REQBUFS, &request, "VIDIOC_REQBUFS (output)");
  for (std::uint32_t i = 0; i < request.count; ++i) {
    v4l2_buffer buffer{};
    buffer.type = V4L2_BUF_TYPE_VIDEO_OUTPUT;
    buffer.memory = V4L2_MEMORY_MMAP;
    buffer.index = i;
    node_.call(VIDIOC_QUERYBUF, &buffer, "VIDIOC_QUERYBUF (output)");
    void* address = ::mmap(nullptr, buffer.length, PROT_READ | PROT_WRITE, MAP_SHARED, node_.fd(),
                           buffer.m.offset);
    if (address == MAP_FAILED) {
      throw std::runtime_error(node_.path() + ": mmap output buffer: " + std::strerror(errno));
    }
    buffers_.push_back({static_cast<std::uint8_t*>(address), buffer.length, false});
    std::memset(address, 0, buffer.length);
  }
}

OutputStream::~OutputStream() {
  if (streaming_) {
    int type = V4L2_BUF_TYPE_VIDEO_OUTPUT;
    node_.try_call(VIDIOC_STREAMOFF, &type);
  }
  for (const Buffer& buffer : buffers_) ::munmap(buffer.data, buffer.length);
  v4l2_requestbuffers request{};
  request.type = V4L2_BUF_TYPE_VIDEO_OUTPUT;
  request.memory = V4L2_MEMORY_MMAP;
  node_.try_call(VIDIOC_REQBUFS, &request);
}

int OutputStream::free_buffer() const {
  for (std::size_t i = 0; i < buffers_.size(); ++i) {
    if (!buffers_[i].queued) return static_cast<int>(i);
  }
  return -1;
}

int OutputStream::queued() const {
  return static_cast<int>(
      std::count_if(buffers_.begin(), buffers_.end(), [](const Buffer& b) { return b.queued; }));
}

void OutputStream::queue(int index, std::uint32_t bytes_used) {
  v4l2_buffer buffer{};
  buffer.type = V4L2_BUF_TYPE_VIDEO_OUTPUT;
  buffer.memory = V4L2_MEMORY_MMAP;
  buffer.index = static_cast<std::uint32_t>(index);
  buffer.bytesused = bytes_used;
  buffer.field = V4L2_FIELD_NONE;
  node_.call(VIDIOC_QBUF, &buffer, "VIDIOC_QBUF (output)");
  buffers_[static_cast<std::size_t>(index)].queued = true;
}

void OutputStream::stream_on() {
  int type = V4L2_BUF_TYPE_VIDEO_OUTPUT;
  node_.call(VIDIOC_STREAMON, &type, "VIDIOC_STREAMON (output)");
  streaming_ = true;
}

void OutputStream::stream_off() {
  int type = V4L2_BUF_TYPE_VIDEO_OUTPUT;
  node_.call(VIDIOC_STREAMOFF, &type, "VIDIOC_STREAMOFF (output)");
  for (Buffer& buffer : buffers_) buffer.queued = false;
  streaming_ = false;
}

bool OutputStream::dequeue(Retired& retired) {
  v4l2_buffer buffer{};
  buffer.type = V4L2_BUF_TYPE_VIDEO_OUTPUT;
  buffer.memory = V4L2_MEMORY_MMAP;
  if (const int error = node_.try_call(VIDIOC_DQBUF, &buffer); error != 0) {
    if (error == EAGAIN) return false;
    throw std::runtime_error(node_.path() + ": VIDIOC_DQBUF (output): " + std::strerror(error));
  }
  buffers_[buffer.index].queued = false;
  retired.index = static_cast<int>(buffer.index);
  retired.t_ns = timeval_to_us(buffer.timestamp) * 1000;
  return true;
}

}  // namespace cosmos::hil
