#pragma once
// Conditioning of one sensor profile for COSMOS: resampling onto the COSMOS grid (sensors
// deliver up to 3,200 points; COSMOS runs on grid_mm, default 0.4 mm), removal of the belt
// plane and a height threshold that turns the belt into background (NaN). Box-averages when
// the sensor is finer than the grid (no aliasing of its noise), interpolates linearly when it
// is coarser, and never across a depth jump or a gap. No allocation, no branches on the
// per-point path beyond the validity tests.
#include "core/profile.hpp"

namespace cosmos {

struct ConditioningParameters {
  double grid_mm = 0.4;  // COSMOS grid along x (and the belt step along y)
  // The grid covers [x_min, x_max) across the belt; the defaults put its points on the
  // default scanner's samples (config/cell.yaml says why that matters).
  double x_min_mm = -127.8;
  double x_max_mm = 128.2;
  double belt_height_mm = 0.0;  // the belt plane z = belt_height + belt_slope_x * x
  double belt_slope_x = 0.0;
  double height_threshold_mm = 0.5;  // above the belt: part; below: background
  double depth_jump_mm = 3.0;        // no interpolation between samples further apart in z
};

class ProfileConditioner {
 public:
  explicit ProfileConditioner(const ConditioningParameters& parameters);

  int width() const { return width_; }
  double x0_mm() const { return parameters_.x_min_mm; }
  // Writes width() heights above the belt (NaN = background or no data) into out_z_mm.
  void condition(const Profile& profile, float* out_z_mm) const;

 private:
  void box_average(const Profile& profile, float* out_z_mm) const;
  void interpolate(const Profile& profile, float* out_z_mm) const;

  ConditioningParameters parameters_;
  int width_;
};

}  // namespace cosmos
