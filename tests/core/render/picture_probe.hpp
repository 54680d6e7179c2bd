#pragma once
// Reading rendered pictures back in the render tests: the colour at the centre of an image
// pixel's block, and how many picture pixels have a colour.
#include "core/render/bgr_picture.hpp"
#include "core/render/field_layout.hpp"

namespace cosmos::testing {

inline BgrColor at_pixel(const BgrPicture& picture, const FieldLayout& layout, int column,
                         int row) {
  return picture(layout.centre_x_px(column), layout.centre_y_px(row));
}

inline int count_color(const BgrPicture& picture, BgrColor color) {
  int count = 0;
  for (const BgrColor& c : picture.values()) count += c == color ? 1 : 0;
  return count;
}

}  // namespace cosmos::testing
