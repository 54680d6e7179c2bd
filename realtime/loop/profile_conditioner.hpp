#pragma once
// Conditioning of one sensor profile for COSMOS: resampling onto the COSMOS grid (sensors
// deliver up to 3,200 points; COSMOS runs on grid_mm, default 0.4 mm), removal of the belt
// plane and a height threshold that turns the belt into background (NaN). Box-averages when
// the sensor is finer than the grid (no aliasing of its noise), interpolates linearly when it
// is coarser, and never across a depth jump or a gap: the COSMOS fit's depth_jump_mm, so the
// grid is never interpolated across an edge that the fit (§3.5.1) treats as one. No allocation, no
// branches on the per-point path beyond the validity tests.
#include <cstdint>

#include "core/cosmos_parameters.hpp"  // SurfaceFitParameters
#include "core/profile.hpp"
#include "scanner/conditioning_parameters.hpp"  // ConditioningParameters

namespace cosmos {

class ProfileConditioner {
 public:
  // `fit`: the COSMOS fit the conditioned rows go to (the model base's), for its depth jump.
  ProfileConditioner(const ConditioningParameters& parameters, const SurfaceFitParameters& fit);

  int width() const { return width_; }
  double x0_mm() const { return parameters_.x_min_mm; }
  // Writes width() heights above the belt (NaN = background or no data) into out_z_mm.
  // False, and no data at all, for a profile whose dx_mm is no scanner's spacing (0, 1e-300,
  // NaN: the sample index divides by it) or whose x0_mm is not within a kilometre.
  // out_belt (optional, width() flags): 1 where the belt itself was measured, 0 where a part
  // was or nothing was (no data: the camera's occlusion shadow, or off the sensor).
  bool condition(const Profile& profile, float* out_z_mm, std::uint8_t* out_belt = nullptr) const;

 private:
  void box_average(const Profile& profile, float* out_z_mm) const;
  void interpolate(const Profile& profile, float* out_z_mm) const;

  ConditioningParameters parameters_;
  float depth_jump_mm_;
  int width_;
};

}  // namespace cosmos
