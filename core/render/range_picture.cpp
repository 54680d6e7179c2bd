#include "core/render/range_picture.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <opencv2/imgproc.hpp>

#include "core/render/picture_drawing.hpp"
#include "core/render/shape_category_palette.hpp"

namespace cosmos {
namespace {

using namespace render;

constexpr int kBarWidthPx = 26;
constexpr int kPanelWidthPx = 150;

// Turbo sampled at 256 levels; z is quantized to these.
cv::Mat turbo_lookup() {
  cv::Mat ramp(256, 1, CV_8UC1);
  for (int level = 0; level < 256; ++level)
    ramp.at<std::uint8_t>(level) = static_cast<std::uint8_t>(level);
  cv::Mat colors;
  cv::applyColorMap(ramp, colors, cv::COLORMAP_TURBO);
  return colors;
}

BgrColor lookup(const cv::Mat& colors, int level) {
  const cv::Vec3b c = colors.at<cv::Vec3b>(std::clamp(level, 0, 255));
  return BgrColor{c[0], c[1], c[2]};
}

void draw_colour_bar(cv::Mat& canvas, const cv::Mat& colors, int x, int top, int bottom,
                     double z_min_mm, double z_max_mm) {
  draw_text(canvas, "z (mm)", {x, top - 12}, 0.5);
  const int height = bottom - top;
  for (int y = top; y <= bottom; ++y) {
    const int level = static_cast<int>(std::lround(255.0 * (bottom - y) / std::max(height, 1)));
    cv::line(canvas, {x, y}, {x + kBarWidthPx, y}, scalar(lookup(colors, level)));
  }
  cv::rectangle(canvas, {x, top}, {x + kBarWidthPx, bottom}, scalar(kInk));
  if (z_max_mm == z_min_mm) {
    draw_text(canvas, format_fixed(z_min_mm, 2), {x + kBarWidthPx + 6, (top + bottom) / 2 + 5},
              0.45);
    return;
  }
  const std::vector<double> ticks = nice_ticks(z_min_mm, z_max_mm, 6);
  const double step = ticks.size() > 1 ? ticks[1] - ticks[0] : 1.0;
  for (double z : ticks) {
    const int y =
        bottom - static_cast<int>(std::lround((z - z_min_mm) / (z_max_mm - z_min_mm) * height));
    cv::line(canvas, {x + kBarWidthPx, y}, {x + kBarWidthPx + 5, y}, scalar(kInk));
    draw_text(canvas, format_tick(z, step), {x + kBarWidthPx + 8, y + 5}, 0.45);
  }
}

}  // namespace

BgrPicture render_range_picture(const RangeImage& image) {
  const FieldLayout layout =
      field_layout(image.width(), image.height(), image.pixel_size_x_mm, image.pixel_size_y_mm);
  if (layout.width == 0 || layout.height == 0) return to_picture(empty_field_canvas("range"));

  double z_min_mm = std::numeric_limits<double>::infinity();
  double z_max_mm = -z_min_mm;
  for (float z : image.z_mm.values()) {
    if (!std::isfinite(z)) continue;
    z_min_mm = std::min(z_min_mm, double(z));
    z_max_mm = std::max(z_max_mm, double(z));
  }
  const bool any_data = z_min_mm <= z_max_mm;
  const double span_mm = any_data ? z_max_mm - z_min_mm : 0.0;

  const cv::Mat colors = turbo_lookup();
  const int width_px = layout.origin_x_px + layout.display_width_px() + kPanelWidthPx;
  const int height_px =
      layout.origin_y_px + std::max(layout.display_height_px(), 300) + kFieldMarginPx;
  cv::Mat canvas = blank_canvas(width_px, height_px);
  paint_field(canvas, layout, [&](int column, int row) {
    const float z = image.z_mm(column, row);
    if (!std::isfinite(z)) return kNoDataColor;
    // A flat scene has no span: its single depth maps to the middle of the colour map.
    const double unit = span_mm > 0 ? (z - z_min_mm) / span_mm : 0.5;
    return lookup(colors, static_cast<int>(std::lround(unit * 255)));
  });

  const int bar_x = layout.origin_x_px + layout.display_width_px() + 20;
  const int bar_top = layout.origin_y_px + 30;
  const int bar_bottom = layout.origin_y_px + std::max(layout.display_height_px(), 300) - 10;
  if (any_data) {
    draw_colour_bar(canvas, colors, bar_x, bar_top, bar_bottom, z_min_mm, z_max_mm);
  } else {
    draw_text(canvas, "no data", {bar_x, bar_top}, 0.5);
  }
  return to_picture(canvas);
}

}  // namespace cosmos
