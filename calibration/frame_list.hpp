#pragma once
// Recorded frames on disk, as `cosmos calibrate` reads them from a real cell (and the
// simulator writes them): a directory with one image per frame (PNG, 8- or 16-bit grey) and
// frames.csv listing them in exposure order,
//   file,encoder_ticks,roi_top_px
//   frame-0000.png,0,51
// where roi_top_px is the sensor row of the image's first row. A missing directory, list or
// image, or a malformed line, is InputError naming the file (and line).
#include <filesystem>
#include <vector>

#include "calibration/stripe_frame.hpp"

namespace cosmos {

std::vector<StripeFrame> read_frame_list(const std::filesystem::path& directory);
void write_frame_list(const std::filesystem::path& directory,
                      const std::vector<StripeFrame>& frames);

// Every *.png of `directory`, sorted by name, as grey images (InputError when none).
std::vector<std::filesystem::path> png_files(const std::filesystem::path& directory);
cv::Mat read_grey_image(const std::filesystem::path& file);

}  // namespace cosmos
