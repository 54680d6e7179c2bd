#pragma once
// Where a per-pixel field (range, shape index, CSMP labels) lands in its picture: every image
// pixel becomes a block of scale_x by scale_y picture pixels, so small scans stay crisp
// (nearest neighbour), and the block shape follows the physical pixel aspect (dy / dx), so a
// scan with coarse encoder steps is not drawn squashed.
namespace cosmos {

// The short side of a field picture reaches at least this, unless the long side would then
// exceed kMaxFieldSidePx.
inline constexpr int kMinFieldSidePx = 400;
inline constexpr int kMaxFieldSidePx = 3000;
// The field sits this far from the picture's top-left corner; legends go to its right.
inline constexpr int kFieldMarginPx = 12;

struct FieldLayout {
  int width = 0;  // field size in image pixels
  int height = 0;
  int scale_x = 1;  // picture pixels per image pixel
  int scale_y = 1;
  int origin_x_px = kFieldMarginPx;
  int origin_y_px = kFieldMarginPx;

  int display_width_px() const { return width * scale_x; }
  int display_height_px() const { return height * scale_y; }
  // Picture coordinates of the centre of image pixel (column, row).
  int centre_x_px(int column) const { return origin_x_px + column * scale_x + scale_x / 2; }
  int centre_y_px(int row) const { return origin_y_px + row * scale_y + scale_y / 2; }
};

FieldLayout field_layout(int width, int height, double pixel_size_x_mm, double pixel_size_y_mm);

}  // namespace cosmos
