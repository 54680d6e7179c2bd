// The distance to a mesh's surface: each Voronoi region of a triangle measured against its
// hand-worked value, and the hierarchy's walk against every triangle measured in turn; a
// hierarchy shared with the scanner's scene against one of its own.
#include "sim/mesh_surface_distance.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <random>

#include "sim/embree_scene.hpp"
#include "sim/procedural_meshes.hpp"

namespace cosmos {
namespace {

const Eigen::Vector3d kA(0, 0, 0), kB(4, 0, 0), kC(0, 3, 0);

TEST(PointTriangleDistance, EachRegionOfTheTriangleIsMeasuredToItsNearestFeature) {
  // Above the face: the height.
  EXPECT_DOUBLE_EQ(point_triangle_squared_distance({1, 1, 2}, kA, kB, kC), 4);
  // Beyond vertex B along x, 2 up: to B itself.
  EXPECT_DOUBLE_EQ(point_triangle_squared_distance({6, -1, 2}, kA, kB, kC), 4 + 1 + 4);
  // Below edge AB (y < 0), over its middle: to the edge.
  EXPECT_DOUBLE_EQ(point_triangle_squared_distance({2, -1, 1}, kA, kB, kC), 1 + 1);
  // Beyond the hypotenuse BC, on the line 3x + 4y = 12: (4, 3, 0) is (12 + 12 - 12) / 5 = 2.4
  // from it, and its foot (2.56, 1.08) lies between B and C.
  EXPECT_NEAR(point_triangle_squared_distance({4, 3, 0}, kA, kB, kC), 2.4 * 2.4, 1e-12);
  // Behind A: to A.
  EXPECT_DOUBLE_EQ(point_triangle_squared_distance({-1, -2, 0}, kA, kB, kC), 5);
  // On the face: zero.
  EXPECT_DOUBLE_EQ(point_triangle_squared_distance({1, 1, 0}, kA, kB, kC), 0);
}

TEST(PointTriangleDistance, ADegenerateTriangleIsMeasuredAsItsEdges) {
  // All three corners on the x axis: the segment from 0 to 4.
  const Eigen::Vector3d a(0, 0, 0), b(4, 0, 0), c(2, 0, 0);
  EXPECT_DOUBLE_EQ(point_triangle_squared_distance({2, 3, 0}, a, b, c), 9);
  EXPECT_DOUBLE_EQ(point_triangle_squared_distance({6, 0, 0}, a, b, c), 4);
  EXPECT_DOUBLE_EQ(point_triangle_squared_distance({1, 1, 1}, a, a, a), 3);
}

TEST(MeshSurfaceDistance, TheWalkAgreesWithMeasuringEveryTriangle) {
  const TriangleMesh sphere = make_icosphere(30, 3);
  const MeshSurfaceDistance distance(sphere);
  std::mt19937 random(11);
  std::uniform_real_distribution<double> coordinate(-60, 60);
  for (int query = 0; query < 300; ++query) {
    const Eigen::Vector3d p(coordinate(random), coordinate(random), 0.5 * coordinate(random));
    double every_mm2 = std::numeric_limits<double>::infinity();
    for (const Eigen::Vector3i& t : sphere.triangles)
      every_mm2 =
          std::min(every_mm2, point_triangle_squared_distance(
                                  p, sphere.vertices[static_cast<std::size_t>(t(0))].cast<double>(),
                                  sphere.vertices[static_cast<std::size_t>(t(1))].cast<double>(),
                                  sphere.vertices[static_cast<std::size_t>(t(2))].cast<double>()));
    ASSERT_DOUBLE_EQ(distance.nearest_squared_mm2(p), every_mm2) << "query " << query;
  }
}

TEST(MeshSurfaceDistance, APointOnAFaceIsOnTheSurfaceWhereNoVertexIs) {
  const TriangleMesh box = make_box(40, 20, 10);
  const MeshSurfaceDistance distance(box);
  // The middle of the top face, 5 mm above the box's centre: far from every corner.
  EXPECT_NEAR(distance.nearest_squared_mm2({0, 0, 5}), 0, 1e-12);
  EXPECT_NEAR(distance.nearest_squared_mm2({0, 0, 8}), 9, 1e-9);
}

TEST(MeshSurfaceDistance, AScannersHierarchyMeasuresAsItsOwnAndOutlivesTheScene) {
  const TriangleMesh sphere = make_icosphere(30, 3);
  const MeshSurfaceDistance own(sphere);
  std::unique_ptr<const MeshSurfaceDistance> shared;
  {
    EmbreeScene scene;
    scene.add_mesh(make_box(40, 20, 10));
    const int mesh = scene.add_mesh(sphere);
    shared = std::make_unique<const MeshSurfaceDistance>(scene, mesh);
    EXPECT_THROW(MeshSurfaceDistance(scene, 2), std::invalid_argument);
  }
  std::mt19937 random(13);
  std::uniform_real_distribution<double> coordinate(-60, 60);
  for (int query = 0; query < 300; ++query) {
    const Eigen::Vector3d p(coordinate(random), coordinate(random), coordinate(random));
    ASSERT_DOUBLE_EQ(shared->nearest_squared_mm2(p), own.nearest_squared_mm2(p))
        << "query " << query;
  }
  // The sphere's, not the box's: the box's centre is 5 mm under its top face.
  EXPECT_NEAR(std::sqrt(shared->nearest_squared_mm2(Eigen::Vector3d::Zero())), 30, 0.5);
}

TEST(MeshSurfaceDistance, AMeshWithoutTrianglesIsRefused) {
  EXPECT_THROW(MeshSurfaceDistance(TriangleMesh{}), std::invalid_argument);
  TriangleMesh bad = make_box(1, 1, 1);
  bad.triangles[0](1) = 99;
  EXPECT_THROW(MeshSurfaceDistance{bad}, std::invalid_argument);
}

}  // namespace
}  // namespace cosmos
