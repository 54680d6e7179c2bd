#pragma once
// Distance from a point to the nearest point of a triangle mesh's surface (not to its nearest
// vertex): Embree 3's point query walks the mesh's bounding-volume hierarchy, and each
// triangle the query sphere reaches is measured exactly (the closest point of a triangle,
// Ericson, "Real-Time Collision Detection", §5.1.5), in double precision.
//
// Why the surface: a CAD part's mesh has few vertices on its smooth stretches (a knob of
// revolution is a few rings of vertices), so the distance to the nearest vertex counts up to
// half a ring's spacing for a point that lies on the part's surface.
//
// The triangles are read from the buffers Embree keeps for its hierarchy (float, as the
// mesh's vertices are), so a measure holds no copy of its mesh; and one can share the
// hierarchy the simulated scanner built for the same mesh, so a simulated cell that measures
// its poses holds each mesh's hierarchy once.
//
// Thread-safe for queries once built: each query keeps its own state; a hierarchy shared
// with a scanner is never changed after it was built.
#include <Eigen/Core>
#include <memory>

#include "sim/mesh.hpp"

namespace cosmos {

class EmbreeScene;

class MeshSurfaceDistance {
 public:
  // The mesh's vertices in its own frame, mm. std::invalid_argument when it has no triangle
  // or an index out of range.
  explicit MeshSurfaceDistance(const TriangleMesh& mesh);
  // Mesh `mesh` of `scene` (EmbreeScene::add_mesh), its hierarchy shared: it stays valid
  // after the scene is gone. std::invalid_argument when the scene has no such mesh.
  MeshSurfaceDistance(const EmbreeScene& scene, int mesh);
  ~MeshSurfaceDistance();
  MeshSurfaceDistance(const MeshSurfaceDistance&) = delete;
  MeshSurfaceDistance& operator=(const MeshSurfaceDistance&) = delete;

  // Squared distance (mm^2) from `point_mm` (the mesh's frame) to the nearest surface point.
  double nearest_squared_mm2(const Eigen::Vector3d& point_mm) const;

 private:
  struct Hierarchy;
  std::unique_ptr<Hierarchy> hierarchy_;
};

// Squared distance from `point` to the nearest point of triangle (a, b, c); a degenerate
// triangle is measured as its edges.
double point_triangle_squared_distance(const Eigen::Vector3d& point, const Eigen::Vector3d& a,
                                       const Eigen::Vector3d& b, const Eigen::Vector3d& c);

}  // namespace cosmos
