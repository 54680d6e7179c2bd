#pragma once
// The mesh formats read through assimp (STL, OBJ): every triangle of every mesh in the file's
// scene (node transforms applied), polygons triangulated, identical vertices joined, points
// and lines dropped. OFF and PLY have the project's own readers (sim/off_mesh_reader.hpp,
// sim/ply_mesh_reader.hpp): assimp trusted their counts and line ends and crashed or
// allocated without bound on malformed files.
#include <filesystem>

#include "sim/mesh.hpp"

namespace cosmos {

// Throws InputError on a file assimp cannot read (its reason on one line) or a NaN/inf
// vertex. Vertices no triangle uses may remain.
TriangleMesh read_assimp_mesh(const std::filesystem::path& path);

}  // namespace cosmos
