#include "realtime/web/belt_tile.hpp"

#include <algorithm>
#include <cmath>

namespace cosmos {

int BeltStripGeometry::decimation_for(double strip_mm_per_pixel, double grid_mm) {
  return std::max(1, static_cast<int>(std::lround(strip_mm_per_pixel / grid_mm)));
}

BeltTile make_belt_tile(const RangeImage& part, std::int64_t first_profile,
                        const BeltStripGeometry& geometry) {
  const int d = geometry.decimation;
  const int rows = part.height();
  const int columns = part.width();
  BeltTile tile;
  tile.first_profile = first_profile;
  tile.last_profile = first_profile + rows - 1;
  tile.width_px = (rows + d - 1) / d;
  tile.height_px = (columns + d - 1) / d;
  // Loop column of the view's column 0; the view's last column is the tile's first strip row.
  const double c0 = (part.origin_x_mm - geometry.x0_loop_mm) / geometry.grid_mm;
  tile.top_px = (geometry.belt_columns - (c0 + columns)) / d;
  for (const float z : part.z_mm.values())
    if (std::isfinite(z)) tile.z_max_mm = std::max(tile.z_max_mm, static_cast<double>(z));
  tile.levels.assign(static_cast<std::size_t>(tile.width_px) * tile.height_px, 0);
  if (tile.z_max_mm <= 0) tile.z_max_mm = 1.0;
  for (int row = 0; row < rows; ++row) {
    const int column_px = (rows - 1 - row) / d;
    const float* z = part.z_mm.row(row);
    for (int column = 0; column < columns; ++column) {
      if (!std::isfinite(z[column])) continue;
      const int row_px = (columns - 1 - column) / d;
      const double fraction = std::clamp(z[column] / tile.z_max_mm, 0.0, 1.0);
      const auto level = static_cast<std::uint8_t>(1 + std::lround(fraction * 254));
      std::uint8_t& cell =
          tile.levels[static_cast<std::size_t>(row_px) * tile.width_px + column_px];
      cell = std::max(cell, level);
    }
  }
  return tile;
}

}  // namespace cosmos
