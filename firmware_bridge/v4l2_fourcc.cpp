#include "firmware_bridge/v4l2_fourcc.hpp"

#include <linux/videodev2.h>

namespace cosmos {

std::uint32_t fourcc_of(PixelFormat format) noexcept {
  switch (format) {
    case PixelFormat::kGrey8:
      return V4L2_PIX_FMT_GREY;
    case PixelFormat::kY10:
      return V4L2_PIX_FMT_Y10;
    case PixelFormat::kY12:
      return V4L2_PIX_FMT_Y12;
    case PixelFormat::kY16:
      return V4L2_PIX_FMT_Y16;
  }
  return V4L2_PIX_FMT_GREY;
}

FourccText::FourccText(std::uint32_t code) noexcept {
  for (int i = 0; i < 4; ++i) text[i] = static_cast<char>((code >> (8 * i)) & 0xff);
  for (int i = 3; i >= 0 && text[i] == ' '; --i) text[i] = '\0';
}

}  // namespace cosmos
