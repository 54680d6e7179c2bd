#pragma once
// Range image files: a single-channel float32 TIFF or PFM (z in mm, NaN = no data) read and
// written through OpenCV, with the sidecar <stem>.yaml:
//   pixel_size_mm: [dx, dy]
//   origin_mm: [x0, y0]                      # optional, default [0, 0]
//   ground_truth: {part, rotation: [9 values row-major], translation_mm: [x, y, z]}  # optional
// Bad files throw InputError with one line naming the file and the reason.
#include <cstdint>
#include <filesystem>

#include "core/range_image.hpp"

namespace cosmos {

// The most pixels a range image file may declare (4096 x 4096; a scanner's widest profile
// over a whole belt's part is far below): a header claiming more is refused before decoding.
inline constexpr std::uint64_t kMaxRangeImagePixels = std::uint64_t{1} << 24;

std::filesystem::path sidecar_path(const std::filesystem::path& image_path);
RangeImage read_range_image(const std::filesystem::path& image_path);
void write_range_image(const RangeImage& image, const std::filesystem::path& image_path);

}  // namespace cosmos
