#include "realtime/cell/blob_regions.hpp"

#include <algorithm>
#include <cmath>

#include "core/recognition/explained_surface.hpp"

namespace cosmos {

Remaining remaining_of(const RangeImage& image, const std::vector<std::uint8_t>* excluded) {
  Remaining out;
  const int width = image.width();
  const int height = image.height();
  out.mask.assign(static_cast<std::size_t>(width) * height, 0);
  out.first_row = height;
  for (int row = 0; row < height; ++row) {
    for (int column = 0; column < width; ++column) {
      const float z = image.z_mm(column, row);
      const std::size_t pixel = static_cast<std::size_t>(row) * width + column;
      if (std::isnan(z) || (excluded && (*excluded)[pixel])) continue;
      out.mask[pixel] = 1;
      ++out.pixels;
      out.centroid_mm += Eigen::Vector3d(image.x_mm(column), image.y_mm(row), z);
      out.first_row = std::min(out.first_row, row);
      out.last_row = std::max(out.last_row, row);
    }
  }
  if (out.pixels > 0) out.centroid_mm /= static_cast<double>(out.pixels);
  out.interior_mm2 = static_cast<double>(interior_pixels(out.mask, width, height)) *
                     image.pixel_size_x_mm * image.pixel_size_y_mm;
  return out;
}

std::vector<Eigen::Vector3d> sampled_points(const RangeImage& image) {
  std::vector<Eigen::Vector3d> points_mm;
  for (int row = 0; row < image.height(); row += 2)
    for (int column = 0; column < image.width(); column += 2)
      if (const float z = image.z_mm(column, row); !std::isnan(z))
        points_mm.emplace_back(image.x_mm(column), image.y_mm(row), z);
  return points_mm;
}

std::vector<int> necks(const std::vector<int>& count) {
  constexpr double kNeckFraction = 0.2;
  constexpr int kEnd = 40;  // 16 mm at 0.4 mm: a part is longer and wider than that
  const int widest = count.empty() ? 0 : *std::max_element(count.begin(), count.end());
  int first = -1, last = -1;
  for (int k = 0; k < static_cast<int>(count.size()); ++k)
    if (count[static_cast<std::size_t>(k)] > 0) {
      if (first < 0) first = k;
      last = k;
    }
  const auto narrow = [&](int k) {
    return count[static_cast<std::size_t>(k)] <= kNeckFraction * widest;
  };
  std::vector<int> cuts;
  for (int k = first + kEnd; k < last - kEnd; ++k) {
    if (!narrow(k)) continue;
    int narrowest = k;
    for (; k < last - kEnd && narrow(k); ++k)
      if (count[static_cast<std::size_t>(k)] < count[static_cast<std::size_t>(narrowest)])
        narrowest = k;
    if (cuts.empty() || narrowest - cuts.back() >= kEnd) cuts.push_back(narrowest);
  }
  return cuts;
}

std::vector<int> pixels_per(const RangeImage& image, bool rows) {
  std::vector<int> count(static_cast<std::size_t>(rows ? image.height() : image.width()), 0);
  for (int row = 0; row < image.height(); ++row)
    for (int column = 0; column < image.width(); ++column)
      if (!std::isnan(image.z_mm(column, row)))
        ++count[static_cast<std::size_t>(rows ? row : column)];
  return count;
}

}  // namespace cosmos
