#include "sim/range_image_scan.hpp"

#include <algorithm>
#include <cmath>

namespace cosmos {

RangeImage scan_range_image(const ConveyorScene& scene, SimulatedScanner& scanner,
                            const ConditioningParameters& conditioning,
                            const RangeScanOptions& options, const ProfileObserver& observer) {
  const ScannerParameters& parameters = scanner.parameters();
  const ProfileRange range = profiles_covering(scene, parameters, options.scan_margin_mm);
  if (range.count() <= 0) return {};
  const int width = parameters.points_per_profile;
  const auto rows = static_cast<int>(range.count());
  PixelGrid<float> exposed(width, rows);  // row r = profile range.first + r
  PixelGrid<std::uint8_t> belt(width, rows, 0);
  Profile profile;
  scanner.reserve(profile);
  const auto background_mm = static_cast<float>(conditioning.height_threshold_mm);
  int first_row = rows;
  int last_row = -1;
  int first_column = width;
  int last_column = -1;
  for (int r = 0; r < rows; ++r) {
    const std::int64_t k = range.first + r;
    profile.seq = static_cast<std::uint64_t>(r);
    scanner.acquire(k, profile);
    if (observer) observer(k, profile, scanner);
    float* row = exposed.row(r);
    for (int i = 0; i < width; ++i) {
      const float z = profile.z_mm[static_cast<std::size_t>(i)];
      // NaN fails the comparison and stays NaN.
      row[i] = z >= background_mm ? z : Profile::kNoData;
      belt(i, r) = z < background_mm ? 1 : 0;  // NaN compares false: no data, not belt
      if (std::isnan(row[i])) continue;
      first_row = std::min(first_row, r);
      last_row = std::max(last_row, r);
      first_column = std::min(first_column, i);
      last_column = std::max(last_column, i);
    }
  }
  if (last_row < 0) return {};
  const int margin = std::max(options.crop_margin_px, 0);
  first_row = std::max(first_row - margin, 0);
  last_row = std::min(last_row + margin, rows - 1);
  first_column = std::max(first_column - margin, 0);
  last_column = std::min(last_column + margin, width - 1);

  const double step_mm = parameters.profile_step_mm();
  RangeImage image(last_column - first_column + 1, last_row - first_row + 1,
                   parameters.sample_spacing_mm(width), step_mm);
  image.origin_x_mm = parameters.first_sample_x_mm(width) + first_column * image.pixel_size_x_mm;
  // Image row 0 is the last exposed profile kept: the smallest y.
  image.origin_y_mm = laser_y_belt_mm(parameters, range.first + last_row);
  image.belt_seen = PixelGrid<std::uint8_t>(image.width(), image.height(), 0);
  for (int j = 0; j < image.height(); ++j) {
    const float* source = exposed.row(last_row - j) + first_column;
    std::copy(source, source + image.width(), image.z_mm.row(j));
    const std::uint8_t* belt_source = belt.row(last_row - j) + first_column;
    std::copy(belt_source, belt_source + image.width(), image.belt_seen.row(j));
  }
  return image;
}

}  // namespace cosmos
