#pragma once
// STL files (stereolithography), binary and ASCII, read by the project rather than a general
// importer: a binary file is an 80-byte header, a little-endian uint32 triangle count and 50
// bytes per triangle (normal, three corners, attribute word); an ASCII file is "solid NAME",
// facets "facet normal nx ny nz / outer loop / vertex x y z (three times) / endloop /
// endfacet", then "endsolid [NAME]", and may hold several solids one after another. Keywords
// are read in any case; the facet normals are not used.
//
// A file is binary when its size is exactly what its count says (84 + 50 per triangle), even
// when its header starts with "solid" as some exporters write it; otherwise it is ASCII when it
// starts with "solid" and holds no NUL byte, and refused with its size and count when not.
// The count is so weighed against the file's size before anything is allocated for it.
//
// STL repeats each corner in every facet that has it: corners at exactly the same position
// (bit for bit once -0 is taken as 0) are welded into one vertex, in the order of their first
// use. Triangles are kept as the file has them, a degenerate one too. Each refusal is one
// InputError line: "FILE:LINE: reason" in ASCII and "FILE: byte OFFSET: reason" in binary.
#include <filesystem>

#include "sim/mesh.hpp"

namespace cosmos {

TriangleMesh read_stl_mesh(const std::filesystem::path& path);

}  // namespace cosmos
