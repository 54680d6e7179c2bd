#include "sim/procedural_meshes.hpp"

#include <cmath>
#include <map>
#include <stdexcept>
#include <utility>

namespace cosmos {

TriangleMesh make_icosphere(double radius_mm, int subdivisions) {
  if (!(radius_mm > 0.0) || subdivisions < 0 || subdivisions > 8) {
    throw std::invalid_argument("make_icosphere: radius must be > 0 and subdivisions in [0, 8]");
  }
  const double phi = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Eigen::Vector3d> unit = {
      {-1, phi, 0},  {1, phi, 0},  {-1, -phi, 0}, {1, -phi, 0}, {0, -1, phi},  {0, 1, phi},
      {0, -1, -phi}, {0, 1, -phi}, {phi, 0, -1},  {phi, 0, 1},  {-phi, 0, -1}, {-phi, 0, 1},
  };
  for (Eigen::Vector3d& v : unit) v.normalize();
  std::vector<Eigen::Vector3i> faces = {
      {0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
      {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
      {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1},
  };
  for (int level = 0; level < subdivisions; ++level) {
    // Shared edges get one midpoint, so the mesh stays watertight.
    std::map<std::pair<int, int>, int> midpoints;
    const auto midpoint = [&](int a, int b) {
      const std::pair<int, int> key(std::min(a, b), std::max(a, b));
      if (const auto it = midpoints.find(key); it != midpoints.end()) return it->second;
      unit.push_back(
          (unit[static_cast<std::size_t>(a)] + unit[static_cast<std::size_t>(b)]).normalized());
      const int index = static_cast<int>(unit.size()) - 1;
      midpoints.emplace(key, index);
      return index;
    };
    std::vector<Eigen::Vector3i> finer;
    finer.reserve(faces.size() * 4);
    for (const Eigen::Vector3i& f : faces) {
      const int ab = midpoint(f[0], f[1]);
      const int bc = midpoint(f[1], f[2]);
      const int ca = midpoint(f[2], f[0]);
      finer.emplace_back(f[0], ab, ca);
      finer.emplace_back(f[1], bc, ab);
      finer.emplace_back(f[2], ca, bc);
      finer.emplace_back(ab, bc, ca);
    }
    faces = std::move(finer);
  }
  TriangleMesh mesh;
  mesh.vertices.reserve(unit.size());
  for (const Eigen::Vector3d& v : unit) mesh.vertices.push_back((radius_mm * v).cast<float>());
  mesh.triangles = std::move(faces);
  return mesh;
}

double icosphere_max_sag_mm(const TriangleMesh& icosphere, double radius_mm) {
  double sag = 0.0;
  for (const Eigen::Vector3i& t : icosphere.triangles) {
    const Eigen::Vector3d a = icosphere.vertices[static_cast<std::size_t>(t[0])].cast<double>();
    const Eigen::Vector3d b = icosphere.vertices[static_cast<std::size_t>(t[1])].cast<double>();
    const Eigen::Vector3d c = icosphere.vertices[static_cast<std::size_t>(t[2])].cast<double>();
    const Eigen::Vector3d normal = (b - a).cross(c - a).normalized();
    sag = std::max(sag, radius_mm - std::abs(normal.dot(a)));
  }
  return sag;
}

TriangleMesh make_box(double size_x_mm, double size_y_mm, double size_z_mm) {
  if (!(size_x_mm > 0.0 && size_y_mm > 0.0 && size_z_mm > 0.0)) {
    throw std::invalid_argument("make_box: sizes must be > 0");
  }
  TriangleMesh mesh;
  const Eigen::Vector3f half(static_cast<float>(size_x_mm / 2), static_cast<float>(size_y_mm / 2),
                             static_cast<float>(size_z_mm / 2));
  for (int corner = 0; corner < 8; ++corner) {
    mesh.vertices.emplace_back((corner & 1) ? half.x() : -half.x(),
                               (corner & 2) ? half.y() : -half.y(),
                               (corner & 4) ? half.z() : -half.z());
  }
  // Corner index bits: x = 1, y = 2, z = 4.
  mesh.triangles = {
      {0, 2, 1}, {1, 2, 3},  // z = -
      {4, 5, 6}, {5, 7, 6},  // z = +
      {0, 1, 4}, {1, 5, 4},  // y = -
      {2, 6, 3}, {3, 6, 7},  // y = +
      {0, 4, 2}, {2, 4, 6},  // x = -
      {1, 3, 5}, {3, 7, 5},  // x = +
  };
  return mesh;
}

}  // namespace cosmos
