#pragma once
// Resampling of one frame's triangulated stripe points onto the uniform x grid of a Profile.
//
// Camera columns do not land on a uniform x grid (perspective, distortion, height), while
// everything downstream wants z on fixed x samples. Consecutive valid points (in column
// order) are joined by straight segments and each grid sample under a segment gets the
// linearly interpolated height; samples under no segment stay NaN. Two points are not
// joined across a gap (occlusion, dark surface) or a depth jump (the step between a part's
// top and the belt), so no surface is invented where the sensor saw none.
#include <span>

#include "core/profile.hpp"

namespace cosmos {

struct ProfileResamplingParameters {
  // Consecutive points further apart in x than this many profile samples (dx_mm) are not
  // joined. The profile's dx should not be finer than the point spacing.
  double max_gap_in_dx = 3.0;
  // Consecutive points whose heights differ by more than this are not joined: a depth
  // discontinuity. 2 mm keeps surfaces up to ~84° steep joined at 0.2 mm point spacing.
  double max_z_jump_mm = 2.0;
};

// Fills profile.z_mm on the grid x0_mm + i * dx_mm, i < profile.width(), which the caller
// sets (and leaves seq, encoder_ticks, t_us alone). x_mm and z_mm are per-column points,
// NaN = none. A point with no neighbour to join sets the nearest sample if within dx / 2.
// Where segments overlap (the stripe folding back in x), the higher surface wins: it is the
// one a scanner looking down sees. Returns the number of samples with data. Never allocates.
int resample_to_profile(std::span<const float> x_mm, std::span<const float> z_mm,
                        const ProfileResamplingParameters& parameters, Profile& profile) noexcept;

}  // namespace cosmos
