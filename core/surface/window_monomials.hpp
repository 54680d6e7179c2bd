#pragma once
// The bicubic monomials of the local surface fit (§3.5.1) at a window offset (u, v) in pixel
// steps: 1, u, v, u^2, uv, v^2, u^3, u^2 v, u v^2, v^3 (pixel steps: the fit's conditioning
// does not depend on the pixel size; callers rescale to mm). The first 6 are the
// biquadratic's; coefficients 0..5 at the centre are the Taylor terms z, z_u, z_v, z_uu/2,
// z_uv, z_vv/2.
#include <Eigen/Core>

namespace cosmos {

inline constexpr int kBicubicTerms = 10;
inline constexpr int kBiquadraticTerms = 6;

inline Eigen::Matrix<double, kBicubicTerms, 1> window_monomials(double u, double v) {
  Eigen::Matrix<double, kBicubicTerms, 1> m;
  m << 1, u, v, u * u, u * v, v * v, u * u * u, u * u * v, u * v * v, v * v * v;
  return m;
}

}  // namespace cosmos
