#pragma once
// A whole simulated scan of a conveyor scene assembled into one range image.
//
// The image is in the belt frame (conveyor_scene.hpp: the scanner frame at encoder tick 0),
// so the parts' T_belt_part are its ground truth T_scanner_part. Profile k lies at
// y = −k · Δy in that frame: the belt carries the part downstream through the sheet, so the
// sheet sweeps the part from its downstream (+y) end to its upstream end. Rows are stored in
// increasing y (row 0 is the last profile exposed) so that pixel (i, j) is
// x = x0 + i·dx, y = y0 + j·dy with positive dx, dy, as every range-image consumer expects;
// rows in exposure order would mirror the part.
//
// The belt is background: every sample below the conditioning's height_threshold_mm (the
// visible belt at z ≈ 0, and the lowest rim of the parts) becomes NaN, the threshold the cell
// uses to separate live parts from the belt; the caller passes its one ConditioningParameters
// so model views, test scans and live scans lose the same belt. The image is cropped to the
// measured part pixels plus a margin.
#include <cstdint>
#include <functional>

#include "core/profile.hpp"
#include "core/range_image.hpp"
#include "scanner/conditioning_parameters.hpp"
#include "sim/conveyor_scene.hpp"
#include "sim/simulated_scanner.hpp"

namespace cosmos {

struct RangeScanOptions {
  double scan_margin_mm = 2.0;  // scan this far beyond the parts' y extent on both sides
  int crop_margin_px = 4;       // pixels kept around the measured part pixels
};

// Called after each profile (in exposure order), e.g. to save the scanner's camera frames.
using ProfileObserver = std::function<void(std::int64_t profile_index, const Profile& profile,
                                           const SimulatedScanner& scanner)>;

// Scans every profile covering the scene. Returns an image with its belt mask and without
// ground truth (the caller knows which part it is), or an empty image (width 0) when no part
// pixel was measured.
RangeImage scan_range_image(const ConveyorScene& scene, SimulatedScanner& scanner,
                            const ConditioningParameters& conditioning,
                            const RangeScanOptions& options = {},
                            const ProfileObserver& observer = {});

}  // namespace cosmos
