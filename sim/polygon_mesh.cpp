#include "sim/polygon_mesh.hpp"

#include <Eigen/Geometry>
#include <cstddef>

namespace cosmos {
namespace {

// Twice the signed area of the 2D triangle a, b, c (> 0 counter-clockwise).
float cross_2d(const Eigen::Vector2f& a, const Eigen::Vector2f& b, const Eigen::Vector2f& c) {
  return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
}

bool inside_triangle(const Eigen::Vector2f& p, const Eigen::Vector2f& a, const Eigen::Vector2f& b,
                     const Eigen::Vector2f& c) {
  return cross_2d(a, b, p) >= 0.0f && cross_2d(b, c, p) >= 0.0f && cross_2d(c, a, p) >= 0.0f;
}

// The polygon's corners projected on the plane of its Newell normal, in a frame where the
// polygon winds counter-clockwise; nothing when its area is zero.
std::optional<std::vector<Eigen::Vector2f>> projected_corners(
    const std::vector<Eigen::Vector3f>& vertices, const int* corners, int count) {
  Eigen::Vector3f normal = Eigen::Vector3f::Zero();
  for (int k = 0; k < count; ++k) {
    const Eigen::Vector3f& a = vertices[static_cast<std::size_t>(corners[k])];
    const Eigen::Vector3f& b = vertices[static_cast<std::size_t>(corners[(k + 1) % count])];
    normal += a.cross(b);
  }
  if (!(normal.norm() > 0.0f)) return std::nullopt;
  normal.normalize();
  const Eigen::Vector3f u = normal.unitOrthogonal();
  const Eigen::Vector3f v = normal.cross(u);
  std::vector<Eigen::Vector2f> points;
  points.reserve(static_cast<std::size_t>(count));
  for (int k = 0; k < count; ++k) {
    const Eigen::Vector3f& p = vertices[static_cast<std::size_t>(corners[k])];
    points.emplace_back(p.dot(u), p.dot(v));
  }
  return points;
}

void add_fan(const int* corners, int count, std::vector<Eigen::Vector3i>& triangles) {
  for (int k = 1; k + 1 < count; ++k)
    triangles.emplace_back(corners[0], corners[k], corners[k + 1]);
}

// Ear clipping costs up to the cube of the corner count: a larger polygon (none in the
// catalog; a hostile file can hold thousands of corners) is cut as a fan.
constexpr int kMaxEarClippedCorners = 64;

void add_polygon(const std::vector<Eigen::Vector3f>& vertices, const int* corners, int count,
                 std::vector<Eigen::Vector3i>& triangles) {
  const auto points = count > 3 && count <= kMaxEarClippedCorners
                          ? projected_corners(vertices, corners, count)
                          : std::nullopt;
  if (!points) {
    add_fan(corners, count, triangles);
    return;
  }
  std::vector<int> left(static_cast<std::size_t>(count));  // positions in corners still uncut
  for (int k = 0; k < count; ++k) left[static_cast<std::size_t>(k)] = k;
  const auto at = [&](std::size_t k) { return (*points)[static_cast<std::size_t>(left[k])]; };
  while (left.size() > 3) {
    const std::size_t n = left.size();
    bool cut = false;
    for (std::size_t k = 0; k < n && !cut; ++k) {
      const std::size_t before = (k + n - 1) % n, after = (k + 1) % n;
      if (!(cross_2d(at(before), at(k), at(after)) > 0.0f)) continue;  // reflex or flat corner
      bool ear = true;
      for (std::size_t other = 0; other < n && ear; ++other)
        if (other != before && other != k && other != after)
          ear = !inside_triangle(at(other), at(before), at(k), at(after));
      if (!ear) continue;
      triangles.emplace_back(corners[left[before]], corners[left[k]], corners[left[after]]);
      left.erase(left.begin() + static_cast<std::ptrdiff_t>(k));
      cut = true;
    }
    if (!cut) break;  // no ear left: a self-touching or degenerate rest
  }
  std::vector<int> rest;
  rest.reserve(left.size());
  for (int k : left) rest.push_back(corners[k]);
  add_fan(rest.data(), static_cast<int>(rest.size()), triangles);
}

}  // namespace

TriangleMesh triangulate(const PolygonMesh& mesh) {
  TriangleMesh triangles;
  triangles.vertices = mesh.vertices;
  std::size_t count = 0;
  for (int corners : mesh.face_corners) count += static_cast<std::size_t>(corners - 2);
  triangles.triangles.reserve(count);
  const int* corners = mesh.corners.data();
  for (int face_corners : mesh.face_corners) {
    add_polygon(mesh.vertices, corners, face_corners, triangles.triangles);
    corners += face_corners;
  }
  return triangles;
}

}  // namespace cosmos
