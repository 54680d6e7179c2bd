#pragma once
// How a part lies on the belt: its rotation (three modes) and its placement, lowest point on
// the belt surface z = 0. Rotations are R_belt_part: they turn part-frame vectors into the
// belt frame (conveyor_scene.hpp).
#include <Eigen/Geometry>
#include <cstdint>
#include <vector>

#include "core/parameter_visitor.hpp"
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

// The stable resting poses of a part, most likely first: the stable faces of its hull (as in
// resting_rotation), faces whose normals lie within merge_deg of a likelier one counted as that
// one (a curved side is many small hull faces), each with the chance that a dropped part
// settles on it. What a recognizer may try first for parts lying on a belt.
struct RestingPoseParameters {
  double merge_deg = 4.0;
  int max_poses = 32;
  double min_probability = 0.002;

  template <class Visitor>
  void visit(Visitor& v) {
    v("merge_deg", merge_deg, "stable faces this close in normal are one pose, deg", Range{0, 90});
    v("max_poses", max_poses, "the likeliest poses kept per part", Range{1, 1000});
    v("min_probability", min_probability, "less likely poses are not kept", Range{0, 1});
  }
};

struct StableRestingPose {
  Eigen::Matrix3d R_belt_part;  // the face down, no turn about the vertical
  double height_mm = 0;         // of the part's origin above the belt
  double probability = 0;
};

std::vector<StableRestingPose> stable_resting_poses(const TriangleMesh& mesh,
                                                    const RestingPoseParameters& parameters);

// The corners of the mesh's convex hull, each once (a flat mesh: its vertices): the points a
// part can touch the belt with.
std::vector<Eigen::Vector3d> hull_vertices(const TriangleMesh& mesh);

// T_belt_part placing the rotated part with its lowest vertex on the belt (z = 0) and the
// centre of its bounding box at (x_mm, y_mm).
Eigen::Isometry3d place_on_belt(const TriangleMesh& mesh, const Eigen::Matrix3d& R_belt_part,
                                double x_mm = 0.0, double y_mm = 0.0);

}  // namespace cosmos
