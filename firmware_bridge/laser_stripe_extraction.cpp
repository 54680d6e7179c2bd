#include "firmware_bridge/laser_stripe_extraction.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace cosmos {
namespace {

constexpr float kNoPeak = std::numeric_limits<float>::quiet_NaN();

// Read access to one column of a frame whose rows may not be contiguous (ROI views).
template <class Pixel>
class ColumnReader {
 public:
  ColumnReader(const cv::Mat& frame, int column)
      : base_(frame.data + static_cast<std::size_t>(column) * sizeof(Pixel)),
        step_(frame.step[0]) {}
  int operator()(int row) const {
    return *reinterpret_cast<const Pixel*>(base_ + static_cast<std::size_t>(row) * step_);
  }

 private:
  const std::uint8_t* base_;
  std::size_t step_;
};

// Column-wise maximum and the first row reaching it, one frame row at a time: contiguous
// reads, and a loop body of compare + two selects on 16-bit lanes that the compiler turns
// into SIMD. Walking each column top to bottom instead would stride through the frame.
template <class Pixel>
void column_maxima(const cv::Mat& frame, std::uint16_t* __restrict column_max,
                   std::uint16_t* __restrict column_argmax) {
  const int columns = frame.cols;
  const Pixel* first = frame.ptr<Pixel>(0);
  for (int c = 0; c < columns; ++c) {
    column_max[c] = first[c];
    column_argmax[c] = 0;
  }
  for (int r = 1; r < frame.rows; ++r) {
    const Pixel* __restrict row = frame.ptr<Pixel>(r);
    const auto row_index = static_cast<std::uint16_t>(r);
    for (int c = 0; c < columns; ++c) {
      const std::uint16_t value = row[c];
      const bool higher = value > column_max[c];  // strict: keeps the first row of a plateau
      column_max[c] = higher ? value : column_max[c];
      column_argmax[c] = higher ? row_index : column_argmax[c];
    }
  }
}

// Intensity-minus-threshold weighted mean row of the contiguous above-threshold run that
// contains rows [run_first, run_last] (the maximum, or the saturated run), grown at most
// `half_width` rows beyond it. Returns NaN when the run reaches the frame edge: the ROI cut
// the stripe and the mean would be pulled inwards.
template <class Pixel>
float centre_of_gravity(const ColumnReader<Pixel>& column, int rows, int run_first, int run_last,
                        int threshold, int half_width) {
  const int window_first = std::max(0, run_first - half_width);
  const int window_last = std::min(rows - 1, run_last + half_width);
  int first = run_first;
  while (first > window_first && column(first - 1) > threshold) --first;
  int last = run_last;
  while (last < window_last && column(last + 1) > threshold) ++last;
  if (first == 0 || last == rows - 1) return kNoPeak;
  // Integer sums are exact and cheap: at most 2 * 65535 * 65535 * rows fits 64 bits.
  std::int64_t weight_sum = 0;
  std::int64_t weighted_row_sum = 0;
  for (int r = first; r <= last; ++r) {
    const std::int64_t weight = column(r) - threshold;
    weight_sum += weight;
    weighted_row_sum += weight * r;
  }
  return static_cast<float>(static_cast<double>(weighted_row_sum) /
                            static_cast<double>(weight_sum));
}

// Sub-pixel offset of the vertex of the parabola through (-1, ln a), (0, ln b), (1, ln c):
// exact for a Gaussian stripe. b is the first maximum (b > a, b >= c), so the offset lies
// in (-0.5, 0.5]; a plateau a = b = c cannot happen, but would give 0.
float gaussian_three_point_offset(int a, int b, int c) {
  // ln 0 is -inf: clamp dark neighbours to one grey level.
  const float ln_a = std::log(static_cast<float>(std::max(a, 1)));
  const float ln_b = std::log(static_cast<float>(std::max(b, 1)));
  const float ln_c = std::log(static_cast<float>(std::max(c, 1)));
  const float curvature = ln_a - 2.0f * ln_b + ln_c;
  if (!(curvature < 0.0f)) return 0.0f;
  return (ln_a - ln_c) / (2.0f * curvature);
}

}  // namespace

LaserStripeExtractor::LaserStripeExtractor(const StripeExtractionParameters& parameters)
    : parameters_(parameters) {}

