#include "sim/free_form_view_pair.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>

namespace cosmos {
namespace {

struct Bump {
  double x_mm, y_mm, sigma_mm, height_mm;
};
// Two bumps of different size, a dent and a wave, no symmetry. The flanks reach ~65 degrees:
// a part seen from above shows surface at every inclination, which is what makes the noise
// of d_s vary over the view (§6.5.1, §6.8).
constexpr Bump kBumps[] = {
    {10.0, 3.0, 7.0, 27.0}, {-13.0, -5.0, 5.5, 18.0}, {-1.0, 11.0, 5.0, -12.0}};
constexpr double kWaveMm = 1.2, kWaveX = 0.23, kWaveY = 0.19, kWavePhase = 0.4;

bool inside_footprint(const FreeFormPartSpec& spec, double x_mm, double y_mm) {
  const double u = x_mm / spec.semi_axis_x_mm, v = y_mm / spec.semi_axis_y_mm;
  return u * u + v * v <= 1.0;
}

Eigen::Vector3d part_point(double x_mm, double y_mm) {
  return {x_mm, y_mm, free_form_height_mm(x_mm, y_mm)};
}

}  // namespace

double free_form_height_mm(double x_mm, double y_mm) {
  double z = kWaveMm * std::sin(kWaveX * x_mm + kWavePhase) * std::cos(kWaveY * y_mm);
  for (const Bump& b : kBumps) {
    const double dx = x_mm - b.x_mm, dy = y_mm - b.y_mm;
    z += b.height_mm * std::exp(-(dx * dx + dy * dy) / (2 * b.sigma_mm * b.sigma_mm));
  }
  return z;
}

Eigen::Vector2d free_form_gradient(double x_mm, double y_mm) {
  Eigen::Vector2d g(
      kWaveMm * kWaveX * std::cos(kWaveX * x_mm + kWavePhase) * std::cos(kWaveY * y_mm),
      -kWaveMm * kWaveY * std::sin(kWaveX * x_mm + kWavePhase) * std::sin(kWaveY * y_mm));
  for (const Bump& b : kBumps) {
    const double dx = x_mm - b.x_mm, dy = y_mm - b.y_mm, s2 = b.sigma_mm * b.sigma_mm;
    const double e = b.height_mm * std::exp(-(dx * dx + dy * dy) / (2 * s2));
    g += Eigen::Vector2d(-dx / s2 * e, -dy / s2 * e);
  }
  return g;
}

RangeImage render_free_form_part(const RigidTransform& T_scanner_part,
                                 const FreeFormPartSpec& spec) {
  const double pixel = spec.pixel_size_mm;
  // Bounding box of the placed footprint from its boundary (the interior relief stays within
  // the margin for the gentle tilts this is used with).
  double min_x = std::numeric_limits<double>::infinity(), max_x = -min_x;
  double min_y = min_x, max_y = -min_x;
  for (int k = 0; k < 720; ++k) {
    const double angle = k * std::numbers::pi / 360.0;
    const Eigen::Vector3d p = T_scanner_part.apply(
        part_point(spec.semi_axis_x_mm * std::cos(angle), spec.semi_axis_y_mm * std::sin(angle)));
    min_x = std::min(min_x, p.x()), max_x = std::max(max_x, p.x());
    min_y = std::min(min_y, p.y()), max_y = std::max(max_y, p.y());
  }
  const int first_column = static_cast<int>(std::floor(min_x / pixel)) - spec.margin_px;
  const int first_row = static_cast<int>(std::floor(min_y / pixel)) - spec.margin_px;
  const int width = static_cast<int>(std::ceil(max_x / pixel)) + spec.margin_px - first_column + 1;
  const int height = static_cast<int>(std::ceil(max_y / pixel)) + spec.margin_px - first_row + 1;
  RangeImage image(width, height, pixel, pixel);
  image.origin_x_mm = first_column * pixel;
  image.origin_y_mm = first_row * pixel;

  const Eigen::Matrix3d& R = T_scanner_part.rotation;
  const Eigen::Matrix2d R_xy = R.topLeftCorner<2, 2>();
  const Eigen::Matrix2d R_xy_inverse = R_xy.inverse();
  for (int row = 0; row < height; ++row) {
    for (int column = 0; column < width; ++column) {
      const Eigen::Vector2d target(image.x_mm(column), image.y_mm(row));
      // Newton on (u, v) -> [T (u, v, f(u, v))]_xy = target, from the flat-part guess.
      Eigen::Vector2d uv = R_xy_inverse * (target - T_scanner_part.translation_mm.head<2>());
      bool converged = false;
      for (int iteration = 0; iteration < 30 && !converged; ++iteration) {
        const Eigen::Vector2d residual =
            T_scanner_part.apply(part_point(uv.x(), uv.y())).head<2>() - target;
        const Eigen::Vector2d g = free_form_gradient(uv.x(), uv.y());
        Eigen::Matrix2d J = R_xy;
        J.col(0) += R.block<2, 1>(0, 2) * g.x();
        J.col(1) += R.block<2, 1>(0, 2) * g.y();
        uv -= J.inverse() * residual;
        converged = residual.norm() < 1e-9;
      }
      if (!converged || !inside_footprint(spec, uv.x(), uv.y())) continue;
      const Eigen::Vector2d g = free_form_gradient(uv.x(), uv.y());
      if (R.row(2).dot(Eigen::Vector3d(-g.x(), -g.y(), 1.0)) <= 0.0) continue;
      image.z_mm(column, row) =
          static_cast<float>(T_scanner_part.apply(part_point(uv.x(), uv.y())).z());
    }
  }
  return image;
}

void add_z_noise(RangeImage& image, double sigma_mm, std::uint64_t seed) {
  std::mt19937_64 generator(seed);
  const auto uniform = [&generator] { return static_cast<double>(generator() >> 11) * 0x1.0p-53; };
  for (float& z : image.z_mm.values()) {
    if (!std::isfinite(z)) continue;
    const double radius = std::sqrt(-2.0 * std::log(1.0 - uniform()));
    z += static_cast<float>(sigma_mm * radius * std::cos(2.0 * std::numbers::pi * uniform()));
  }
}

}  // namespace cosmos
