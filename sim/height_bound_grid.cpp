#include "sim/height_bound_grid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace cosmos {

HeightBoundGrid::HeightBoundGrid(const TriangleMesh& mesh, const Eigen::Isometry3d& T_belt_part,
                                 double cell_mm)
    : cell_mm_(cell_mm) {
  if (!(cell_mm > 0.0)) throw std::invalid_argument("HeightBoundGrid: cell_mm must be > 0");
  std::vector<Eigen::Vector3d> placed;
  placed.reserve(mesh.vertices.size());
  Eigen::AlignedBox3d box;
  for (const Eigen::Vector3f& v : mesh.vertices) {
    placed.push_back(T_belt_part * v.cast<double>());
    box.extend(placed.back());
  }
  if (placed.empty()) return;
  // One spare cell on each side: float rounding of a vertex on a cell border stays inside.
  x0_mm_ = box.min().x() - cell_mm;
  y0_mm_ = box.min().y() - cell_mm;
  columns_ = static_cast<int>(std::ceil((box.max().x() - x0_mm_) / cell_mm)) + 2;
  rows_ = static_cast<int>(std::ceil((box.max().y() - y0_mm_) / cell_mm)) + 2;
  max_z_mm_ = box.max().z();
  heights_.assign(static_cast<std::size_t>(columns_) * static_cast<std::size_t>(rows_),
                  -std::numeric_limits<float>::infinity());
  for (const Eigen::Vector3i& triangle : mesh.triangles) {
    Eigen::AlignedBox3d t;
    for (int k = 0; k < 3; ++k) t.extend(placed[static_cast<std::size_t>(triangle[k])]);
    const int ix0 = static_cast<int>(std::floor((t.min().x() - x0_mm_) / cell_mm));
    const int ix1 = static_cast<int>(std::floor((t.max().x() - x0_mm_) / cell_mm));
    const int iy0 = static_cast<int>(std::floor((t.min().y() - y0_mm_) / cell_mm));
    const int iy1 = static_cast<int>(std::floor((t.max().y() - y0_mm_) / cell_mm));
    const auto top = static_cast<float>(t.max().z());
    for (int iy = std::max(iy0, 0); iy <= std::min(iy1, rows_ - 1); ++iy) {
      for (int ix = std::max(ix0, 0); ix <= std::min(ix1, columns_ - 1); ++ix) {
        float& height = heights_[static_cast<std::size_t>(iy) * columns_ + ix];
        height = std::max(height, top);
      }
    }
  }
  first_column_.assign(static_cast<std::size_t>(rows_), -1);
  last_column_.assign(static_cast<std::size_t>(rows_), -1);
  for (int iy = 0; iy < rows_; ++iy) {
    for (int ix = 0; ix < columns_; ++ix) {
      if (cell(ix, iy) == -std::numeric_limits<float>::infinity()) continue;
      if (first_column_[static_cast<std::size_t>(iy)] < 0)
        first_column_[static_cast<std::size_t>(iy)] = ix;
      last_column_[static_cast<std::size_t>(iy)] = ix;
    }
  }
}

bool HeightBoundGrid::x_extent(double y_mm, double& x_low, double& x_high) const {
  const auto iy = static_cast<int>(std::floor((y_mm - y0_mm_) / cell_mm_));
  if (iy < 0 || iy >= rows_ || first_column_[static_cast<std::size_t>(iy)] < 0) return false;
  x_low = x0_mm_ + first_column_[static_cast<std::size_t>(iy)] * cell_mm_;
  x_high = x0_mm_ + (last_column_[static_cast<std::size_t>(iy)] + 1) * cell_mm_;
  return true;
}

