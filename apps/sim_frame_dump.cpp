#include "apps/sim_frame_dump.hpp"

#include <cmath>
#include <cstdio>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "core/input_error.hpp"

namespace cosmos::cli {

FrameDump::FrameDump(const std::filesystem::path& dir, int full_scale, int roi_row_offset_px)
    : dir_(dir), full_scale_(full_scale), roi_row_offset_px_(roi_row_offset_px) {
  std::error_code error;
  std::filesystem::create_directories(dir_, error);
  if (!std::filesystem::is_directory(dir_, error)) {
    throw InputError(dir_.string() + ": cannot create the frames directory");
  }
}

void FrameDump::write(std::uint64_t seq, const cv::Mat& frame, const StripePeaks& peaks) {
  cv::Mat grey;
  frame.convertTo(grey, CV_8U, 255.0 / full_scale_);
  cv::cvtColor(grey, picture_, cv::COLOR_GRAY2BGR);
  for (int i = 0; i < peaks.width(); ++i) {
    const float row = peaks.row_px[static_cast<std::size_t>(i)];
    if (std::isnan(row)) continue;
    const int r = static_cast<int>(std::lround(row)) - roi_row_offset_px_;
    const int c = peaks.column_offset_px + i;
    if (r >= 0 && r < picture_.rows && c >= 0 && c < picture_.cols)
      picture_.at<cv::Vec3b>(r, c) = {0, 0, 255};
  }
  char name[40];
  std::snprintf(name, sizeof name, "frame_%06llu.png", static_cast<unsigned long long>(seq));
  const std::filesystem::path path = dir_ / name;
  bool written = false;
  try {
    written = cv::imwrite(path.string(), picture_);
  } catch (const cv::Exception&) {
    written = false;
  }
  if (!written) throw InputError(path.string() + ": cannot be written");
  ++count_;
}

}  // namespace cosmos::cli
