#pragma once
// How much of a scene a registered part explains (the decision of ch. 5-6 recognition): the
// fraction of scene control points lying within inlier_distance_mm of the part's surface, and
// their RMS distance. The part's surface is not one model view but the union of its views
// whose directions lie within neighbour_view_angle_deg of the matched one, each brought into
// the matched view's frame through the part frame (T_v_scene = T_v_part T_part_matched
// T_matched_scene). A single view misses what the scene sees beyond that view's
// self-occlusions; the views around it fill that in, so a correct part is judged on its whole
// visible surface while a wrong one still fits only by chance.
#include <span>
#include <vector>

#include "core/modelbase/model_base.hpp"
#include "core/modelbase/model_surface.hpp"
#include "core/parameter_visitor.hpp"
#include "core/registration/registration_points.hpp"
#include "core/registration/view_registration.hpp"
#include "core/rigid_transform.hpp"
#include "core/task_runner.hpp"

namespace cosmos {

struct PartSupportParameters {
  double inlier_distance_mm = 0.2;
  double neighbour_view_angle_deg = 40.0;
  // At most this many of them, the nearest first: a 320-view base has ~37 within 40 degrees,
  // where 12 (~20 degrees) already cover what one view misses.
  int max_neighbour_views = 20;

  template <class Visitor>
  void visit(Visitor& v) {
    v("inlier_distance_mm", inlier_distance_mm, "scene points this close are explained, mm",
      Range::above(0, 100));
    v("neighbour_view_angle_deg", neighbour_view_angle_deg,
      "the part's views this close to the matched one join its surface, deg", Range{0, 180});
    v("max_neighbour_views", max_neighbour_views, "at most this many of them, nearest first",
      Range{0, 320});
  }
};

struct PartSupport {
  double inlier_fraction = 0;  // of all scene control points
  double rms_mm = 0;           // over the inliers
  int views_used = 0;
};

// Each scene point's distance to the part's surface so placed (the nearest over the views
// that join it; farther than inlier_distance_mm: some value above it, maybe infinity), in
// `distance_mm`; returns the number of views asked. `matched` indexes ModelBase::views;
// T_model_scene registers the scene onto it; `part_views` are the views of its part (indices
// into ModelBase::views, in base order; PartSearchModel::views), the only ones asked. The
// views' surfaces come from (and stay in) `surfaces`, unpacked on the calling thread; each
// view's points are asked in shares on `tasks` (a point's distance depends on it alone).
int part_surface_distances(const RegistrationPoints& scene, const ModelBase& base,
                           std::span<const int> part_views, int matched,
                           const RigidTransform& T_model_scene,
                           const RegistrationParameters& registration,
                           const PartSupportParameters& parameters, ModelSurfaces& surfaces,
                           std::vector<double>& distance_mm,
                           const TaskRunner& tasks = one_after_another());

// The fraction of those within inlier_distance_mm, and their RMS distance.
PartSupport measure_part_support(const RegistrationPoints& scene, const ModelBase& base,
                                 std::span<const int> part_views, int matched,
                                 const RigidTransform& T_model_scene,
                                 const RegistrationParameters& registration,
                                 const PartSupportParameters& parameters, ModelSurfaces& surfaces,
                                 const TaskRunner& tasks = one_after_another());

}  // namespace cosmos
