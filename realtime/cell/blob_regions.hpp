#pragma once
// What the scene loop over a blob (blob_recognition.hpp) measures of a region of it, a range
// image holding only the region's pixels: which pixels remain and how much area their interior
// covers, where the region narrows to necks (touching parts meet in a few pixels), and its
// surface sampled as points.
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "core/range_image.hpp"

namespace cosmos {

// The pixels of an image that hold data, their centroid (the image's frame) and row range.
struct Remaining {
  std::vector<std::uint8_t> mask;  // 1 per pixel with data, row-major
  std::int64_t pixels = 0;
  double interior_mm2 = 0;  // of the pixels whose 8 neighbours hold data too
  Eigen::Vector3d centroid_mm = Eigen::Vector3d::Zero();
  int first_row = 0;
  int last_row = -1;
};
// With `excluded` (one flag per pixel), only the pixels it does not flag: what remains of the
// image once those are taken away, without a new image.
Remaining remaining_of(const RangeImage& image,
                       const std::vector<std::uint8_t>* excluded = nullptr);

// The image's surface in its frame, every other pixel each way.
std::vector<Eigen::Vector3d> sampled_points(const RangeImage& image);

// The image's data pixels per row (rows) or per column.
std::vector<int> pixels_per(const RangeImage& image, bool rows);

// Where a region narrows to a neck along one axis (rows: along the belt, parts touching end
// to end; columns: across it, parts side by side), from its pixel counts per row (or
// column): counts at most a fifth of the largest, one cut per neck at its narrowest, none
// within 40 rows (16 mm at 0.4 mm, less than any part's length or width) of the region's
// ends or of the previous cut.
std::vector<int> necks(const std::vector<int>& count);

}  // namespace cosmos
