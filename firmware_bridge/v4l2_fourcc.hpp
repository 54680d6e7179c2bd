#pragma once
// V4L2 four-character pixel codes: the project's PixelFormat ↔ V4L2_PIX_FMT_*, and a code as
// text for messages ("driver offers YUYV").
#include <cstdint>

#include "firmware_bridge/pixel_format.hpp"

namespace cosmos {

std::uint32_t fourcc_of(PixelFormat format) noexcept;

// The code's four characters, trailing blanks dropped ("Y10 " → "Y10"). No allocation.
struct FourccText {
  char text[5] = {};
  explicit FourccText(std::uint32_t code) noexcept;
};

}  // namespace cosmos
