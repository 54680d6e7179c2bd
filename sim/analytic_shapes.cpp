#include "sim/analytic_shapes.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace cosmos {
namespace {

// A point of a sphere of radius r centred at the origin, seen from outside (convex, top half)
// or from inside (concave, bottom half: the cup).
ShapePoint sphere_point(double radius_mm, double x_mm, double y_mm, bool concave) {
  ShapePoint point;
  const double rho_sq = x_mm * x_mm + y_mm * y_mm;
  const double radius_sq = radius_mm * radius_mm;
  if (rho_sq >= radius_sq) return point;
  const double height_mm = std::sqrt(radius_sq - rho_sq);
  point.valid = true;
  const double sign = concave ? -1.0 : 1.0;
  point.z_mm = sign * height_mm;
  // The normal towards the sensor points away from the centre on the cap, towards it in the cup.
  point.normal = Eigen::Vector3d(sign * x_mm, sign * y_mm, height_mm) / radius_mm;
  point.kappa1 = point.kappa2 = sign / radius_mm;
  return point;
}

// Curvatures of a height field z = f(x, y) from its exact derivatives, with the normal
// (-fx, -fy, 1)/|.| towards +z: K = det(Hess f)/w^2, H = -div-form/(2 w^(3/2)), w = 1+|grad f|^2.
// The minus sign on H makes caps convex-positive.
ShapePoint graph_point(double z_mm, double fx, double fy, double fxx, double fxy, double fyy) {
  ShapePoint point;
  point.valid = true;
  point.z_mm = z_mm;
  const double w = 1.0 + fx * fx + fy * fy;
  point.normal = Eigen::Vector3d(-fx, -fy, 1.0) / std::sqrt(w);
  const double gaussian = (fxx * fyy - fxy * fxy) / (w * w);
  const double mean = -((1.0 + fy * fy) * fxx - 2.0 * fx * fy * fxy + (1.0 + fx * fx) * fyy) /
                      (2.0 * std::pow(w, 1.5));
  const double spread = std::sqrt(std::max(mean * mean - gaussian, 0.0));
  point.kappa1 = mean + spread;
  point.kappa2 = mean - spread;
  return point;
}

ShapePoint cylinder_point(const AnalyticDimensions& d, double x_mm, double y_mm) {
  ShapePoint point;
  const double r = d.radius_mm;
  if (std::abs(x_mm) >= r || std::abs(y_mm) > 0.5 * d.cylinder_length_mm) return point;
  const double height_mm = std::sqrt(r * r - x_mm * x_mm);
  point.valid = true;
  point.z_mm = height_mm;
  point.normal = Eigen::Vector3d(x_mm, 0.0, height_mm) / r;
  point.kappa1 = 1.0 / r;  // across the axis; along it the surface is straight
  return point;
}

ShapePoint saddle_point(const AnalyticDimensions& d, double x_mm, double y_mm) {
  const double w = d.saddle_half_width_mm;
  if (std::abs(x_mm) > w || std::abs(y_mm) > w) return {};
  const double r = d.radius_mm;
  return graph_point((x_mm * x_mm - y_mm * y_mm) / (2.0 * r), x_mm / r, -y_mm / r, 1.0 / r, 0.0,
                     -1.0 / r);
}

ShapePoint plane_point(const AnalyticDimensions& d, double x_mm, double y_mm) {
  ShapePoint point;
  const double w = d.plane_half_width_mm;
  if (std::abs(x_mm) > w || std::abs(y_mm) > w) return point;
  const double tilt_rad = d.plane_tilt_deg * std::numbers::pi / 180.0;
  point.valid = true;
  point.z_mm = std::tan(tilt_rad) * x_mm;
  point.normal = Eigen::Vector3d(-std::sin(tilt_rad), 0.0, std::cos(tilt_rad));
  return point;
}

// The top half of the tube: at tube angle phi (cos phi = (rho - R)/a) the meridian curvature
// is 1/a and the parallel one cos(phi)/rho, negative on the inner (saddle-shaped) side.
ShapePoint torus_point(const AnalyticDimensions& d, double x_mm, double y_mm) {
  ShapePoint point;
  const double major = d.torus_major_radius_mm;
  const double minor = d.torus_minor_radius_mm;
  const double rho = std::hypot(x_mm, y_mm);
  const double offset = rho - major;
  if (std::abs(offset) >= minor) return point;
  const double height_mm = std::sqrt(minor * minor - offset * offset);
  point.valid = true;
  point.z_mm = height_mm;
  point.normal =
      Eigen::Vector3d(offset / minor * x_mm / rho, offset / minor * y_mm / rho, height_mm / minor);
  point.kappa1 = 1.0 / minor;
  point.kappa2 = offset / (minor * rho);
  return point;
}

ShapePoint ellipsoid_point(const AnalyticDimensions& d, double x_mm, double y_mm) {
  const double a = d.ellipsoid_semi_axes_mm.x();
  const double b = d.ellipsoid_semi_axes_mm.y();
  const double c = d.ellipsoid_semi_axes_mm.z();
  const double u = 1.0 - x_mm * x_mm / (a * a) - y_mm * y_mm / (b * b);
  if (u <= 0.0) return {};
  // z = c sqrt(u) and its exact derivatives.
  const double root_u = std::sqrt(u);
  const double u_32 = u * root_u;
  const double fx = -c * x_mm / (a * a * root_u);
  const double fy = -c * y_mm / (b * b * root_u);
  const double fxx = -c / (a * a * root_u) - c * x_mm * x_mm / (a * a * a * a * u_32);
  const double fyy = -c / (b * b * root_u) - c * y_mm * y_mm / (b * b * b * b * u_32);
  const double fxy = -c * x_mm * y_mm / (a * a * b * b * u_32);
  return graph_point(c * root_u, fx, fy, fxx, fxy, fyy);
}

ShapePoint capsule_point(const AnalyticDimensions& d, double x_mm, double y_mm) {
  const double r = d.capsule_radius_mm;
  const double half_length = 0.5 * d.capsule_length_mm;
  if (std::abs(x_mm) <= half_length) {
    ShapePoint point;
    if (std::abs(y_mm) >= r) return point;
    const double height_mm = std::sqrt(r * r - y_mm * y_mm);
    point.valid = true;
    point.z_mm = height_mm;
    point.normal = Eigen::Vector3d(0.0, y_mm, height_mm) / r;
    point.kappa1 = 1.0 / r;
    point.region = 1;
    return point;
  }
  const double centre_x = x_mm < 0.0 ? -half_length : half_length;
  ShapePoint point = sphere_point(r, x_mm - centre_x, y_mm, false);
  point.region = x_mm < 0.0 ? 0 : 2;
  return point;
}

constexpr std::array<double, 3> kBoxFaceAzimuthDeg = {90.0, 210.0, 330.0};

// The cube [-e, 0]^3 in face coordinates c_k = n_k . (p - apex), apex at z = e sqrt(3) so the
// hidden far corner is at z = 0. Seen along the body diagonal the three faces c_k = 0 tile a
// regular hexagon; above (x, y) the top point lies on the lowest of the three face planes,
// and it belongs to the cube when its other face coordinates are >= -e.
ShapePoint box_corner_point(const AnalyticDimensions& d, double x_mm, double y_mm) {
  const auto normals = box_corner_shape_normals();
  const double edge_mm = d.box_edge_mm;
  const Eigen::Vector3d apex(0.0, 0.0, edge_mm * std::sqrt(3.0));
  int face = 0;
  double z_mm = 0.0;
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector3d& n = normals[static_cast<std::size_t>(k)];
    const double plane_z = apex.z() - (n.x() * x_mm + n.y() * y_mm) / n.z();
    if (k == 0 || plane_z < z_mm) {
      z_mm = plane_z;
      face = k;
    }
  }
  const Eigen::Vector3d top(x_mm, y_mm, z_mm);
  for (const Eigen::Vector3d& n : normals) {
    if (n.dot(top - apex) < -edge_mm) return {};
  }
  ShapePoint point;
  point.valid = true;
  point.z_mm = z_mm;
  point.normal = normals[static_cast<std::size_t>(face)];
  point.region = face;
  return point;
}

}  // namespace

