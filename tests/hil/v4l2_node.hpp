#pragma once
// A V4L2 device node as the hardware-in-the-loop tools use it: the player's side of vivid
// (the output node, the driver's controls and events), never the cell's camera, which is the
// project's own V4l2Camera. Set-up code of a test tool: a refused ioctl throws
// std::runtime_error with one line naming the node, the request and the reason.
#include <linux/videodev2.h>

#include <cstdint>
#include <string>

namespace cosmos::hil {

class V4l2Node {
 public:
  explicit V4l2Node(std::string path);
  ~V4l2Node();
  V4l2Node(const V4l2Node&) = delete;
  V4l2Node& operator=(const V4l2Node&) = delete;

  int fd() const { return fd_; }
  const std::string& path() const { return path_; }

  // ioctl with EINTR retried; throws naming `what` unless it succeeds.
  void call(unsigned long request, void* argument, const char* what) const;
  // The same, returning errno (0 on success) instead of throwing.
  int try_call(unsigned long request, void* argument) const;

  // A control found by its driver name (VIDIOC_QUERY_EXT_CTRL), so driver-private IDs are
  // never hard-coded; throws when the node has no such control.
  std::uint32_t control_id(const std::string& name) const;
  void set_control(const std::string& name, std::int64_t value) const;
  std::int64_t control(const std::string& name) const;

  // The pixel formats the node enumerates for `type` (VIDIOC_ENUM_FMT), as fourcc text.
  std::string enumerated_formats(v4l2_buf_type type) const;

 private:
  std::string path_;
  int fd_ = -1;
};

// "GREY", "Y16 " … from a fourcc code.
std::string fourcc_text(std::uint32_t fourcc);

}  // namespace cosmos::hil
