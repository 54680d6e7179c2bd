#pragma once
// The calibration targets of a simulated cell, rendered through its TRUE geometry
// (scanner/simulated_mounting.hpp), with the true values at hand to check a calibration
// against:
//   camera: board images in seeded poses over the field of view (tilted up to ±40° from
//           facing the camera)
//   laser:  board image + stripe image pairs, the board held at several heights and tilts
//           across the laser sheet
//   belt:   stripe frames of the empty belt, and of the ramp block carried through the sheet
//           (either way round)
//   cell:   stripe frames of the sphere plate carried through the sheet, and the plate's
//           target description with the centres the robot would touch (true T_cell_scanner)
// Belt and cell frames are the designed ROI's rows, as the cell's camera delivers them;
// camera and laser images are full sensor frames.
#include <cstdint>
#include <opencv2/core/mat.hpp>
#include <vector>

#include "calibration/calibration_board.hpp"
#include "calibration/calibration_targets.hpp"
#include "calibration/stripe_frame.hpp"
#include "core/rigid_transform.hpp"
#include "firmware_bridge/laser_stripe_extraction.hpp"
#include "scanner/scanner_calibration.hpp"
#include "scanner/scanner_model.hpp"
#include "scanner/simulated_mounting.hpp"
#include "scanner/triangulation_geometry.hpp"

namespace cosmos {

struct BoardImage {
  cv::Mat image;
  RigidTransform T_camera_board;  // the truth
};

struct LaserImagePair {
  cv::Mat board_image;
  cv::Mat stripe_image;  // full sensor, the board unmoved, ambient light only
  RigidTransform T_camera_board;
};

struct SpherePlateScan {
  std::vector<StripeFrame> frames;
  SpherePlate plate;  // the centres as the robot measured them: the truth
};

// What the simulated cell really is, in the calibrations' terms.
struct CalibrationTruth {
  CalibratedCamera camera;
  CalibratedLaserPlane laser;  // in the true camera frame
  RigidTransform T_scanner_camera;
  double encoder_mm_per_tick = 0.0;
  RigidTransform T_cell_scanner;
  double roll_deg = 0.0;
  double sheet_pitch_deg = 0.0;
  double camera_height_mm = 0.0;
};

// How the ramp block lies on the belt: as its target file draws it, or turned round (the
// belt calibration scans both to tell the sheet's pitch from the encoder's scale).
enum class RampPlacement : std::uint8_t { kHighEndDownstream, kHighEndUpstream };

class CalibrationTargetSimulator {
 public:
  CalibrationTargetSimulator(const ScannerParameters& nominal, const SimulatedMounting& truth,
                             std::uint64_t seed);

  const TriangulationGeometry& true_geometry() const { return geometry_; }
  CalibrationTruth truth() const;
  // The stripe extraction that matches the drawing (sim/camera_frame_renderer.hpp).
  StripeExtractionParameters extraction_parameters() const;

  std::vector<BoardImage> board_images(const CalibrationBoard& board, int count);
  std::vector<LaserImagePair> laser_views(const CalibrationBoard& board, int count);
  std::vector<StripeFrame> empty_belt_frames(int count);
  std::vector<StripeFrame> ramp_frames(const RampBlock& block, int ticks_between_frames,
                                       RampPlacement placement = RampPlacement::kHighEndDownstream);
  SpherePlateScan sphere_plate_scan(int ticks_between_frames);

  // The sphere plate's designed layout: plate width and length (mm), and sphere positions
  // (x across, y along from the plate's upstream edge) in the plate.
  static constexpr double kPlateWidthMm = 180.0;
  static constexpr double kPlateLengthMm = 150.0;

 private:
  // A board pose in the belt frame at random within the given bounds (tilted from lying
  // printed side up, or from facing the camera square), whose whole outline the true camera
  // sees with a margin.
  RigidTransform random_board_pose(const CalibrationBoard& board, bool facing_camera,
                                   double max_tilt_deg, double y_half_range_mm, double z_max_mm);
  RigidTransform T_camera_belt() const;

  ScannerParameters nominal_;
  SimulatedMounting mounting_;
  TriangulationGeometry geometry_;
  std::uint64_t seed_ = 1;
  std::uint64_t draws_ = 0;
};

}  // namespace cosmos
