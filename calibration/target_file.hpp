#pragma once
// The target files of the belt and cell calibrations (YAML):
//   ramp:   {length_mm: 160, width_mm: 120, low_height_mm: 10, high_height_mm: 40}
//   spheres:
//     radius_mm: 12.5
//     plate_height_mm: 5
//     encoder_ticks: 1862        # the belt's count when the robot touched the centres
//     centres_cell_mm: [[x, y, z], ...]
// A missing key, a wrong type or a value out of range is InputError `file:LINE: key: reason`.
#include <filesystem>

#include "calibration/calibration_targets.hpp"

namespace cosmos {

RampBlock read_ramp_target(const std::filesystem::path& file);
SpherePlate read_sphere_target(const std::filesystem::path& file);
void write_ramp_target(const std::filesystem::path& file, const RampBlock& block);
void write_sphere_target(const std::filesystem::path& file, const SpherePlate& plate);

}  // namespace cosmos
