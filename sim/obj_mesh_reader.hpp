#pragma once
// Wavefront OBJ files, their polygon geometry read by the project rather than a general
// importer: "v x y z" (a fourth number, the weight of rational curves, and three colour
// numbers after x y z as some scanners write them, are skipped) and "f" with corners "i",
// "i/t", "i//n" or "i/t/n", of 3 or more corners; an index counts from 1, a negative one back
// from the last vertex read before the face. Texture and normal indices must be integers and
// are not used.
//
// Statements that carry no polygon surface are skipped: vt, vn, vp, o, g, s, mg, usemtl,
// mtllib, l (lines), p (points) and the display attributes. Free-form geometry (cstype, curv,
// curv2, surf) is refused as such rather than dropped, since its surface would be missing from
// the part; so is a line continuation ('\' at a line's end) and any other statement. '#'
// starts a comment; a line ends at "\n", "\r\n" or a lone "\r"; a UTF-8 byte order mark
// at the start is skipped.
//
// A face may only index vertices read before it, so every index is checked where it stands;
// the mesh grows with the lines read, so it is bounded by the file's size. Each refusal is one
// InputError line "FILE:LINE: reason" (sim/mesh_text.hpp), vertices and faces numbered from 1
// as the file numbers them.
#include <filesystem>

#include "sim/polygon_mesh.hpp"

namespace cosmos {

PolygonMesh read_obj_mesh(const std::filesystem::path& path);

}  // namespace cosmos
