#pragma once
// One camera frame → one Profile: laser-stripe extraction, triangulation, and resampling onto
// the profile's uniform x grid. This is the whole per-frame path of a laser-line scanner, held
// in one place because two callers run it: the live scanner (realtime/sources/hardware_source.hpp)
// and the simulator's camera mode (sim/simulated_scanner.hpp). Sharing it is what makes the
// simulated cell a test of the hardware path rather than of a look-alike.
//
// Owns the extractor, the triangulation table and their per-frame scratch; after
// construction a frame up to max_columns wide allocates nothing, and nothing throws.
#include <opencv2/core/mat.hpp>

#include "core/profile.hpp"
#include "firmware_bridge/laser_stripe_extraction.hpp"
#include "firmware_bridge/laser_triangulation.hpp"
#include "firmware_bridge/profile_resampling.hpp"
#include "scanner/triangulation_geometry.hpp"

namespace cosmos {

class StripeProfiler {
 public:
  // Triangulates the sensor rows [first_row_px, first_row_px + row_count): the rows the
  // camera delivers (its region of interest), which need not be the geometry's design ROI.
  StripeProfiler(const TriangulationGeometry& geometry,
                 const StripeExtractionParameters& extraction, int first_row_px, int row_count,
                 int max_columns, const ProfileResamplingParameters& resampling = {});
  // The geometry's own ROI rows.
  StripeProfiler(const TriangulationGeometry& geometry,
                 const StripeExtractionParameters& extraction, int max_columns);

  // Writes the stripe's heights into profile.z_mm on the grid x0_mm + i · dx_mm, i < width(),
  // that the caller set and cleared (Profile::resize); seq, encoder_ticks and t_us are the
  // caller's too. On a status other than kOk the profile is left as it was.
  StripeExtractionStatus profile_frame(const cv::Mat& frame, const FrameRoi& roi,
                                       Profile& profile) noexcept;

  // The last frame's stripe peaks and triangulated points (diagnostics, frame dumps).
  const StripePeaks& peaks() const noexcept { return peaks_; }

 private:
  LaserStripeExtractor extractor_;
  LaserTriangulator triangulator_;
  ProfileResamplingParameters resampling_;
  StripePeaks peaks_;
  TriangulatedStripe stripe_;
};

}  // namespace cosmos
