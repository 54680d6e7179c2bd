#pragma once
// A camera frame as the cv::Mat the stripe extractor reads, without copying: the Mat is a
// header over the driver's buffer (no reference count, no allocation), valid exactly as long
// as the FrameView. 10/12/16-bit frames become CV_16U; the stripe extractor's
// saturation_level should then be set from FrameView::significant_bits().
#include <opencv2/core/mat.hpp>

#include "firmware_bridge/camera.hpp"
#include "firmware_bridge/laser_stripe_extraction.hpp"

namespace cosmos {

inline cv::Mat frame_as_mat(const FrameView& frame) {
  const int type = frame.bytes_per_pixel() == 1 ? CV_8UC1 : CV_16UC1;
  // OpenCV's external-data constructor takes a non-const pointer but never writes through it
  // unless the caller does; the stripe extractor only reads.
  return cv::Mat(frame.height_px, frame.width_px, type, const_cast<std::uint8_t*>(frame.data),
                 static_cast<std::size_t>(frame.bytes_per_line));
}

inline FrameRoi frame_roi(const FrameView& frame) noexcept {
  return {frame.roi_top_px, frame.roi_left_px};
}

}  // namespace cosmos
