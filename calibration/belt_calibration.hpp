#pragma once
// The scanner frame from the belt, and the encoder's millimetres per tick.
//
// Frame: the empty belt's stripe, triangulated through the calibrated camera and laser
// plane, is the belt's line in the laser sheet. The scanner frame is built on it as the
// design defines it (scanner/scanner_model.hpp): y the laser plane's normal (away from the
// camera: the direction of travel), x along the belt's line (the sensor's columns' way),
// z = x × y up from the belt, the origin on the belt's line below where the optical axis meets
// the sheet. z runs up the sheet: a line of the belt cannot show the sheet's tilt along the
// travel (its pitch), the ramp below does.
//
// Encoder and pitch: the ramp block (calibration_targets.hpp) carried through the sheet; its
// top's height in each frame (the median of the points above the belt) changes linearly with
// the encoder count. With an upright sheet it changes by rise_per_mm · mm_per_tick per tick.
// A pitched sheet meets the slope higher or lower up as it leans with or against it, which
// scales that slope by a factor the scale of the encoder cannot be told from in one scan: the
// block scanned a second time turned round (its slope the other way) separates the two, and
// gives mm_per_tick and the pitch in closed form. With one scan the sheet is taken as upright.
//
// Reported against the belt: the camera's roll about the travel direction, its height above
// the belt, and the residual belt plane in the new frame (written to conditioning:).
#include <string>
#include <vector>

#include "calibration/calibration_targets.hpp"
#include "calibration/stripe_frame.hpp"
#include "firmware_bridge/laser_stripe_extraction.hpp"
#include "scanner/conditioning_parameters.hpp"
#include "scanner/scanner_calibration.hpp"

namespace cosmos {

// One scan of the ramp block: its top's height per used frame and the line through them.
struct RampLine {
  double slope_mm_per_tick = 0.0;
  double rms_mm = 0.0;                        // heights about the line
  std::vector<Eigen::Vector2d> ticks_height;  // (ticks, height) of each used frame
};

struct BeltCalibrationResult {
  bool ok = false;
  std::string reason;
  CalibratedMount mount;
  double encoder_mm_per_tick = 0.0;
  double roll_deg = 0.0;          // the camera's x axis against the belt's line
  double camera_height_mm = 0.0;  // camera centre above the belt
  double belt_height_mm = 0.0;    // residual belt plane z = height + slope_x x, new frame
  double belt_slope_x = 0.0;
  double belt_rms_mm = 0.0;  // belt points about that plane
  RampLine ramp;
  RampLine ramp_turned;          // empty when the turned block was not scanned
  bool pitch_measured = false;   // the turned block was scanned
  double sheet_pitch_deg = 0.0;  // the sheet leans downstream with height (sheet_pitch.hpp)
  std::vector<Eigen::Vector3d> belt_points_scanner;  // for the report
};

// `camera` and `laser` calibrated; `nominal` supplies the designed camera where uncalibrated.
// `ramp_turned`: the block scanned again turned round on the belt, or empty (no pitch).
BeltCalibrationResult calibrate_belt(const std::vector<StripeFrame>& empty_belt,
                                     const std::vector<StripeFrame>& ramp,
                                     const std::vector<StripeFrame>& ramp_turned,
                                     const RampBlock& block, const ScannerParameters& nominal,
                                     const ScannerCalibration& calibration,
                                     const StripeExtractionParameters& extraction);

// The profile grid a cell with this encoder needs: the belt's travel per profile is the grid's
// pitch along the belt (cosmos cell requires it) and a model base's views have one pitch both
// ways, so the profile's samples are respaced to it (field_of_view_mm = points_per_profile ·
// pitch; with the camera calibrated the field no longer shapes the lens) and the grid is laid
// on the samples from the first to the last, as config/cell.yaml's default grid is.
struct ProfileSampling {
  double field_of_view_mm = 0.0;
  ConditioningParameters conditioning;
};
ProfileSampling profile_sampling_for(const ScannerParameters& scanner,
                                     const ConditioningParameters& conditioning,
                                     double encoder_mm_per_tick);

}  // namespace cosmos
