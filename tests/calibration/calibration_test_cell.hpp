#pragma once
// The mis-mounted simulated cell the calibration tests measure: every error of
// scanner/simulated_mounting.hpp set, as the end-to-end cell has them.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "scanner/simulated_mounting.hpp"

namespace cosmos::test {

inline SimulatedMounting mis_mounted_cell() {
  SimulatedMounting truth;
  truth.laser_plane_tilt_deg = 1.0;
  truth.roll_deg = 0.5;
  truth.height_offset_mm = 1.5;
  truth.focal_scale = 1.01;
  truth.principal_shift_u_px = 6.0;
  truth.principal_shift_v_px = -4.0;
  truth.k1 = -0.2;
  truth.encoder_mm_per_tick = 0.102;
  truth.sheet_pitch_deg = 0.5;
  truth.T_cell_scanner.rotation = rotation_from_xyz_angles_deg(0.8, -0.6, 91.0);
  truth.T_cell_scanner.translation_mm = Eigen::Vector3d(850.0, -420.0, 310.0);
  return truth;
}

// A half-resolution sensor over the same field of view: the tests' images stay small.
inline ScannerParameters small_sensor_scanner() {
  ScannerParameters scanner;
  scanner.sensor_width_px = 640;
  scanner.sensor_height_px = 512;
  scanner.roi_height_px = 256;
  return scanner;
}

inline double angle_deg(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::acos(std::clamp(a.normalized().dot(b.normalized()), -1.0, 1.0)) * 180.0 /
         std::numbers::pi;
}

}  // namespace cosmos::test
