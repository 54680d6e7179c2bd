#pragma once
// The monochrome pixel formats a laser-line camera delivers. A stripe is one bright line on a
// dark image, so colour is useless; what matters is the bit depth: 8-bit is enough for a
// well-exposed stripe, 10/12/16-bit lets the centre of gravity resolve a saturating or very
// dim one. 10- and 12-bit samples arrive in 16-bit little-endian words, low bits aligned.
#include <cstdint>
#include <optional>
#include <string_view>

namespace cosmos {

enum class PixelFormat : std::uint8_t {
  kGrey8,  // V4L2_PIX_FMT_GREY
  kY10,    // V4L2_PIX_FMT_Y10, 10 bits in 16
  kY12,    // V4L2_PIX_FMT_Y12, 12 bits in 16
  kY16,    // V4L2_PIX_FMT_Y16
};

int bytes_per_pixel(PixelFormat format) noexcept;
// Bits that carry intensity: the stripe extractor's saturation level is 2^bits − 1.
int significant_bits(PixelFormat format) noexcept;
// The name used in config files and messages: "GREY", "Y10", "Y12", "Y16".
const char* pixel_format_name(PixelFormat format) noexcept;
std::optional<PixelFormat> parse_pixel_format(std::string_view name) noexcept;

}  // namespace cosmos
