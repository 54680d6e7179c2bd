#include "tests/hil/v4l2_node.hpp"

#include <fcntl.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <utility>

namespace cosmos::hil {

V4l2Node::V4l2Node(std::string path) : path_(std::move(path)) {
  fd_ = ::open(path_.c_str(), O_RDWR | O_NONBLOCK);
  if (fd_ < 0) throw std::runtime_error(path_ + ": open: " + std::strerror(errno));
}

V4l2Node::~V4l2Node() {
  if (fd_ >= 0) ::close(fd_);
}

int V4l2Node::try_call(unsigned long request, void* argument) const {
  int result = 0;
  do {
    result = ::ioctl(fd_, request, argument);
  } while (result == -1 && errno == EINTR);
  return result == 0 ? 0 : errno;
}

void V4l2Node::call(unsigned long request, void* argument, const char* what) const {
  if (const int error = try_call(request, argument); error != 0) {
    throw std::runtime_error(path_ + ": " + what + ": " + std::strerror(error));
  }
}

std::uint32_t V4l2Node::control_id(const std::string& name) const {
  v4l2_query_ext_ctrl query{};
  query.id = V4L2_CTRL_FLAG_NEXT_CTRL | V4L2_CTRL_FLAG_NEXT_COMPOUND;
  while (try_call(VIDIOC_QUERY_EXT_CTRL, &query) == 0) {
    if (name == query.name) return query.id;
    query.id |= V4L2_CTRL_FLAG_NEXT_CTRL | V4L2_CTRL_FLAG_NEXT_COMPOUND;
  }
  throw std::runtime_error(path_ + ": no control named \"" + name + "\"");
}

void V4l2Node::set_control(const std::string& name, std::int64_t value) const {
  v4l2_ext_control control{};
  control.id = control_id(name);
  // Every control the tools set (booleans, menus, buttons, percentages) is 32-bit.
  control.value = static_cast<std::int32_t>(value);
  v4l2_ext_controls controls{};
  controls.which = V4L2_CTRL_WHICH_CUR_VAL;
  controls.count = 1;
  controls.controls = &control;
  const std::string what = "VIDIOC_S_EXT_CTRLS \"" + name + "\"";
  call(VIDIOC_S_EXT_CTRLS, &controls, what.c_str());
}

std::int64_t V4l2Node::control(const std::string& name) const {
  v4l2_ext_control control{};
  control.id = control_id(name);
  v4l2_ext_controls controls{};
  controls.which = V4L2_CTRL_WHICH_CUR_VAL;
  controls.count = 1;
  controls.controls = &control;
  const std::string what = "VIDIOC_G_EXT_CTRLS \"" + name + "\"";
  call(VIDIOC_G_EXT_CTRLS, &controls, what.c_str());
  return control.value;
}

std::string V4l2Node::enumerated_formats(v4l2_buf_type type) const {
  std::string formats;
  v4l2_fmtdesc description{};
  description.type = type;
  while (try_call(VIDIOC_ENUM_FMT, &description) == 0) {
    if (!formats.empty()) formats += ' ';
    std::string text = fourcc_text(description.pixelformat);
    while (!text.empty() && text.back() == ' ') text.pop_back();
    formats += text;
    ++description.index;
  }
  return formats;
}

std::string fourcc_text(std::uint32_t fourcc) {
  // Bit 31 marks the big-endian variant of a format (V4L2_PIX_FMT_Y16_BE): not a character.
  std::string text(4, ' ');
  for (int i = 0; i < 4; ++i)
    text[static_cast<std::size_t>(i)] = static_cast<char>((fourcc >> (8 * i)) & 0x7f);
  if ((fourcc & (1u << 31)) != 0) text += "-BE";
  return text;
}

}  // namespace cosmos::hil
