#include "core/render/csmp_picture.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <string>

#include "core/render/picture_drawing.hpp"
#include "core/render/shape_category_palette.hpp"

namespace cosmos {
namespace {

using namespace render;

constexpr int kCaptionHeightPx = 40;

// A boundary is drawn as a strip on each side of the shared pixel edge; thick enough to see on
// strongly upscaled scans, one pixel on full-size ones (the pixel itself, as at scale 1 the
// strip is the whole pixel).
int boundary_strip_px(int scale) { return std::clamp(scale / 10, 1, 3); }

void draw_boundaries(cv::Mat& canvas, const FieldLayout& layout,
                     const PixelGrid<std::int32_t>& labels) {
  const cv::Scalar dark = scalar(kBoundaryColor);
  const int strip_x = boundary_strip_px(layout.scale_x);
  const int strip_y = boundary_strip_px(layout.scale_y);
  const auto other_patch = [&](std::int32_t own, int column, int row) {
    if (!labels.contains(column, row)) return false;
    const std::int32_t other = labels(column, row);
    return other != kNoPatch && other != own;
  };
  for (int row = 0; row < layout.height; ++row) {
    for (int column = 0; column < layout.width; ++column) {
      const std::int32_t own = labels(column, row);
      if (own == kNoPatch) continue;
      const int x0 = layout.origin_x_px + column * layout.scale_x;
      const int y0 = layout.origin_y_px + row * layout.scale_y;
      const int x1 = x0 + layout.scale_x - 1;
      const int y1 = y0 + layout.scale_y - 1;
      if (other_patch(own, column - 1, row))
        cv::rectangle(canvas, {x0, y0}, {x0 + strip_x - 1, y1}, dark, cv::FILLED);
      if (other_patch(own, column + 1, row))
        cv::rectangle(canvas, {x1 - strip_x + 1, y0}, {x1, y1}, dark, cv::FILLED);
      if (other_patch(own, column, row - 1))
        cv::rectangle(canvas, {x0, y0}, {x1, y0 + strip_y - 1}, dark, cv::FILLED);
      if (other_patch(own, column, row + 1))
        cv::rectangle(canvas, {x0, y1 - strip_y + 1}, {x1, y1}, dark, cv::FILLED);
    }
  }
}

// Distance of every patch pixel to the nearest pixel outside its patch (another patch, no
// patch or the image border), in pixels; 0 outside patches.
cv::Mat distance_inside_patch(const PixelGrid<std::int32_t>& labels) {
  cv::Mat interior(labels.height(), labels.width(), CV_8UC1, cv::Scalar(0));
  const auto same = [&](std::int32_t own, int column, int row) {
    return labels.contains(column, row) && labels(column, row) == own;
  };
  for (int row = 0; row < labels.height(); ++row) {
    for (int column = 0; column < labels.width(); ++column) {
      const std::int32_t own = labels(column, row);
      const bool inner = own != kNoPatch && same(own, column - 1, row) &&
                         same(own, column + 1, row) && same(own, column, row - 1) &&
                         same(own, column, row + 1);
      interior.at<std::uint8_t>(row, column) = inner ? 255 : 0;
    }
  }
  cv::Mat distance;
  cv::distanceTransform(interior, distance, cv::DIST_L2, cv::DIST_MASK_PRECISE);
  return distance;
}

void place_label_anchors(const PixelGrid<std::int32_t>& labels,
                         std::vector<PatchPixelCentroid>& centroids) {
  // A label needs this much room around its anchor (pixels) to sit inside the patch.
  constexpr float kClearancePx = 2.0f;
  const cv::Mat distance = distance_inside_patch(labels);
  std::vector<int> slot(
      centroids.empty() ? 0 : static_cast<std::size_t>(centroids.back().patch + 1), -1);
  for (std::size_t i = 0; i < centroids.size(); ++i)
    slot[static_cast<std::size_t>(centroids[i].patch)] = static_cast<int>(i);
  std::vector<float> best_distance(centroids.size(), -1.0f);
  std::vector<double> best_offset2(centroids.size(), 0.0);
  for (int row = 0; row < labels.height(); ++row) {
    for (int column = 0; column < labels.width(); ++column) {
      const std::int32_t id = labels(column, row);
      if (id < 0) continue;
      const std::size_t i = static_cast<std::size_t>(slot[static_cast<std::size_t>(id)]);
      PatchPixelCentroid& c = centroids[i];
      const float d = distance.at<float>(row, column);
      const double offset2 =
          (column - c.column) * (column - c.column) + (row - c.row) * (row - c.row);
      // Most interior pixel; among equals the one nearest the centroid, then raster order.
      if (d > best_distance[i] || (d == best_distance[i] && offset2 < best_offset2[i])) {
        best_distance[i] = d;
        best_offset2[i] = offset2;
        c.label_column = column;
        c.label_row = row;
      }
    }
  }
  for (std::size_t i = 0; i < centroids.size(); ++i) {
    PatchPixelCentroid& c = centroids[i];
    const int column = static_cast<int>(std::lround(c.column));
    const int row = static_cast<int>(std::lround(c.row));
    const bool centroid_inside =
        labels.contains(column, row) && labels(column, row) == c.patch &&
        distance.at<float>(row, column) >= std::min(kClearancePx, best_distance[i]);
    if (centroid_inside) {
      c.label_column = c.column;
      c.label_row = c.row;
    }
  }
}

}  // namespace

std::vector<PatchPixelCentroid> patch_pixel_centroids(
    const PixelGrid<std::int32_t>& patch_of_pixel) {
  std::int32_t max_id = kNoPatch;
  for (std::int32_t id : patch_of_pixel.values()) max_id = std::max(max_id, id);
  std::vector<PatchPixelCentroid> sums(static_cast<std::size_t>(max_id + 1));
  for (int row = 0; row < patch_of_pixel.height(); ++row) {
    for (int column = 0; column < patch_of_pixel.width(); ++column) {
      const std::int32_t id = patch_of_pixel(column, row);
      if (id < 0) continue;
      PatchPixelCentroid& sum = sums[static_cast<std::size_t>(id)];
      sum.column += column;
      sum.row += row;
      ++sum.pixels;
    }
  }
  std::vector<PatchPixelCentroid> centroids;
  for (std::size_t id = 0; id < sums.size(); ++id) {
    const PatchPixelCentroid& sum = sums[id];
    if (sum.pixels == 0) continue;
    const double column = sum.column / sum.pixels;
    const double row = sum.row / sum.pixels;
    centroids.push_back({static_cast<int>(id), column, row, sum.pixels, column, row});
  }
  place_label_anchors(patch_of_pixel, centroids);
  return centroids;
}

BgrPicture render_csmp_picture(const CsmpSegmentation& segmentation, double pixel_size_x_mm,
                               double pixel_size_y_mm) {
  const PixelGrid<std::int32_t>& labels = segmentation.patch_of_pixel;
  const FieldLayout layout =
      field_layout(labels.width(), labels.height(), pixel_size_x_mm, pixel_size_y_mm);
  if (layout.width == 0 || layout.height == 0) return to_picture(empty_field_canvas("CSMPs"));

  const int width_px = layout.origin_x_px + layout.display_width_px() + kFieldMarginPx;
  const int height_px = layout.origin_y_px + layout.display_height_px() + kCaptionHeightPx;
  cv::Mat canvas = blank_canvas(std::max(width_px, 360), height_px);
  paint_field(canvas, layout, [&](int column, int row) {
    const std::int32_t id = labels(column, row);
    return id == kNoPatch ? kNoDataColor : patch_color(id);
  });
  draw_boundaries(canvas, layout, labels);

  const std::vector<PatchPixelCentroid> centroids = patch_pixel_centroids(labels);
  for (const PatchPixelCentroid& centroid : centroids) {
    const cv::Point centre{
        layout.origin_x_px +
            static_cast<int>(std::lround((centroid.label_column + 0.5) * layout.scale_x)),
        layout.origin_y_px +
            static_cast<int>(std::lround((centroid.label_row + 0.5) * layout.scale_y))};
    draw_haloed_text(canvas, std::to_string(centroid.patch), centre, 0.5);
  }
  draw_text(canvas,
            std::to_string(centroids.size()) + " CSMPs, shape diameter limit " +
                format_fixed(segmentation.shape_diameter_limit, 3),
            {layout.origin_x_px, height_px - 14}, 0.45);
  return to_picture(canvas);
}

}  // namespace cosmos
