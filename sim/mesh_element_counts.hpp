#pragma once
// The checks assimp does not make on the two mesh formats that announce their sizes, run on
// the file before assimp reads it (sim/mesh.hpp): a PLY or OFF header claiming more vertices
// or faces than the file's bytes can hold is refused at once (assimp reserved memory for the
// claim: a 200-byte PLY header announcing 2e9 vertices grew to 16 GB), and a face indexing a
// vertex the file does not have is refused (assimp's OFF reader clamps such an index to the
// last vertex, its PLY reader keeps it). Each refusal is one InputError line naming the file.
// STL announces no vertices (assimp checks a binary STL's triangle count against its size)
// and OBJ none at all (assimp refuses its bad indices itself).
#include <filesystem>

namespace cosmos {

// For .ply and .off files (any case); other extensions pass unchecked.
void check_mesh_element_counts(const std::filesystem::path& path);

}  // namespace cosmos