void LaserStripeExtractor::reserve(int max_columns, StripePeaks& peaks) {
  const auto n = static_cast<std::size_t>(std::max(max_columns, 0));
  column_max_.reserve(n);
  column_argmax_.reserve(n);
  peaks.row_px.reserve(n);
  peaks.peak_intensity.reserve(n);
}

StripeExtractionStatus LaserStripeExtractor::extract(const cv::Mat& frame, const FrameRoi& roi,
                                                     StripePeaks& peaks) noexcept {
  peaks.column_offset_px = roi.column_offset_px;
  peaks.valid_columns = 0;
  peaks.saturated_columns = 0;
  if (frame.empty() || frame.dims != 2) {
    peaks.row_px.clear();
    peaks.peak_intensity.clear();
    return StripeExtractionStatus::kEmptyFrame;
  }
  const auto columns = static_cast<std::size_t>(frame.cols);
  // resize() never gives capacity back: allocation happens only for a wider frame than any
  // before (or never, after reserve()).
  peaks.row_px.resize(columns);
  peaks.peak_intensity.resize(columns);
  std::fill(peaks.row_px.begin(), peaks.row_px.end(), kNoPeak);
  std::fill(peaks.peak_intensity.begin(), peaks.peak_intensity.end(), 0.0f);
  if (frame.rows > std::numeric_limits<std::uint16_t>::max() + 1) {
    return StripeExtractionStatus::kTooManyRows;
  }
  column_max_.resize(columns);
  column_argmax_.resize(columns);
  switch (frame.type()) {
    case CV_8UC1:
      extract_typed<std::uint8_t>(frame, roi, peaks);
      return StripeExtractionStatus::kOk;
    case CV_16UC1:
      extract_typed<std::uint16_t>(frame, roi, peaks);
      return StripeExtractionStatus::kOk;
    default:
      return StripeExtractionStatus::kUnsupportedType;
  }
}

template <class Pixel>
void LaserStripeExtractor::extract_typed(const cv::Mat& frame, const FrameRoi& roi,
                                         StripePeaks& peaks) noexcept {
  column_maxima<Pixel>(frame, column_max_.data(), column_argmax_.data());

  const StripeExtractionParameters& p = parameters_;
  const int rows = frame.rows;
  const int saturation = p.saturation_level > 0
                             ? p.saturation_level
                             : static_cast<int>(std::numeric_limits<Pixel>::max());
  const int min_peak = std::max(p.min_peak_intensity, p.threshold + 1);
  const int half_width = std::max(p.window_half_width_px, 1);
  int valid = 0;
  int saturated_columns = 0;

  for (int c = 0; c < frame.cols; ++c) {
    const int peak = column_max_[static_cast<std::size_t>(c)];
    if (peak < min_peak) continue;
    const ColumnReader<Pixel> column(frame, c);
    const int run_first = column_argmax_[static_cast<std::size_t>(c)];
    int run_last = run_first;
    const bool saturated = peak >= saturation;
    if (saturated) {
      // The clipped top carries no shape information: the stripe centre is the middle of
      // the saturated run (first run from the top, the one the arg-max found).
      while (run_last + 1 < rows && column(run_last + 1) >= saturation) ++run_last;
      ++saturated_columns;
    }
    // A maximum on the first or last row is a stripe cut by the ROI: its centre is unknown.
    if (run_first == 0 || run_last == rows - 1) continue;

    float centre_row = kNoPeak;
    if (p.method == StripePeakMethod::kCentreOfGravity) {
      centre_row = centre_of_gravity(column, rows, run_first, run_last, p.threshold, half_width);
    } else if (saturated) {
      centre_row = 0.5f * static_cast<float>(run_first + run_last);
    } else {
      centre_row = static_cast<float>(run_first) +
                   gaussian_three_point_offset(column(run_first - 1), peak, column(run_first + 1));
    }
    if (std::isnan(centre_row)) continue;
    peaks.row_px[static_cast<std::size_t>(c)] = centre_row + static_cast<float>(roi.row_offset_px);
    peaks.peak_intensity[static_cast<std::size_t>(c)] = static_cast<float>(peak);
    ++valid;
  }
  peaks.valid_columns = valid;
  peaks.saturated_columns = saturated_columns;
}

}  // namespace cosmos
