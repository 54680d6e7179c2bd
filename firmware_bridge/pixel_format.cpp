#include "firmware_bridge/pixel_format.hpp"

namespace cosmos {

int bytes_per_pixel(PixelFormat format) noexcept { return format == PixelFormat::kGrey8 ? 1 : 2; }

int significant_bits(PixelFormat format) noexcept {
  switch (format) {
    case PixelFormat::kGrey8:
      return 8;
    case PixelFormat::kY10:
      return 10;
    case PixelFormat::kY12:
      return 12;
    case PixelFormat::kY16:
      return 16;
  }
  return 8;
}

const char* pixel_format_name(PixelFormat format) noexcept {
  switch (format) {
    case PixelFormat::kGrey8:
      return "GREY";
    case PixelFormat::kY10:
      return "Y10";
    case PixelFormat::kY12:
      return "Y12";
    case PixelFormat::kY16:
      return "Y16";
  }
  return "?";
}

std::optional<PixelFormat> parse_pixel_format(std::string_view name) noexcept {
  for (const PixelFormat format :
       {PixelFormat::kGrey8, PixelFormat::kY10, PixelFormat::kY12, PixelFormat::kY16}) {
    if (name == pixel_format_name(format)) return format;
  }
  return std::nullopt;
}

}  // namespace cosmos
