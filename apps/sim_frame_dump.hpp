#pragma once
// `cosmos sim scan --mode camera --frames DIR`: every camera frame of the scan as a PNG,
// grey levels scaled to 8 bits, with the stripe the extractor found drawn in red (one pixel
// per column at its sub-pixel row, rounded), so a user sees what the firmware path saw.
#include <cstdint>
#include <filesystem>
#include <opencv2/core/mat.hpp>

#include "firmware_bridge/laser_stripe_extraction.hpp"

namespace cosmos::cli {

class FrameDump {
 public:
  // Creates `dir` if needed (InputError naming it when impossible). full_scale: the frames'
  // saturation level; roi_row_offset_px: the sensor row of frame row 0.
  FrameDump(const std::filesystem::path& dir, int full_scale, int roi_row_offset_px);

  // Writes DIR/frame_<seq>.png. InputError naming the file when it cannot be written.
  void write(std::uint64_t seq, const cv::Mat& frame, const StripePeaks& peaks);
  int count() const { return count_; }

 private:
  std::filesystem::path dir_;
  int full_scale_;
  int roi_row_offset_px_;
  int count_ = 0;
  cv::Mat picture_;
};

}  // namespace cosmos::cli
