#pragma once
// Mechanical parts built in code, for catalogs larger than the meshes Debian ships: prisms
// extruded from an outline (brackets, sections, channels, notched plates) and solids of
// revolution from a profile (stepped shafts, flanged bushings, knobs). Each family's
// proportions are drawn from a seed, so a catalog of them is the same on every machine and
// nothing downloaded is needed. `cosmos catalog procedural` writes them as OFF files into the
// mesh cache, where config/parts-250.yaml finds them.
#include <Eigen/Core>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "sim/mesh.hpp"

namespace cosmos {

// A closed prism: the simple polygon `outline_mm` (counter-clockwise seen from +z, no repeated
// closing point) from z = 0 to z = height_mm, caps triangulated by ear clipping, every face
// wound counter-clockwise seen from outside. std::invalid_argument for fewer than 3 points, a
// clockwise or degenerate outline, or a height that is not > 0.
TriangleMesh make_extrusion(std::span<const Eigen::Vector2d> outline_mm, double height_mm);

// A closed solid of revolution about z: `profile_rz_mm` runs from a point on the axis (r = 0)
// at the bottom up to a point on the axis at the top, with r > 0 in between; each of its
// points becomes a ring of `segments` vertices (a pole on the axis). Wound counter-clockwise
// seen from outside. std::invalid_argument for fewer than 3 points, ends off the axis, inner
// points on it, or fewer than 3 segments.
TriangleMesh make_revolution(std::span<const Eigen::Vector2d> profile_rz_mm, int segments);

struct ProceduralPart {
  std::string name;  // family-N, e.g. "l-bracket-3"
  TriangleMesh mesh;
  bool symmetric = false;  // solids of revolution are
};

// The families' names, in the order procedural_parts lists them.
std::vector<std::string> procedural_families();

// `per_family` parts of every family, family by family, part N of a family drawn from
// mix_seed(seed, family index * 1000 + N).
std::vector<ProceduralPart> procedural_parts(int per_family, std::uint64_t seed);

// Writes the mesh as an ASCII OFF file; InputError naming the file when it cannot.
void write_off_file(const TriangleMesh& mesh, const std::filesystem::path& path);

}  // namespace cosmos
