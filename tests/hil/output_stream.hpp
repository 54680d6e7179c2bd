#pragma once
// The V4L2 output side of the player: memory-mapped output buffers on vivid's output node,
// filled by the player and queued one frame at a time. vivid's output thread retires the
// head buffer (hands it back, done) only while another is queued behind it, which is what
// keeps the last frame looping while the player waits.
#include <cstdint>
#include <vector>

#include "tests/hil/v4l2_node.hpp"

namespace cosmos::hil {

class OutputStream {
 public:
  // Requests `count` mmap buffers of the node's current format and maps them.
  OutputStream(const V4l2Node& node, int count);
  ~OutputStream();
  OutputStream(const OutputStream&) = delete;
  OutputStream& operator=(const OutputStream&) = delete;

  int buffer_count() const { return static_cast<int>(buffers_.size()); }
  // A buffer the player owns (never queued, or retired and dequeued); -1 when all are queued.
  int free_buffer() const;
  std::uint8_t* data(int index) const { return buffers_[static_cast<std::size_t>(index)].data; }
  std::size_t length(int index) const { return buffers_[static_cast<std::size_t>(index)].length; }

  // Queues the buffer with `bytes_used` bytes of frame (VIDIOC_QBUF).
  void queue(int index, std::uint32_t bytes_used);
  void stream_on();
  void stream_off();

  struct Retired {
    int index = -1;
    std::int64_t t_ns = 0;  // when the output thread retired it (CLOCK_MONOTONIC)
  };
  // Dequeues one retired buffer without waiting; false when none is done.
  bool dequeue(Retired& retired);
  int queued() const;
  bool is_queued(int index) const { return buffers_[static_cast<std::size_t>(index)].queued; }

 private:
  struct Buffer {
    std::uint8_t* data = nullptr;
    std::size_t length = 0;
    bool queued = false;
  };
  const V4l2Node& node_;
  std::vector<Buffer> buffers_;
  bool streaming_ = false;
};

}  // namespace cosmos::hil
