#pragma once
// The simulated cell's true geometry where it departs from the design the cell is told
// (config/cell.yaml `sim_source.truth:`): a scanner mounted and lensed slightly otherwise
// than drawn, so that the simulator renders through one geometry and the cell triangulates
// with another, as a real uncalibrated cell does. All defaults: the design itself.
//
// The belt frame stays the designed scanner frame (belt z = 0, laser sheet y = 0, the sheet
// across the belt): the errors move the camera against it, except the pitch, which tilts the
// whole scanner head (camera and laser together) against the belt.
//   laser_plane_tilt_deg  the camera turned about the sheet's x axis through the origin:
//                         the laser plane in the camera frame is off by this angle
//   roll_deg              the camera turned about the belt's travel (y) through the origin:
//                         the belt's laser line slopes across the image
//   height_offset_mm      the camera this much higher above the belt
//   focal_scale, principal_shift_*_px, k1: the lens against the designed pinhole
//   encoder_mm_per_tick   the belt's true travel per encoder tick (0: the told one)
//   field_of_view_mm      the field the camera was designed for (0: the told one), which the
//                         design's focal length follows: a calibrated cell resamples its
//                         profiles to its own grid (scanner.field_of_view_mm), the lens stays
//   sheet_pitch_deg       the scanner head turned about the belt's x axis through the origin:
//                         the laser sheet leans downstream with height by this angle, so a
//                         point the sheet lights at in-sheet height s lies s · sin(pitch)
//                         downstream of the sheet's foot and s · cos(pitch) above the belt
//                         (the cell de-shears its rows by it, conditioning.sheet_pitch_deg)
//   T_cell_scanner        where the scanner really is in the robot's frame
// The absolute values keep the simulated cell the same physical cell while `cosmos calibrate`
// rewrites the scanner: keys it was told.
#include "core/parameter_visitor.hpp"
#include "core/rigid_transform.hpp"
#include "scanner/scanner_model.hpp"
#include "scanner/triangulation_geometry.hpp"

namespace cosmos {

struct SimulatedMounting {
  double laser_plane_tilt_deg = 0.0;
  double roll_deg = 0.0;
  double height_offset_mm = 0.0;
  double focal_scale = 1.0;
  double principal_shift_u_px = 0.0;
  double principal_shift_v_px = 0.0;
  double k1 = 0.0;
  double encoder_mm_per_tick = 0.0;
  double field_of_view_mm = 0.0;
  double sheet_pitch_deg = 0.0;
  RigidTransform T_cell_scanner;

  template <class Visitor>
  void visit(Visitor& v) {
    v("laser_plane_tilt_deg", laser_plane_tilt_deg,
      "true camera turn about the sheet's x axis: laser-plane error, deg", Range{-10, 10});
    v("roll_deg", roll_deg, "true camera turn about the belt's travel direction, deg",
      Range{-10, 10});
    v("height_offset_mm", height_offset_mm, "true camera height above the designed, mm",
      Range{-100, 100});
    v("focal_scale", focal_scale, "true focal length over the designed", Range{0.8, 1.25});
    v("principal_shift_u_px", principal_shift_u_px, "true principal point column shift, px",
      Range{-200, 200});
    v("principal_shift_v_px", principal_shift_v_px, "true principal point row shift, px",
      Range{-200, 200});
    v("k1", k1, "true radial lens distortion r^2", Range{-1, 1});
    v("encoder_mm_per_tick", encoder_mm_per_tick,
      "true belt travel per encoder tick, mm (0: scanner.encoder_mm_per_tick)", Range{0, 100});
    v("field_of_view_mm", field_of_view_mm,
      "field the true camera was designed for, mm (0: scanner.field_of_view_mm)", Range{0, 5000});
    v("sheet_pitch_deg", sheet_pitch_deg,
      "true tilt of the scanner head about the belt's x axis: the laser sheet leans downstream "
      "with height, deg",
      Range{-10, 10});
    v("T_cell_scanner", T_cell_scanner,
      "true scanner frame in the cell frame: rotation_deg [rx, ry, rz], translation_mm");
  }
};

// The camera and laser sheet the simulator renders through: the design of `nominal` moved
// by `mounting` (the laser sheet stays y = 0 of the belt frame).
TriangulationGeometry true_triangulation_geometry(const ScannerParameters& nominal,
                                                  const SimulatedMounting& mounting);

// `nominal` with the true belt travel per tick and designed field of view: the parameters the
// simulated belt and camera run by.
ScannerParameters true_scanner_parameters(const ScannerParameters& nominal,
                                          const SimulatedMounting& mounting);

// Whether the true camera differs from the designed one (rendering needs re-projection).
bool moves_camera(const SimulatedMounting& mounting);

}  // namespace cosmos
