#pragma once
// An 8-bit BGR picture in the project's own pixel storage. The render headers return this
// instead of cv::Mat so that callers (tests, apps) need no OpenCV include path; the layout is
// exactly that of a CV_8UC3 image, so render code wraps it without copying.
#include <cstdint>

#include "core/pixel_grid.hpp"

namespace cosmos {

struct BgrColor {
  std::uint8_t blue = 0;
  std::uint8_t green = 0;
  std::uint8_t red = 0;
  friend bool operator==(const BgrColor&, const BgrColor&) = default;
};
static_assert(sizeof(BgrColor) == 3, "BgrColor must match a CV_8UC3 pixel");

constexpr BgrColor rgb(std::uint8_t red, std::uint8_t green, std::uint8_t blue) {
  return BgrColor{blue, green, red};
}

using BgrPicture = PixelGrid<BgrColor>;

}  // namespace cosmos