HeightBoundGrid::BeltSight HeightBoundGrid::belt_sight(double y_mm,
                                                       const Eigen::Vector3d& camera_mm) const {
  BeltSight sight;
  sight.y_mm = y_mm;
  sight.camera_mm = camera_mm;
  if (heights_.empty() || !(camera_mm.z() > 0.0)) return sight;
  // y(s) = y + s (camera_y - y) inside [y0, y0 + rows cell]; z(s) = s camera_z <= max_z.
  double s_begin = 0.0;
  double s_end = std::min(1.0, max_z_mm_ / camera_mm.z());
  const double dy = camera_mm.y() - y_mm;
  const double y_low = y0_mm_;
  const double y_high = y0_mm_ + rows_ * cell_mm_;
  if (dy == 0.0) {
    if (y_mm < y_low || y_mm > y_high) return sight;
  } else {
    double s0 = (y_low - y_mm) / dy;
    double s1 = (y_high - y_mm) / dy;
    if (s0 > s1) std::swap(s0, s1);
    s_begin = std::max(s_begin, s0);
    s_end = std::min(s_end, s1);
  }
  sight.s_begin = s_begin;
  sight.s_end = s_end;
  return sight;
}

bool HeightBoundGrid::may_block(const BeltSight& sight, double x_mm) const {
  if (sight.s_end < sight.s_begin) return false;
  const double dx = sight.camera_mm.x() - x_mm;
  const double x_a = x_mm + sight.s_begin * dx;
  const double x_b = x_mm + sight.s_end * dx;
  return std::max(x_a, x_b) >= x0_mm_ && std::min(x_a, x_b) <= x0_mm_ + columns_ * cell_mm_;
}

void HeightBoundGrid::mark_belt_sights(const BeltSight& sight, double x0_mm, double dx_mm,
                                       int samples, int* difference) const {
  if (sight.s_end < sight.s_begin) return;
  const Eigen::Vector3d& camera = sight.camera_mm;
  const double dy = camera.y() - sight.y_mm;
  // A line of sight from (x, y, 0) is over (x (1 - s) + s cx, y + s dy) at height s cz.
  const auto first_row = static_cast<int>(std::floor(
      (sight.y_mm + std::min(sight.s_begin * dy, sight.s_end * dy) - y0_mm_) / cell_mm_));
  const auto last_row = static_cast<int>(std::floor(
      (sight.y_mm + std::max(sight.s_begin * dy, sight.s_end * dy) - y0_mm_) / cell_mm_));
  for (int iy = std::max(first_row, 0); iy <= std::min(last_row, rows_ - 1); ++iy) {
    const int row_first = first_column_[static_cast<std::size_t>(iy)];
    if (row_first < 0) continue;
    double s_low = sight.s_begin;
    double s_high = sight.s_end;
    if (dy != 0.0) {
      const double s0 = (y0_mm_ + iy * cell_mm_ - sight.y_mm) / dy;
      const double s1 = (y0_mm_ + (iy + 1) * cell_mm_ - sight.y_mm) / dy;
      s_low = std::max(s_low, std::min(s0, s1));
      s_high = std::min(s_high, std::max(s0, s1));
    }
    if (!(s_low <= s_high) || !(s_high < 1.0)) continue;
    const double lowest_z = s_low * camera.z();
    const double inverse_low = 1.0 / (1.0 - s_low);
    const double inverse_camera_z = 1.0 / camera.z();
    // Clamped as doubles: near s = 1 the interval can reach far beyond any int.
    const auto sample_index = [&](double index) {
      return static_cast<int>(std::clamp(index, -1.0, static_cast<double>(samples)));
    };
    for (int ix = row_first; ix <= last_column_[static_cast<std::size_t>(iy)]; ++ix) {
      const double height = cell(ix, iy);
      if (!(height >= lowest_z)) continue;
      // Over this cell the sight is at height <= the bound for s in [s_low, s_top].
      const double s_top = std::min(s_high, height * inverse_camera_z);
      const double inverse_top = 1.0 / (1.0 - s_top);
      const double cell_low = x0_mm_ + ix * cell_mm_;
      const double cell_high = cell_low + cell_mm_;
      // x(s) meets [cell_low, cell_high] for some s in [s_low, s_top] iff x lies between these.
      const double x_low = std::min((cell_low - s_low * camera.x()) * inverse_low,
                                    (cell_low - s_top * camera.x()) * inverse_top);
      const double x_high = std::max((cell_high - s_low * camera.x()) * inverse_low,
                                     (cell_high - s_top * camera.x()) * inverse_top);
      const int first = std::max(0, sample_index(std::floor((x_low - x0_mm) / dx_mm) - 1.0));
      const int last =
          std::min(samples - 1, sample_index(std::ceil((x_high - x0_mm) / dx_mm) + 1.0));
      if (first > last) continue;
      ++difference[first];
      --difference[last + 1];
    }
  }
}