std::array<Eigen::Vector3d, 3> box_corner_shape_normals() {
  // Three mutually orthogonal unit vectors with n_z = 1/sqrt(3): their xy parts have length
  // sqrt(2/3) and lie 120 degrees apart, so n_i . n_j = (2/3) cos(120) + 1/3 = 0.
  std::array<Eigen::Vector3d, 3> normals;
  const double horizontal = std::sqrt(2.0 / 3.0);
  for (std::size_t k = 0; k < 3; ++k) {
    const double azimuth_rad = kBoxFaceAzimuthDeg[k] * std::numbers::pi / 180.0;
    normals[k] = Eigen::Vector3d(horizontal * std::cos(azimuth_rad),
                                 horizontal * std::sin(azimuth_rad), 1.0 / std::sqrt(3.0));
  }
  return normals;
}

ShapePoint analytic_shape_point(AnalyticShape shape, const AnalyticDimensions& dimensions,
                                double x_mm, double y_mm) {
  switch (shape) {
    case AnalyticShape::kSphere:
      return sphere_point(dimensions.radius_mm, x_mm, y_mm, false);
    case AnalyticShape::kCup:
      return sphere_point(dimensions.radius_mm, x_mm, y_mm, true);
    case AnalyticShape::kCylinder:
      return cylinder_point(dimensions, x_mm, y_mm);
    case AnalyticShape::kSaddle:
      return saddle_point(dimensions, x_mm, y_mm);
    case AnalyticShape::kPlane:
      return plane_point(dimensions, x_mm, y_mm);
    case AnalyticShape::kTorus:
      return torus_point(dimensions, x_mm, y_mm);
    case AnalyticShape::kEllipsoid:
      return ellipsoid_point(dimensions, x_mm, y_mm);
    case AnalyticShape::kCapsule:
      return capsule_point(dimensions, x_mm, y_mm);
    case AnalyticShape::kBoxCorner:
      return box_corner_point(dimensions, x_mm, y_mm);
  }
  return {};
}

