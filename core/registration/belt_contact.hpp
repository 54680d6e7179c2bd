#pragma once
// Parts that lie on the belt touch it with their lowest point. The belt is the plane z = 0 of
// the scene's frame (docs/architecture.md, Frames); a pose of the part that floats above it or
// sinks into it is not a pose the part can lie in. A registration that knows so holds the
// part on it: besides the scene's points, the part's lowest convex-hull corner is a
// point-to-plane row on the belt, and so is every corner below it. Without those rows only the
// scene's faces decide the pose, and where a view shows two or three flat faces the iterations
// can slide the part along them until it floats millimetres above the belt or sinks into it, a
// pose the decision then refuses although the part is the scene's.
//
// Under T_model_scene the belt is the plane through t (the scene origin's image) with normal
// n = R e_z, and a corner v stands h = n . (v - t) above it. As a correspondence that is the
// belt's point under v, b = v - h n, against the model's plane through v with normal -n: its
// signed distance -n . (b - v) is h, and a small motion of the scene (the belt with it) changes
// h to first order as it does a scene point's distance to the model: both registrations
// (view_registration.hpp, part_distance_field.hpp) take the rows as they take their points.
// Every corner below the belt is lifted, not the lowest alone: a part lying on a face has all
// of that face's corners level with the belt, and pulling on one of them would tilt it.
#include <Eigen/Core>
#include <algorithm>
#include <limits>
#include <span>

#include "core/rigid_transform.hpp"

namespace cosmos {

struct BeltContact {
  // The part's convex-hull corners (ModelPart::hull_vertices_mm), in the part's frame; empty:
  // the pose is free of the belt.
  std::span<const Eigen::Vector3d> hull_vertices_part_mm;
  // The frame the registration's model is in (a view's: ModelBaseView::T_scanner_part; the
  // part's own: the identity).
  RigidTransform T_model_part = RigidTransform::identity();
  // The rows together weigh this many times the scene's points together.
  double weight = 0.0;

  bool holds() const { return !hull_vertices_part_mm.empty() && weight > 0; }
};

// One row: the belt's point under a corner (model frame), the plane's normal as the model's
// (-n) and the corner's height h above the belt (the row's signed distance).
struct BeltRow {
  Eigen::Vector3d point_mm;
  Eigen::Vector3d normal;
  double height_mm;
};

// Calls row(BeltRow, share) for the lowest corner under T_model_scene and every corner below
// the belt, share = 1 / their number (the fraction of the rows' weight each carries).
template <class RowFunction>
void for_each_belt_row(const BeltContact& belt, const RigidTransform& T_model_scene,
                       RowFunction&& row) {
  const Eigen::Vector3d normal = T_model_scene.rotation.col(2);
  const Eigen::Vector3d& origin_mm = T_model_scene.translation_mm;
  const auto height_mm = [&](const Eigen::Vector3d& corner_part_mm, Eigen::Vector3d& corner_mm) {
    corner_mm = belt.T_model_part.apply(corner_part_mm);
    return normal.dot(corner_mm - origin_mm);
  };
  double lowest_mm = std::numeric_limits<double>::infinity();
  int below = 0;
  Eigen::Vector3d corner_mm;
  for (const Eigen::Vector3d& corner_part_mm : belt.hull_vertices_part_mm) {
    const double h = height_mm(corner_part_mm, corner_mm);
    lowest_mm = std::min(lowest_mm, h);
    below += h < 0 ? 1 : 0;
  }
  const int rows = lowest_mm < 0 ? below : 1;
  const double share = 1.0 / rows;
  int emitted = 0;
  for (const Eigen::Vector3d& corner_part_mm : belt.hull_vertices_part_mm) {
    const double h = height_mm(corner_part_mm, corner_mm);
    if (!(h < 0 || h == lowest_mm)) continue;
    row(BeltRow{corner_mm - h * normal, -normal, h}, share);
    if (++emitted == rows) break;
  }
}

}  // namespace cosmos
