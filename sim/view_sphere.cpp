#include "sim/view_sphere.hpp"

#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace cosmos {
namespace {

using Triangle = std::array<Eigen::Vector3d, 3>;

// The 12 icosahedron vertices are the cyclic permutations of (0, ±1, ±φ); the 20 faces are
// listed explicitly (counter-clockwise seen from outside) so the order never depends on a
// hull algorithm.
std::array<Eigen::Vector3d, 12> icosahedron_vertices() {
  const double phi = (1.0 + std::sqrt(5.0)) / 2.0;
  std::array<Eigen::Vector3d, 12> v = {{
      {-1, phi, 0},
      {1, phi, 0},
      {-1, -phi, 0},
      {1, -phi, 0},
      {0, -1, phi},
      {0, 1, phi},
      {0, -1, -phi},
      {0, 1, -phi},
      {phi, 0, -1},
      {phi, 0, 1},
      {-phi, 0, -1},
      {-phi, 0, 1},
  }};
  for (Eigen::Vector3d& vertex : v) vertex.normalize();
  return v;
}

constexpr std::array<std::array<int, 3>, 20> kIcosahedronFaces = {{
    {0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
    {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
    {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1},
}};

// Depth-first so the children of one face stay next to each other in the output order.
void subdivide(const Triangle& face, int levels, std::vector<Eigen::Vector3d>& centres) {
  if (levels == 0) {
    centres.push_back((face[0] + face[1] + face[2]).normalized());
    return;
  }
  const Eigen::Vector3d m01 = (face[0] + face[1]).normalized();
  const Eigen::Vector3d m12 = (face[1] + face[2]).normalized();
  const Eigen::Vector3d m20 = (face[2] + face[0]).normalized();
  subdivide({face[0], m01, m20}, levels - 1, centres);
  subdivide({m01, face[1], m12}, levels - 1, centres);
  subdivide({m20, m12, face[2]}, levels - 1, centres);
  subdivide({m01, m12, m20}, levels - 1, centres);
}

}  // namespace

std::vector<Eigen::Vector3d> view_directions(int subdivisions) {
  if (subdivisions < 0 || subdivisions > 6) {
    throw std::invalid_argument("view_directions: subdivisions must be in [0, 6]");
  }
  const auto vertices = icosahedron_vertices();
  std::vector<Eigen::Vector3d> centres;
  centres.reserve(static_cast<std::size_t>(20) << (2 * subdivisions));
  for (const auto& face : kIcosahedronFaces) {
    subdivide({vertices[face[0]], vertices[face[1]], vertices[face[2]]}, subdivisions, centres);
  }
  return centres;
}

Eigen::Matrix3d rotation_looking_along(const Eigen::Vector3d& direction_part) {
  const double norm = direction_part.norm();
  if (!(norm > 0.0) || !std::isfinite(norm)) {
    throw std::invalid_argument("rotation_looking_along: direction must be finite and non-zero");
  }
  const Eigen::Vector3d d = direction_part / norm;
  const Eigen::Vector3d z = Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d axis = d.cross(z);  // |axis| = sin(angle)
  const double cos_angle = d.dot(z);
  const double sin_angle = axis.norm();
  // Near -z the shortest arc's axis is ill-conditioned; a fixed half turn about x keeps the
  // result deterministic and exact there.
  if (sin_angle < 1e-12) {
    return cos_angle > 0.0
               ? Eigen::Matrix3d::Identity()
               : Eigen::AngleAxisd(std::numbers::pi, Eigen::Vector3d::UnitX()).toRotationMatrix();
  }
  return Eigen::AngleAxisd(std::atan2(sin_angle, cos_angle), axis / sin_angle).toRotationMatrix();
}

}  // namespace cosmos
