#pragma once
// One recognized part's patch of the web view's belt strip: its view image (only its own
// pixels, as the recognizer cut it out) decimated to the strip's pixel and turned from the
// loop frame into the strip's orientation.
//
// The strip is the belt seen from above, the laser sheet at its left edge: strip columns run
// downstream along +y_belt (a profile p lies (head - p) · grid_mm behind the sheet when the
// head profile is exposed), strip rows across the belt along +x_belt, so that +x down and +y
// right keep z towards the viewer (no mirror image). The loop frame mirrors x (x_L = −x_belt,
// realtime/loop/scan_loop.hpp) and lists rows in arrival order, i.e. upstream first: a tile's
// first strip column holds the part's last profile.
//
// The conditioner has already removed the belt (realtime/loop/profile_conditioner.hpp), so
// the strip built from the parts' views shows what a strip of every conditioned row would:
// the parts on empty belt, without touching the acquisition thread.
#include <cstdint>
#include <vector>

#include "core/range_image.hpp"

namespace cosmos {

// The cell's grid and the strip's pixel.
struct BeltStripGeometry {
  double grid_mm = 0.4;     // belt step per profile and column pitch (conditioning.grid_mm)
  int belt_columns = 0;     // the loop's row width, columns
  double x0_loop_mm = 0.0;  // x_L of loop column 0 (ScanLoop::x0_loop_mm)
  int decimation = 4;       // grid cells per strip pixel, along and across

  // Grid cells per strip pixel for a wished pixel size: whole cells, at least one.
  static int decimation_for(double strip_mm_per_pixel, double grid_mm);
  double mm_per_pixel() const { return grid_mm * decimation; }
  int belt_width_px() const { return (belt_columns + decimation - 1) / decimation; }
};

struct BeltTile {
  std::int64_t first_profile = 0;  // the source's profile index of the part's first row
  std::int64_t last_profile = -1;
  double top_px = 0;  // strip row of the tile's first row
  int width_px = 0;   // along the belt
  int height_px = 0;  // across the belt
  double z_max_mm = 0;
  // height_px rows of width_px: 0 where the part has no pixel, else 1 + the block's highest
  // z as a fraction of z_max_mm in 254 steps.
  std::vector<std::uint8_t> levels;

  std::uint8_t level(int column_px, int row_px) const {
    return levels[static_cast<std::size_t>(row_px) * width_px + column_px];
  }
};

// `part` is PartRecognition::image (loop frame, its row 0 the source's profile first_profile).
BeltTile make_belt_tile(const RangeImage& part, std::int64_t first_profile,
                        const BeltStripGeometry& geometry);

}  // namespace cosmos
