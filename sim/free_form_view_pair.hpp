#pragma once
// A smooth free-form part for registration tests (chapter 6): a relief of Gaussian bumps, a
// dent and a wave over an elliptical footprint (72 x 44 mm, up to 27 mm high), asymmetric
// enough that its surface fixes all six pose parameters, rendered as a range image seen from +z
// after any rigid placement, by exact ray casting of the analytic surface (no resampling error),
// plus seeded Gaussian z noise. Two renders at different placements are a view pair with a known
// transform, as in the thesis's synthetic experiments (§6.7.4).
#include <cstdint>

#include "core/range_image.hpp"
#include "core/rigid_transform.hpp"

namespace cosmos {

struct FreeFormPartSpec {
  double semi_axis_x_mm = 36.0;  // elliptical footprint in the part frame (not round, so the
  double semi_axis_y_mm = 22.0;  // principal axes of §6.7.2 are defined)
  double pixel_size_mm = 0.5;
  int margin_px = 3;  // NaN pixels around the footprint
};

// Height of the relief z = f(x, y) in the part frame, and its gradient.
double free_form_height_mm(double x_mm, double y_mm);
Eigen::Vector2d free_form_gradient(double x_mm, double y_mm);

// The part placed at T_scanner_part, seen by a sensor looking down -z: pixel (x, y) holds
// the z of the surface point over it, NaN off the footprint or where the surface faces away.
// The grid covers the placed footprint; it is aligned with multiples of the pixel size.
RangeImage render_free_form_part(const RigidTransform& T_scanner_part,
                                 const FreeFormPartSpec& spec);

// Adds i.i.d. N(0, sigma^2) noise to every valid z, from a generator seeded with `seed`
// (std::mt19937_64, whose sequence the standard fixes, and a written-out Box-Muller).
void add_z_noise(RangeImage& image, double sigma_mm, std::uint64_t seed);

}  // namespace cosmos
