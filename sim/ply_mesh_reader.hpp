#pragma once
// PLY files (Stanford polygon format), read by the project: ASCII, binary little endian and
// binary big endian; the vertex element's x, y, z (any scalar type) and the face element's
// vertex_indices (or vertex_index) list of any integer types. Every other property and
// element is read past and skipped; faces of fewer than 3 corners (points, edges) are
// dropped, as they bound no surface.
//
// The header's element counts are weighed against the bytes after it before anything is
// allocated for them, as is every list's length; every face index is checked against the
// vertex count. Each refusal is one InputError line: "FILE:LINE: reason" in the header and an
// ASCII body, "FILE: byte OFFSET: reason" in a binary body.
#include <filesystem>

#include "sim/polygon_mesh.hpp"

namespace cosmos {

PolygonMesh read_ply_mesh(const std::filesystem::path& path);

}  // namespace cosmos
