#pragma once
// shape_index.png: each pixel in the colour of its Fig. 3.3 category (shape_category_palette),
// planar grey, invalid black, with a legend naming the categories. The field is placed by
// field_layout() of the field size and the given pixel size.
#include "core/render/bgr_picture.hpp"
#include "core/surface/shape_index.hpp"

namespace cosmos {

BgrColor shape_index_pixel_color(SurfaceLabel label, float shape_index);
BgrPicture render_shape_index_picture(const ShapeIndexField& field, double pixel_size_x_mm,
                                      double pixel_size_y_mm);

}  // namespace cosmos
