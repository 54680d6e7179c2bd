#pragma once
// How a part lies on the belt: its rotation (three modes) and its placement, lowest point on
// the belt surface z = 0. Rotations are R_belt_part: they turn part-frame vectors into the
// belt frame (conveyor_scene.hpp).
#include <Eigen/Geometry>
#include <cstdint>

#include "sim/mesh.hpp"

namespace cosmos {

// Rz(rz) · Ry(ry) · Rx(rx), angles in degrees about the belt frame's axes: first about x,
// then y, then z.
Eigen::Matrix3d rotation_from_xyz_deg(double rx_deg, double ry_deg, double rz_deg);

// A rotation drawn uniformly from SO(3) (Shoemake's unit-quaternion method) by the seed.
Eigen::Matrix3d random_rotation(std::uint64_t seed);

// Centre of mass of the part as a homogeneous solid: the mesh's volume centroid when the
// surface encloses a volume (at least 1 % of its hull's, and the centroid inside the hull),
// otherwise the centroid of the solid convex hull (open or inconsistently wound meshes); the
// vertex mean for a flat mesh.
Eigen::Vector3d centre_of_mass(const TriangleMesh& mesh);

// A quasi-static resting pose: the part is dropped with a random orientation and settles on
// a face of its convex hull. The model: the stable faces are those through which the centre
// of mass projects inside the face; one of them is drawn with probability proportional to
// the solid angle it subtends at the centre of mass (the chance that the downward direction
// of a uniformly random orientation passes through it), then the part is turned so that face
// lies on the belt, and about the vertical by a uniformly random angle. Deterministic in the
// seed. A flat mesh (no hull volume) lies on its plane.
Eigen::Matrix3d resting_rotation(const TriangleMesh& mesh, std::uint64_t seed);

// T_belt_part placing the rotated part with its lowest vertex on the belt (z = 0) and the
// centre of its bounding box at (x_mm, y_mm).
Eigen::Isometry3d place_on_belt(const TriangleMesh& mesh, const Eigen::Matrix3d& R_belt_part,
                                double x_mm = 0.0, double y_mm = 0.0);

}  // namespace cosmos
