#pragma once
// The view sphere of the model base (thesis §4.5): each catalog part is seen from the
// directions of a quasi-regular tessellation of the sphere built from the icosahedron. Its
// 20 faces are split into 4 (edge midpoints pushed out to the sphere) `subdivisions` times;
// the view directions are the face centres projected on the sphere, 20·4^subdivisions of
// them — 320 for the thesis' two subdivisions.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

namespace cosmos {

// Unit view directions in the part frame, in a fixed order: icosahedron face by face, and
// inside a face child by child (corner children 0,1,2 then the middle one, recursively), so a
// view index means the same direction in every build and every model base.
// subdivisions must be in [0, 6] (std::invalid_argument otherwise: 6 already gives 81,920).
std::vector<Eigen::Vector3d> view_directions(int subdivisions = 2);

// R_scanner_part: the rotation that turns the part so direction_part (a direction in the part
// frame, any non-zero length) points at the scanner, i.e. R * direction = +z of the scanner
// frame. The in-plane angle about the viewing axis is fixed by taking the shortest-arc
// rotation from the direction to +z (deterministic and continuous except at -z, where the
// half turn about the scanner's x axis is used). std::invalid_argument on a zero or
// non-finite direction.
Eigen::Matrix3d rotation_looking_along(const Eigen::Vector3d& direction_part);

}  // namespace cosmos
