#include "firmware_bridge/profile_resampling.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace cosmos {
namespace {

// Grid positions within this fraction of dx of a segment end count as on it, so a point
// that lies on a sample in exact arithmetic is not lost to rounding.
constexpr double kGridTolerance = 1e-6;

class ProfileWriter {
 public:
  explicit ProfileWriter(Profile& profile)
      : profile_(profile), width_(static_cast<std::ptrdiff_t>(profile.width())) {}

  // Writes the segment (xa, za)–(xb, zb) onto every grid sample between its ends.
  void segment(double xa, double za, double xb, double zb) {
    if (xa > xb) {
      std::swap(xa, xb);
      std::swap(za, zb);
    }
    const double length = xb - xa;
    const auto first = std::max<std::ptrdiff_t>(
        0, static_cast<std::ptrdiff_t>(std::ceil(grid_position(xa) - kGridTolerance)));
    const auto last = std::min<std::ptrdiff_t>(
        width_ - 1, static_cast<std::ptrdiff_t>(std::floor(grid_position(xb) + kGridTolerance)));
    for (std::ptrdiff_t i = first; i <= last; ++i) {
      const double t =
          length > 0.0
              ? std::clamp((profile_.x_mm(static_cast<std::size_t>(i)) - xa) / length, 0.0, 1.0)
              : 0.0;
      write(i, za + t * (zb - za));
    }
  }

  // A point joined to nothing: its nearest sample, if the point is within half a sample.
  void point(double x, double z) {
    const double position = grid_position(x);
    const auto i = static_cast<std::ptrdiff_t>(std::lround(position));
    if (i >= 0 && i < width_ && std::abs(position - static_cast<double>(i)) <= 0.5) write(i, z);
  }

 private:
  double grid_position(double x) const { return (x - profile_.x0_mm) / profile_.dx_mm; }

  void write(std::ptrdiff_t i, double z) {
    float& sample = profile_.z_mm[static_cast<std::size_t>(i)];
    const auto value = static_cast<float>(z);
    if (std::isnan(sample) || value > sample) sample = value;
  }

  Profile& profile_;
  std::ptrdiff_t width_;
};

}  // namespace

int resample_to_profile(std::span<const float> x_mm, std::span<const float> z_mm,
                        const ProfileResamplingParameters& parameters, Profile& profile) noexcept {
  profile.clear_data();
  if (profile.width() == 0 || !(profile.dx_mm > 0.0)) return 0;
  const double max_gap_mm = parameters.max_gap_in_dx * profile.dx_mm;
  ProfileWriter writer(profile);

  const std::size_t count = std::min(x_mm.size(), z_mm.size());
  bool have_previous = false;
  bool previous_joined = false;  // whether the previous point was joined to its predecessor
  double previous_x = 0.0;
  double previous_z = 0.0;
  for (std::size_t i = 0; i < count; ++i) {
    const double x = x_mm[i];
    const double z = z_mm[i];
    if (std::isnan(x) || std::isnan(z)) continue;
    bool joined = false;
    if (have_previous) {
      joined = std::abs(x - previous_x) <= max_gap_mm &&
               std::abs(z - previous_z) <= parameters.max_z_jump_mm;
      if (joined) {
        writer.segment(previous_x, previous_z, x, z);
      } else if (!previous_joined) {
        writer.point(previous_x, previous_z);
      }
    }
    have_previous = true;
    previous_joined = joined;
    previous_x = x;
    previous_z = z;
  }
  if (have_previous && !previous_joined) writer.point(previous_x, previous_z);

  int with_data = 0;
  for (std::size_t i = 0; i < profile.width(); ++i) with_data += profile.has_data(i) ? 1 : 0;
  return with_data;
}

}  // namespace cosmos
