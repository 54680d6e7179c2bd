#pragma once
// A part's whole model surface as a distance field, for the pose search's coarse stage
// (part_pose_search.hpp). One model view covers only what the scanner saw from its
// direction, with its own laser shadows, so a scene seen from 10-15 degrees away, or turned
// so that other parts of it are shadowed, matches that view poorly even at its true pose;
// against the union of all the part's views it matches wherever it is. The field holds, on a
// regular voxel grid over the part frame, the distance to the nearest voxel holding a control
// point of any of the part's views (the exact Euclidean distance transform of Felzenszwalb &
// Huttenlocher, 2012), trilinearly interpolated: a table lookup per query instead of a
// tangent-plane search, so thousands of start poses can be scored and aligned per part.
// Distances are accurate to half a voxel diagonal: enough to rank starts, never used for the
// final pose (ch. 6 registration on the views does that). So each voxel keeps its distance in
// 16 bits, in steps of the grid's largest distance / 65535 (a few micrometres on real parts,
// a thousandth of that accuracy): half the memory of floats for every part of the catalog.
#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "core/parameter_visitor.hpp"
#include "core/registration/belt_contact.hpp"
#include "core/registration/part_surface_voxels.hpp"
#include "core/registration/registration_points.hpp"
#include "core/rigid_transform.hpp"

namespace cosmos {

class PartDistanceField {
 public:
  PartDistanceField() = default;
  // The distance transform of the occupied voxels, on their grid; empty when they are empty
  // or not consistent (part_surface_voxels_consistent).
  explicit PartDistanceField(const PartSurfaceVoxels& voxels);
  // `points_part_mm`: the part's surface points in the part frame (part_surface_voxels).
  PartDistanceField(const std::vector<Eigen::Vector3d>& points_part_mm,
                    const PartDistanceFieldParameters& parameters);

  // At most kMaxSurfaceVoxels of 2 bytes: 32 MiB.
  static constexpr std::size_t kMaxVoxels = kMaxSurfaceVoxels;

  bool empty() const { return distance_units_.empty(); }
  std::size_t voxel_count() const { return distance_units_.size(); }
  std::size_t memory_bytes() const { return distance_units_.size() * sizeof(std::uint16_t); }
  double voxel_mm() const { return voxel_mm_; }
  // Distance to the part's surface; beyond the grid, at least the margin (the grid edge's
  // value plus the way out). The gradient is that of the trilinear interpolant (zero
  // outside the grid).
  double distance_mm(const Eigen::Vector3d& point_part_mm) const {
    return interpolate(point_part_mm, nullptr);
  }
  double distance_mm(const Eigen::Vector3d& point_part_mm, Eigen::Vector3d& gradient) const {
    return interpolate(point_part_mm, &gradient);
  }

 private:
  double interpolate(const Eigen::Vector3d& point_part_mm, Eigen::Vector3d* gradient) const;
  // The gradient only when asked: scoring, most of the queries, needs none. Inlined into the
  // scoring and alignment loops (this file's free functions are its friends).
  template <bool kGradient>
  double sample(const Eigen::Vector3d& point_part_mm, Eigen::Vector3d& gradient) const;
  friend double field_truncated_mean_square_mm2(const RegistrationPoints&, const PartDistanceField&,
                                                const RigidTransform&, double, double);
  friend double field_fraction_within(const RegistrationPoints&, const PartDistanceField&,
                                      const RigidTransform&, double);
  friend RigidTransform align_in_distance_field(const RegistrationPoints&, const PartDistanceField&,
                                                const RigidTransform&, int, double,
                                                const BeltContact&);

  Eigen::Vector3d origin_mm_ = Eigen::Vector3d::Zero();  // centre of voxel (0, 0, 0)
  double voxel_mm_ = 1.0;
  double voxels_per_mm_ = 1.0;  // multiplying is several times faster than dividing
  int size_[3] = {0, 0, 0};
  double mm_per_unit_ = 0.0;
  std::vector<std::uint16_t> distance_units_;  // x fastest
};

// Mean over the scene points of min(d^2, truncation^2), d their distance to the part surface
// under T_part_scene.
// With `abandon_above_mm2`, the sum stops once the mean is sure to exceed it: the value
// returned is then some value above it, not the mean (a search that keeps the best few poses
// needs no more of the others; the kept ones' values are the same to the last bit).
double field_truncated_mean_square_mm2(
    const RegistrationPoints& scene, const PartDistanceField& field,
    const RigidTransform& T_part_scene, double truncation_mm,
    double abandon_above_mm2 = std::numeric_limits<double>::infinity());

// The fraction of the scene points within `distance_mm` of the part surface under
// T_part_scene.
double field_fraction_within(const RegistrationPoints& scene, const PartDistanceField& field,
                             const RigidTransform& T_part_scene, double distance_mm);

// Whether a pose is worth registering (ch. 6): registration refines a start, it rarely
// rescues one under which much of the scene is nowhere near the part. Support needs 60 % of
// the scene within 0.2 mm of the part's views (part_support.hpp); a start with less than half
// of it within 2 mm (the field's resolution) of all of them hardly gets there. On the
// acceptance scans the gate skips a large share of the registrations that would end below
// that support and none of those that reach it.
struct FieldGate {
  double distance_mm = 2.0;
  double min_fraction = 0.5;
  bool passes(const RegistrationPoints& scene, const PartDistanceField& field,
              const RigidTransform& T_part_scene) const {
    return field_fraction_within(scene, field, T_part_scene, distance_mm) >= min_fraction;
  }

  template <class Visitor>
  void visit(Visitor& v) {
    v("distance_mm", distance_mm, "scene points this close to the part count, mm",
      Range::above(0, 1e3));
    v("min_fraction", min_fraction, "a pose passes with this share of them", Range{0, 1});
  }
};

// Gauss-Newton on the scene points' distances to the field (those within the truncation),
// `iterations` steps from T_part_scene: a registration that needs no correspondences. Held on
// the belt when `belt` holds (belt_contact.hpp; its T_model_part the identity, as the field
// is in the part's frame).
RigidTransform align_in_distance_field(const RegistrationPoints& scene,
                                       const PartDistanceField& field,
                                       const RigidTransform& T_part_scene, int iterations,
                                       double truncation_mm, const BeltContact& belt = {});

}  // namespace cosmos
