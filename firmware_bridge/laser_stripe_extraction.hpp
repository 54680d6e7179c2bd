#pragma once
// Laser-stripe extraction: the sub-pixel row of the laser line in every column of a camera
// frame. The laser sheet crosses the sensor roughly along its rows, so each sensor column
// sees one intensity peak (or none where the surface is occluded or dark); the peak's
// sub-pixel row is what triangulation turns into a height.
//
// The same code runs on real V4L2 frames and on frames drawn by the simulator, so the
// simulated cell exercises the hardware path. It runs once per camera frame on the
// acquisition thread: no allocation after the first frame, no exceptions.
#include <cstdint>
#include <opencv2/core/mat.hpp>
#include <span>
#include <vector>

#include "core/parameter_visitor.hpp"

namespace cosmos {

enum class StripePeakMethod : std::uint8_t {
  // Intensity-minus-threshold weighted mean of the rows of the contiguous above-threshold run
  // containing the maximum (within the window). Uses every stripe pixel: robust to noise.
  kCentreOfGravity,
  // Log-parabola through the maximum and its two neighbours: exact for a Gaussian stripe
  // without background, uses three pixels only.
  kGaussianThreePoint,
};

inline std::span<const ParameterChoice<StripePeakMethod>> parameter_choices(StripePeakMethod) {
  static constexpr ParameterChoice<StripePeakMethod> kChoices[] = {
      {StripePeakMethod::kCentreOfGravity, "centre_of_gravity"},
      {StripePeakMethod::kGaussianThreePoint, "gaussian_three_point"}};
  return kChoices;
}

struct StripeExtractionParameters {
  StripePeakMethod method = StripePeakMethod::kCentreOfGravity;
  // Grey levels of the frame's own type (an 8-bit default; a 16-bit camera sets its own).
  // Pixels at or below the threshold carry no weight and end the centre-of-gravity run.
  int threshold = 20;
  // A column whose maximum is below this has no stripe (dark surface, occlusion).
  int min_peak_intensity = 40;
  // Rows either side of the maximum that the centre of gravity may use: bounds the work per
  // column and keeps a second reflection further away out of the estimate.
  int window_half_width_px = 8;
  // Intensity at which the sensor clips. 0 = the maximum of the frame's type (255 or 65535);
  // a 10- or 12-bit sensor delivered in 16-bit words sets 1023 or 4095.
  int saturation_level = 0;

  // The keys of a hardware YAML's `stripe:` section. The ranges are a 16-bit frame's; the
  // reader narrows them to its pixel format's full scale, from which saturation_level comes.
  template <class Visitor>
  void visit(Visitor& v) {
    v("method", method, "centre_of_gravity, or gaussian_three_point (exact for a Gaussian)");
    v("threshold", threshold, "grey level at or below which a pixel has no weight",
      Range{0, 65534});
    v("min_peak_intensity", min_peak_intensity, "a dimmer column maximum is no stripe",
      Range{1, 65535});
    v("window_half_width_px", window_half_width_px,
      "rows either side of the maximum the peak may use", Range{1, 64});
  }
};

// Sensor coordinates of pixel (0, 0) of a frame: cameras deliver region-of-interest frames,
// and triangulation needs full-sensor coordinates.
struct FrameRoi {
  int row_offset_px = 0;
  int column_offset_px = 0;
};

// Per frame column i (sensor column = column_offset_px + i): the stripe's sub-pixel sensor
// row, NaN where there is no valid peak, and the peak intensity (grey levels, 0 if none).
// saturated_columns counts the columns whose maximum reached the saturation level: an
// exposure indicator. Owned by the caller and reused frame after frame.
struct StripePeaks {
  int column_offset_px = 0;
  std::vector<float> row_px;
  std::vector<float> peak_intensity;
  int valid_columns = 0;
  int saturated_columns = 0;

  int width() const { return static_cast<int>(row_px.size()); }
  double sensor_column_px(int i) const { return column_offset_px + i; }
};

enum class StripeExtractionStatus : std::uint8_t {
  kOk,
  kEmptyFrame,
  kUnsupportedType,  // not single-channel CV_8U / CV_16U
  kTooManyRows,      // the per-column arg-max is kept in 16 bits
};

class LaserStripeExtractor {
 public:
  explicit LaserStripeExtractor(const StripeExtractionParameters& parameters = {});

  // Allocates the scratch and output buffers for frames up to `max_columns` wide, so that
  // even the first frame does not allocate.
  void reserve(int max_columns, StripePeaks& peaks);

  // Finds the stripe in every column of `frame`. `peaks` is resized to frame.cols (allocates
  // only when wider than ever before). Never throws.
  StripeExtractionStatus extract(const cv::Mat& frame, const FrameRoi& roi,
                                 StripePeaks& peaks) noexcept;

  const StripeExtractionParameters& parameters() const { return parameters_; }

 private:
  template <class Pixel>
  void extract_typed(const cv::Mat& frame, const FrameRoi& roi, StripePeaks& peaks) noexcept;

  StripeExtractionParameters parameters_;
  // Column-wise running maximum and its first row, filled row by row so the whole-frame
  // pass reads memory contiguously and vectorizes (16-bit lanes for both arrays).
  std::vector<std::uint16_t> column_max_;
  std::vector<std::uint16_t> column_argmax_;
};

}  // namespace cosmos
