#pragma once
// Triangle meshes of catalog parts, read from CAD/scan files by the project's own readers
// (sim/off_mesh_reader.hpp, sim/ply_mesh_reader.hpp, sim/stl_mesh_reader.hpp,
// sim/obj_mesh_reader.hpp). A part is simulated at its physical size, so a loaded mesh is
// centred (bounding-box centre at the origin) and uniformly scaled so its largest bounding-box
// extent is the catalog's size_mm: the files' own units (often unit boxes or arbitrary) never
// matter.
//
// Every defect of the file (missing, unknown extension, malformed, no triangles, NaN/inf
// coordinates, all vertices at one point, a header or a binary STL count claiming more than the
// file holds, a face indexing a missing vertex) throws cosmos::InputError with one line naming
// the file (and the line of a text file or the byte of a binary body) and the reason.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace cosmos {

struct TriangleMesh {
  std::vector<Eigen::Vector3f> vertices;   // mm once loaded with a size
  std::vector<Eigen::Vector3i> triangles;  // indices into vertices, winding kept from the file
};

// Reads every triangle of the file (of every solid of an STL file, of every object and group
// of an OBJ file), in the file's own units. Polygons are triangulated, vertices at the same
// position joined and vertices no triangle uses dropped; points and lines are dropped.
// Throws InputError on any defect listed above.
TriangleMesh read_mesh_file(const std::filesystem::path& path);

// read_mesh_file, then centred and scaled so the largest bounding-box extent is size_mm.
// size_mm must be finite and > 0 (InputError naming the file otherwise).
TriangleMesh load_mesh(const std::filesystem::path& path, double size_mm);

// The reason a vertex read from a file cannot be used ("(0, inf, 0) has a NaN or infinite
// coordinate"), or nothing.
std::optional<std::string> vertex_defect(const Eigen::Vector3f& vertex);

// Axis-aligned bounding box of the vertices (empty box for an empty mesh).
Eigen::AlignedBox3f bounding_box(const TriangleMesh& mesh);

// Moves the bounding-box centre to the origin and scales uniformly so the largest extent is
// size_mm. The mesh must have a non-zero extent and size_mm must be > 0 (read_mesh_file and
// load_mesh guarantee the first; std::invalid_argument otherwise, as it is a caller bug).
void center_and_scale(TriangleMesh& mesh, double size_mm);

}  // namespace cosmos
