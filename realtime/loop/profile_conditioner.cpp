#include "realtime/loop/profile_conditioner.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cosmos {

ProfileConditioner::ProfileConditioner(const ConditioningParameters& parameters,
                                       const SurfaceFitParameters& fit)
    : parameters_(parameters),
      depth_jump_mm_(static_cast<float>(fit.depth_jump_mm)),
      width_(std::max(1, static_cast<int>(std::floor((parameters.x_max_mm - parameters.x_min_mm) /
                                                     parameters.grid_mm)))) {}

namespace {

// A sample position (in samples) as an int within [-2, samples + 1]: positions outside the
// profile only need to stay outside it, and a far x0_mm or a tiny dx_mm would exceed int.
int sample_index(double position, int samples) {
  return static_cast<int>(std::clamp(position, -2.0, samples + 1.0));
}

// Sample spacings a scanner can have (a 10..5000 mm field of view over 16..8192 points, with
// a margin of ten either way) and sample 0 within a kilometre: anything else is a damaged
// record, not a profile.
constexpr double kMinSpacingMm = 1e-4;
constexpr double kMaxSpacingMm = 3e3;
constexpr double kMaxOriginMm = 1e6;

}  // namespace

bool ProfileConditioner::condition(const Profile& profile, float* out_z_mm,
                                   std::uint8_t* out_belt) const {
  // Written as "not inside" so that NaN fails too.
  if (!(profile.dx_mm >= kMinSpacingMm && profile.dx_mm <= kMaxSpacingMm) ||
      !(std::abs(profile.x0_mm) <= kMaxOriginMm)) {
    std::fill(out_z_mm, out_z_mm + width_, std::numeric_limits<float>::quiet_NaN());
    if (out_belt) std::fill(out_belt, out_belt + width_, std::uint8_t{0});
    return false;
  }
  if (profile.dx_mm < parameters_.grid_mm) {
    box_average(profile, out_z_mm);
  } else {
    interpolate(profile, out_z_mm);
  }
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float threshold = static_cast<float>(parameters_.height_threshold_mm);
  for (int k = 0; k < width_; ++k) {
    const double x = parameters_.x_min_mm + k * parameters_.grid_mm;
    const float height =
        out_z_mm[k] - static_cast<float>(parameters_.belt_height_mm + parameters_.belt_slope_x * x);
    if (out_belt) out_belt[k] = height < threshold ? 1 : 0;  // NaN compares false: no data
    out_z_mm[k] = height >= threshold ? height : nan;        // NaN compares false: stays NaN
  }
  return true;
}

// The valid samples of each grid cell [x_k - g/2, x_k + g/2); a cell whose samples straddle a
// depth jump keeps the samples nearer the sensor (the top surface).
void ProfileConditioner::box_average(const Profile& profile, float* out_z_mm) const {
  const int samples = static_cast<int>(profile.width());
  const double g = parameters_.grid_mm;
  const float jump = depth_jump_mm_;
  for (int k = 0; k < width_; ++k) {
    const double x_center = parameters_.x_min_mm + k * g;
    const int first = std::max(
        0, sample_index(std::ceil((x_center - 0.5 * g - profile.x0_mm) / profile.dx_mm), samples));
    const int last = std::min(
        samples - 1,
        sample_index(std::ceil((x_center + 0.5 * g - profile.x0_mm) / profile.dx_mm), samples) - 1);
    float top = -std::numeric_limits<float>::infinity();
    for (int i = first; i <= last; ++i)
      if (!std::isnan(profile.z_mm[i])) top = std::max(top, profile.z_mm[i]);
    // A least-squares line through the cell's samples, evaluated at the cell centre: unlike
    // their mean, unbiased on a sloped surface when the samples sit off-centre in the cell.
    double sum_u = 0, sum_z = 0, sum_uu = 0, sum_uz = 0;
    int count = 0;
    for (int i = first; i <= last; ++i) {
      const float z = profile.z_mm[i];
      if (!(z >= top - jump)) continue;  // NaN compares false
      const double u = profile.x0_mm + i * profile.dx_mm - x_center;
      sum_u += u;
      sum_z += z;
      sum_uu += u * u;
      sum_uz += u * z;
      ++count;
    }
    float value = std::numeric_limits<float>::quiet_NaN();
    if (count > 0) {
      const double mean_u = sum_u / count, mean_z = sum_z / count;
      const double spread = sum_uu - count * mean_u * mean_u;
      const double slope = spread > 1e-12 ? (sum_uz - count * mean_u * mean_z) / spread : 0.0;
      value = static_cast<float>(mean_z - slope * mean_u);
    }
    out_z_mm[k] = value;
  }
}

void ProfileConditioner::interpolate(const Profile& profile, float* out_z_mm) const {
  const int samples = static_cast<int>(profile.width());
  const float jump = depth_jump_mm_;
  for (int k = 0; k < width_; ++k) {
    const double u =
        (parameters_.x_min_mm + k * parameters_.grid_mm - profile.x0_mm) / profile.dx_mm;
    const int i = sample_index(std::floor(u), samples);
    const float t = static_cast<float>(u - i);
    float z = std::numeric_limits<float>::quiet_NaN();
    if (i >= 0 && i + 1 < samples) {
      const float a = profile.z_mm[i], b = profile.z_mm[i + 1];
      if (std::abs(a - b) <= jump) {
        z = a + t * (b - a);
      } else if (!std::isnan(t < 0.5f ? a : b)) {
        z = t < 0.5f ? a : b;  // across a jump or next to a gap: the nearest sample only
      }
    } else if (i + 1 == samples && t == 0.0f) {
      z = profile.z_mm[i];
    }
    out_z_mm[k] = z;
  }
}

}  // namespace cosmos
