#pragma once
// ASCII OFF files (Geomview's Object File Format), read by the project: the optional keyword
// ([ST][C][N]OFF: texture coordinates, colours and normals after a vertex's x y z are
// skipped), the counts line "vertices faces [edges]", one vertex per line, then one face per
// line "n i1 ... in" (a face colour after the indices is skipped). '#' starts a comment; a
// line ends at "\n", "\r\n" or a lone "\r".
//
// The counts are weighed against the file's size before anything is allocated for them, and
// every face index against the vertex count. Each refusal is one InputError line
// "FILE:LINE: reason" (sim/mesh_text.hpp). Homogeneous (4OFF), n-dimensional (nOFF) and binary
// OFF files are refused as such.
#include <filesystem>

#include "sim/polygon_mesh.hpp"

namespace cosmos {

PolygonMesh read_off_mesh(const std::filesystem::path& path);

}  // namespace cosmos
