#pragma once
// One camera frame of the laser stripe as a calibration reads it: the image (the camera's
// rows from roi_top_px) and the encoder count at its exposure. Real frames come from a
// frame list (calibration/frame_list.hpp), simulated ones from sim/calibration_targets.
#include <cstdint>
#include <opencv2/core/mat.hpp>

namespace cosmos {

struct StripeFrame {
  cv::Mat image;
  int roi_top_px = 0;
  std::int64_t encoder_ticks = 0;
};

}  // namespace cosmos
