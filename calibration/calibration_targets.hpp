#pragma once
// The physical targets of the belt and cell calibrations, as their target files describe them
// (calibration/target_file.hpp):
//   RampBlock: a block whose top rises linearly along the belt from low_height_mm at its
//     upstream end to high_height_mm at its downstream end over length_mm: the rise per
//     belt millimetre is known, so the rise per encoder tick gives the millimetres per tick.
//     The ramp faces the camera (upstream), so the whole slope is seen.
//   SpherePlate: spheres of one radius whose centres the robot has touched, given in the
//     cell frame at the belt position of encoder count encoder_ticks (the belt stopped there).
#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace cosmos {

struct RampBlock {
  double length_mm = 160.0;
  double width_mm = 120.0;
  double low_height_mm = 10.0;
  double high_height_mm = 40.0;

  double rise_per_mm() const { return (high_height_mm - low_height_mm) / length_mm; }
};

struct SpherePlate {
  double radius_mm = 12.5;
  double plate_height_mm = 5.0;  // the plate's top above the belt; spheres stand above it
  std::int64_t encoder_ticks = 0;
  std::vector<Eigen::Vector3d> centres_cell_mm;
};

}  // namespace cosmos
