#pragma once
// Parts on a belt lie in few stable poses (ModelPart::resting_poses, computed from the mesh
// when the base is built): their face down, any turn about the vertical, anywhere on the
// belt. A scene in such a pose is found by trying each resting pose at turns about the belt's
// normal (the scene's z) — a search over one angle per resting pose instead of over every
// view direction (part_pose_search.hpp) — and a candidate whose pose rests on none of them
// cannot be the part lying there. The scene's frame must have z along the belt's normal, as
// the scanner's and the cell's frames do (docs/architecture.md, Frames).
#include <vector>

#include "core/modelbase/model_base.hpp"
#include "core/parameter_visitor.hpp"
#include "core/recognition/part_pose_search.hpp"
#include "core/registration/registration_points.hpp"
#include "core/rigid_transform.hpp"

namespace cosmos {

struct RestingSearchParameters {
  // Search each part's resting poses before the pose search over all its views, when the
  // parts are known to rest (parts_rest below).
  bool search = true;
  // The parts lie on the belt (not propped on each other): a candidate whose lowest point is
  // not on the belt (within max_height_error_mm) neither wins nor rivals.
  bool parts_touch_belt = false;
  // Moreover in their stable poses: nor does one whose vertical is farther than max_tilt_deg
  // from every resting pose's. A part whose kept resting poses cover less than min_coverage
  // of the chance (a roller: its side is many hull faces, each unlikely) is held to its
  // contact with the belt alone.
  bool parts_rest = false;
  double max_height_error_mm = 2.0;
  // With parts_touch_belt, every alignment and registration holds a part on the belt by its
  // lowest hull corners (belt_contact.hpp), their rows weighing this many times the scene's
  // points together; 0 leaves the pose free of the belt, to be checked after.
  double belt_contact_weight = 1.0;
  // The same for the pose search's field poses, before registration moves them the last
  // millimetres (part_pose_search.hpp): a floating field pose is not registered.
  double field_height_error_mm = 6.0;
  double max_tilt_deg = 5.0;
  double min_coverage = 0.98;
  int turns = 36;  // about the vertical, per resting pose
  // The search's field stages (part_pose_search.hpp), narrower than the search over views:
  // the starts are right in tilt and height, and there are a tenth as many.
  int field_aligned = 32;
  int refined_hypotheses = 8;

  template <class Visitor>
  void visit(Visitor& v) {
    v("search", search, "with parts_rest: search the resting poses before all the views");
    v("parts_touch_belt", parts_touch_belt, "parts lie on the belt: floating poses cannot win");
    v("parts_rest", parts_rest, "and in their stable poses: leaning ones cannot win either");
    v("max_height_error_mm", max_height_error_mm,
      "lowest point farther from the belt: not at rest, mm", Range{0, 1e3});
    v("belt_contact_weight", belt_contact_weight,
      "registrations hold the part's lowest corners on the belt with this weight (x the scene's)",
      Range{0, 1e6});
    v("field_height_error_mm", field_height_error_mm,
      "a field pose's lowest point farther from the belt: not registered, mm", Range{0, 1e3});
    v("max_tilt_deg", max_tilt_deg, "farther from every resting pose: not at rest, deg",
      Range{0, 180});
    v("min_coverage", min_coverage, "parts whose poses cover less: held to contact alone",
      Range{0, 1});
    v("turns", turns, "turns about the vertical per resting pose", Range{1, 3600});
    v("field_aligned", field_aligned, "kept after one alignment step", Range{1, 100000});
    v("refined_hypotheses", refined_hypotheses, "returned for registration", Range{1, 100000});
  }
};

// Field hypotheses (T_part_scene, best first) from the part's resting poses turned about the
// scene's vertical, at their height above the belt, the scene's centroid over that of the
// part's surface seen from above.
// Empty when the part has no resting poses.
std::vector<FieldHypothesis> resting_pose_hypotheses(const RegistrationPoints& scene,
                                                     const ModelBase& base, int part,
                                                     const PartSearchModel& model,
                                                     const PartPoseSearchParameters& search,
                                                     const RestingSearchParameters& parameters);

// How a pose T_part_scene of the part lies on the belt (the scene's z = 0).
struct RestingCheck {
  // The height of the part's lowest point (ModelPart::hull_vertices_mm): 0 when it touches the
  // belt.
  double lowest_point_mm = 0;
  double tilt_deg = 180;      // the vertical's angle from the nearest resting pose's
  bool covered = false;       // the part's resting poses cover min_coverage of the chance
  bool touches_belt = false;  // the lowest point within max_height_error_mm of the belt
  bool at_rest = false;       // touches the belt and, when covered, is a resting pose
};

RestingCheck check_resting(const ModelPart& part, const RigidTransform& T_part_scene,
                           const RestingSearchParameters& parameters);

}  // namespace cosmos
