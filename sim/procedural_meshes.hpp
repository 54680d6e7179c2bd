#pragma once
// Meshes built in code, for tests and benchmarks that must not depend on the catalog cache:
// their true surfaces are known analytically. Both are centred on the origin, wound
// counter-clockwise seen from outside.
#include "sim/mesh.hpp"

namespace cosmos {

// Icosahedron split `subdivisions` times (20 · 4^n triangles), vertices on the sphere.
// The flat triangles lie inside the sphere by at most icosphere_max_sag_mm().
TriangleMesh make_icosphere(double radius_mm, int subdivisions);
// Largest distance between the sphere and the mesh surface (at a triangle's centroid).
double icosphere_max_sag_mm(const TriangleMesh& icosphere, double radius_mm);

// Axis-aligned box of the given extents (12 triangles).
TriangleMesh make_box(double size_x_mm, double size_y_mm, double size_z_mm);

}  // namespace cosmos
