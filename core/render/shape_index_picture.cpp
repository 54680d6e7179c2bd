#include "core/render/shape_index_picture.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <opencv2/imgproc.hpp>

#include "core/render/picture_drawing.hpp"
#include "core/render/shape_category_palette.hpp"

namespace cosmos {
namespace {

using namespace render;

constexpr int kLegendWidthPx = 300;
constexpr int kLegendRowPx = 26;
constexpr float kNoValue = std::numeric_limits<float>::quiet_NaN();

void draw_swatch(cv::Mat& canvas, cv::Point top_left, BgrColor color) {
  cv::rectangle(canvas, top_left, top_left + cv::Point(24, 16), scalar(color), cv::FILLED);
  cv::rectangle(canvas, top_left, top_left + cv::Point(24, 16), scalar(kInk));
}

void draw_legend(cv::Mat& canvas, int x, int y) {
  draw_text(canvas, "shape index S_I", {x, y + 14}, 0.55);
  y += 30;
  // Highest S_I on top, like a colour bar.
  for (int k = kShapeCategories - 1; k >= 0; --k) {
    const ShapeCategory& category = kShapeCategoryTable[static_cast<std::size_t>(k)];
    draw_swatch(canvas, {x, y}, category.color);
    draw_text(canvas, std::string(category.name), {x + 32, y + 13}, 0.45);
    draw_text(canvas, std::string(category.interval), {x + 140, y + 13}, 0.4, rgb(90, 90, 90));
    y += kLegendRowPx;
  }
  y += 6;
  draw_swatch(canvas, {x, y}, kPlanarColor);
  draw_text(canvas, "planar", {x + 32, y + 13}, 0.45);
  y += kLegendRowPx;
  draw_swatch(canvas, {x, y}, kNoDataColor);
  draw_text(canvas, "invalid / no data", {x + 32, y + 13}, 0.45);
}

}  // namespace

BgrColor shape_index_pixel_color(SurfaceLabel label, float shape_index) {
  if (label == SurfaceLabel::kPlanar) return kPlanarColor;
  if (label != SurfaceLabel::kCurved || !std::isfinite(shape_index)) return kNoDataColor;
  return shape_category_color(shape_index);
}

BgrPicture render_shape_index_picture(const ShapeIndexField& field, double pixel_size_x_mm,
                                      double pixel_size_y_mm) {
  const FieldLayout layout =
      field_layout(field.width(), field.height(), pixel_size_x_mm, pixel_size_y_mm);
  if (layout.width == 0 || layout.height == 0) return to_picture(empty_field_canvas("shape index"));

  constexpr int kLegendHeightPx = 30 + (kShapeCategories + 2) * kLegendRowPx + 20;
  const int width_px = layout.origin_x_px + layout.display_width_px() + kLegendWidthPx;
  const int height_px =
      layout.origin_y_px + std::max(layout.display_height_px(), kLegendHeightPx) + kFieldMarginPx;
  cv::Mat canvas = blank_canvas(width_px, height_px);
  const bool has_values =
      field.shape_index.width() == field.width() && field.shape_index.height() == field.height();
  paint_field(canvas, layout, [&](int column, int row) {
    return shape_index_pixel_color(field.label(column, row),
                                   has_values ? field.shape_index(column, row) : kNoValue);
  });
  draw_legend(canvas, layout.origin_x_px + layout.display_width_px() + 24, layout.origin_y_px);
  return to_picture(canvas);
}

}  // namespace cosmos