bool HeightBoundGrid::clears(const Eigen::Vector3d& from, const Eigen::Vector3d& to) const {
  if (heights_.empty()) return true;
  // Clip to the grid's box (z up to the part's top) first: a line of sight from far away
  // walks no empty cells.
  const Eigen::Vector3d low(x0_mm_, y0_mm_, -std::numeric_limits<double>::infinity());
  const Eigen::Vector3d high(x0_mm_ + columns_ * cell_mm_, y0_mm_ + rows_ * cell_mm_, max_z_mm_);
  double s_enter = 0.0;
  double s_exit = 1.0;
  for (int axis = 0; axis < 3; ++axis) {
    const double d = to(axis) - from(axis);
    if (d == 0.0) {
      if (from(axis) < low(axis) || from(axis) > high(axis)) return true;
      continue;
    }
    const double inverse = 1.0 / d;
    double s0 = (low(axis) - from(axis)) * inverse;
    double s1 = (high(axis) - from(axis)) * inverse;
    if (s0 > s1) std::swap(s0, s1);
    s_enter = std::max(s_enter, s0);
    s_exit = std::min(s_exit, s1);
    if (s_enter > s_exit) return true;
  }
  // Amanatides–Woo walk through the cells under the clipped segment, in grid units.
  const double gx = (from.x() + s_enter * (to.x() - from.x()) - x0_mm_) / cell_mm_;
  const double gy = (from.y() + s_enter * (to.y() - from.y()) - y0_mm_) / cell_mm_;
  const double dx = (to.x() - from.x()) / cell_mm_;
  const double dy = (to.y() - from.y()) / cell_mm_;
  int ix = std::clamp(static_cast<int>(std::floor(gx)), 0, columns_ - 1);
  int iy = std::clamp(static_cast<int>(std::floor(gy)), 0, rows_ - 1);
  const int step_x = dx > 0.0 ? 1 : -1;
  const int step_y = dy > 0.0 ? 1 : -1;
  constexpr double kNever = std::numeric_limits<double>::infinity();
  const double delta_x = dx != 0.0 ? 1.0 / std::abs(dx) : kNever;
  const double delta_y = dy != 0.0 ? 1.0 / std::abs(dy) : kNever;
  double next_x = dx != 0.0 ? s_enter + (dx > 0.0 ? ix + 1 - gx : gx - ix) * delta_x : kNever;
  double next_y = dy != 0.0 ? s_enter + (dy > 0.0 ? iy + 1 - gy : gy - iy) * delta_y : kNever;
  double s = s_enter;
  while (s <= s_exit && ix >= 0 && iy >= 0 && ix < columns_ && iy < rows_) {
    // The segment rises, so its lowest point over a cell is where it enters it.
    if (from.z() + s * (to.z() - from.z()) <= cell(ix, iy)) return false;
    if (next_x < next_y) {
      s = next_x;
      next_x += delta_x;
      ix += step_x;
    } else {
      s = next_y;
      next_y += delta_y;
      iy += step_y;
    }
  }
  return true;
}

}  // namespace cosmos
