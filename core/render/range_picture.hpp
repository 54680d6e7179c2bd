#pragma once
// range.png: depth colour-mapped (turbo, near = red) over the finite z range, no data black,
// with a colour bar in mm. The field is placed by field_layout() of the image.
#include "core/range_image.hpp"
#include "core/render/bgr_picture.hpp"

namespace cosmos {

BgrPicture render_range_picture(const RangeImage& image);

}  // namespace cosmos
