#pragma once
// A mesh as OFF and PLY files hold it: vertices and polygon faces of any corner count, before
// it becomes the TriangleMesh the simulator scans (sim/mesh.hpp).
#include <Eigen/Core>
#include <vector>

#include "sim/mesh.hpp"

namespace cosmos {

struct PolygonMesh {
  std::vector<Eigen::Vector3f> vertices;
  std::vector<int> corners;       // every face's vertex indices, face after face
  std::vector<int> face_corners;  // each face's corner count (>= 3), in file order
};

// Each face split into corner count - 2 triangles, winding kept. A polygon is cut by ear
// clipping in the plane of its Newell normal, so a non-convex face (an L-shaped cap) is not
// covered past its edges; a degenerate one (collinear or repeated corners) falls back to a
// fan from its first corner, as is a polygon of more than 64 corners. Vertices are copied as they
// are.
TriangleMesh triangulate(const PolygonMesh& mesh);

}  // namespace cosmos
