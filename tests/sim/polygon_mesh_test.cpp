// Triangulating polygon faces: corner count - 2 triangles each, winding kept, a non-convex
// face covered exactly (its triangles' areas add up to its own), a degenerate one fanned.
#include "sim/polygon_mesh.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace cosmos {
namespace {

PolygonMesh one_face(const std::vector<Eigen::Vector3f>& corners) {
  PolygonMesh mesh;
  mesh.vertices = corners;
  for (int k = 0; k < static_cast<int>(corners.size()); ++k) mesh.corners.push_back(k);
  mesh.face_corners.push_back(static_cast<int>(corners.size()));
  return mesh;
}

// Each triangle's normal (unnormalized: twice its area), summed.
Eigen::Vector3f summed_area_normals(const TriangleMesh& mesh) {
  Eigen::Vector3f sum = Eigen::Vector3f::Zero();
  for (const Eigen::Vector3i& t : mesh.triangles) {
    const Eigen::Vector3f& a = mesh.vertices[static_cast<std::size_t>(t[0])];
    const Eigen::Vector3f& b = mesh.vertices[static_cast<std::size_t>(t[1])];
    const Eigen::Vector3f& c = mesh.vertices[static_cast<std::size_t>(t[2])];
    sum += (b - a).cross(c - a);
  }
  return sum;
}

float summed_areas(const TriangleMesh& mesh) {
  float sum = 0;
  for (const Eigen::Vector3i& t : mesh.triangles) {
    const Eigen::Vector3f& a = mesh.vertices[static_cast<std::size_t>(t[0])];
    sum += 0.5f * (mesh.vertices[static_cast<std::size_t>(t[1])] - a)
                      .cross(mesh.vertices[static_cast<std::size_t>(t[2])] - a)
                      .norm();
  }
  return sum;
}

TEST(PolygonTriangulation, ATriangleStaysAsItIs) {
  const TriangleMesh mesh = triangulate(one_face({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}));
  ASSERT_EQ(mesh.triangles.size(), 1u);
  EXPECT_EQ(mesh.triangles[0], Eigen::Vector3i(0, 1, 2));
}

// An L in the plane x + y + z = const, tilted so no axis plane would do: 6 corners, area 3,
// clockwise seen from +normal so the winding must be kept.
TEST(PolygonTriangulation, ANonConvexPolygonIsCoveredExactlyWithItsWinding) {
  const Eigen::Vector3f u = Eigen::Vector3f(1, -1, 0).normalized();
  const Eigen::Vector3f v = Eigen::Vector3f(1, 1, -2).normalized();
  std::vector<Eigen::Vector3f> corners;
  const float l_shape[6][2] = {{0, 0}, {0, 2}, {1, 2}, {1, 1}, {2, 1}, {2, 0}};
  for (const auto& p : l_shape) corners.push_back(Eigen::Vector3f(5, 6, 7) + p[0] * u + p[1] * v);
  const TriangleMesh mesh = triangulate(one_face(corners));
  ASSERT_EQ(mesh.triangles.size(), 4u);
  EXPECT_NEAR(summed_areas(mesh), 3.0f, 1e-5f);  // > 3 if a triangle crossed the notch
  const Eigen::Vector3f normal = u.cross(v);
  EXPECT_NEAR(summed_area_normals(mesh).dot(normal), -6.0f, 1e-4f);
}

TEST(PolygonTriangulation, QuadsOfAMeshEachBecomeTwoTriangles) {
  PolygonMesh mesh = one_face({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}});
  mesh.corners = {0, 1, 2, 3, 0, 1, 4};
  mesh.face_corners = {4, 3};
  const TriangleMesh triangles = triangulate(mesh);
  ASSERT_EQ(triangles.triangles.size(), 3u);
  EXPECT_EQ(triangles.triangles[2], Eigen::Vector3i(0, 1, 4));
  EXPECT_NEAR(summed_area_normals(triangles).z(), 2.0f, 1e-6f);
}

TEST(PolygonTriangulation, ADegeneratePolygonIsFannedFromItsFirstCorner) {
  const TriangleMesh mesh =
      triangulate(one_face({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}, {4, 0, 0}}));
  ASSERT_EQ(mesh.triangles.size(), 3u);
  EXPECT_EQ(mesh.triangles[0], Eigen::Vector3i(0, 1, 2));
  EXPECT_EQ(mesh.triangles[2], Eigen::Vector3i(0, 3, 4));
}

}  // namespace
}  // namespace cosmos
