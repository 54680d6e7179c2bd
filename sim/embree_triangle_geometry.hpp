#pragma once
// A triangle mesh handed to Embree 3: its vertices (mm, float as Embree stores them) and
// triangles copied into buffers Embree allocates and pads for its vector loads, the geometry
// committed. Shared by the scanner's ray casting (embree_scene.hpp) and the distance to a
// mesh's surface (mesh_surface_distance.hpp).
//
// Only .cpp files include this header: it brings in Embree's C API.
#include <embree3/rtcore.h>

#include "sim/mesh.hpp"

namespace cosmos {

// A committed triangle geometry of `mesh` on `device`, which the caller attaches and
// releases. std::invalid_argument ("<who>: ...") when the mesh has no triangle or an index
// out of range; std::runtime_error when Embree cannot allocate the buffers.
RTCGeometry new_triangle_geometry(RTCDevice device, const TriangleMesh& mesh, const char* who);

// The buffers of the one triangle geometry of `scene` (one new_triangle_geometry attached),
// which Embree keeps as long as the scene: x, y, z per vertex and three vertex indices per
// triangle.
struct TriangleBuffers {
  const float* vertices_mm = nullptr;
  const unsigned* triangles = nullptr;
};
TriangleBuffers triangle_buffers(RTCScene scene);

}  // namespace cosmos
