#include "firmware_bridge/stripe_profiler.hpp"

namespace cosmos {

StripeProfiler::StripeProfiler(const TriangulationGeometry& geometry,
                               const StripeExtractionParameters& extraction, int first_row_px,
                               int row_count, int max_columns,
                               const ProfileResamplingParameters& resampling)
    : extractor_(extraction),
      triangulator_(geometry, first_row_px, row_count),
      resampling_(resampling) {
  extractor_.reserve(max_columns, peaks_);
  triangulator_.reserve(max_columns, stripe_);
}

StripeProfiler::StripeProfiler(const TriangulationGeometry& geometry,
                               const StripeExtractionParameters& extraction, int max_columns)
    : StripeProfiler(geometry, extraction, geometry.roi_row_offset_px, geometry.roi_height_px,
                     max_columns) {}

StripeExtractionStatus StripeProfiler::profile_frame(const cv::Mat& frame, const FrameRoi& roi,
                                                     Profile& profile) noexcept {
  const StripeExtractionStatus status = extractor_.extract(frame, roi, peaks_);
  if (status != StripeExtractionStatus::kOk) return status;
  triangulator_.triangulate(peaks_, stripe_);
  resample_to_profile(stripe_.x_mm, stripe_.z_mm, resampling_, profile);
  return status;
}

}  // namespace cosmos
