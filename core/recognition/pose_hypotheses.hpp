#pragma once
// Initial-pose hypotheses for registering a scene view onto a model view (ch. 6 needs a
// start within its basin of convergence): the pose implied by the COSMOS correspondence
// (§5.3.5), the principal-axes estimate (§6.7.2: all four sign choices), and turns about the
// viewing axis (+z) that align the two views' centroids — both views are seen from the
// scanner, so what is unknown is mostly that turn plus a small tilt. The recognizer ranks and
// aligns them against the part's distance field (part_pose_search.hpp), so registration
// refines only the few most promising.
#include <vector>

#include "core/matching/pose_from_patches.hpp"
#include "core/parameter_visitor.hpp"
#include "core/registration/registration_points.hpp"
#include "core/rigid_transform.hpp"

namespace cosmos {

struct PoseHypothesisParameters {
  int in_plane_turns = 12;  // evenly spaced turns about +z, 0 = none

  template <class Visitor>
  void visit(Visitor& v) {
    v("in_plane_turns", in_plane_turns, "evenly spaced turns about +z; 0: none", Range{0, 360});
  }
};

// Turn k of `turns` evenly spaced ones about the viewing axis (+z), taking the scene's
// centroid onto the model's: T_model_scene.
RigidTransform in_plane_turn(int k, int turns, const Eigen::Vector3d& scene_centre_mm,
                             const Eigen::Vector3d& model_centre_mm);

// The hypotheses' T_model_scene in generation order (patch groups, principal axes, turns by
// angle), unscored. `from_patches` is used when its status is ok.
std::vector<RigidTransform> generate_pose_hypotheses(const RegistrationPoints& scene,
                                                     const RegistrationPoints& model,
                                                     const PoseFromPatches& from_patches,
                                                     const PoseHypothesisParameters& parameters);

}  // namespace cosmos