double analytic_silhouette_extent_mm(AnalyticShape shape, const AnalyticDimensions& d,
                                     const Eigen::Vector2d& direction) {
  const double ax = std::abs(direction.x());
  const double ay = std::abs(direction.y());
  switch (shape) {
    case AnalyticShape::kSphere:
    case AnalyticShape::kCup:
      return d.radius_mm;
    case AnalyticShape::kCylinder:
      return ax * d.radius_mm + ay * 0.5 * d.cylinder_length_mm;
    case AnalyticShape::kSaddle:
      return (ax + ay) * d.saddle_half_width_mm;
    case AnalyticShape::kPlane:
      return (ax + ay) * d.plane_half_width_mm;
    case AnalyticShape::kTorus:
      return d.torus_major_radius_mm + d.torus_minor_radius_mm;
    case AnalyticShape::kEllipsoid:
      return std::hypot(ax * d.ellipsoid_semi_axes_mm.x(), ay * d.ellipsoid_semi_axes_mm.y());
    case AnalyticShape::kCapsule:
      return ax * 0.5 * d.capsule_length_mm + d.capsule_radius_mm;
    case AnalyticShape::kBoxCorner: {
      // The hexagon's vertices are +-e times the faces' horizontal normal parts.
      double extent = 0.0;
      for (const Eigen::Vector3d& n : box_corner_shape_normals()) {
        extent = std::max(extent, d.box_edge_mm * std::abs(n.head<2>().dot(direction)));
      }
      return extent;
    }
  }
  return 0.0;
}

}  // namespace cosmos
