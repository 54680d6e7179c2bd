#pragma once
// The motion a registration leaves free, searched (§6.8). Point-to-plane registration
// (view_registration.hpp) constrains a motion only as far as the surface's normals do: on a
// surface of revolution the turn about its axis moves every point along its own tangent
// plane, and on a cylinder so does the slide along it. A part that is such a surface for the
// most part (a rotor's hub, a knob) with a few features that are not (the rotor's blades)
// registers with the features' points among the rejected outliers whenever its start was
// turned by more than the rejection distance: the step then leaves the turn where the start
// put it, and the pose fits the hub and misses the blades. Here the pose is moved along
// that least constrained motion over its whole range (a full turn, or a slide each way),
// and the position that explains the most scene points on the matched view is kept when it
// explains clearly more than the registered one; the registration is then run again from
// it.
#include <optional>

#include "core/parameter_visitor.hpp"
#include "core/registration/registration_points.hpp"
#include "core/registration/view_registration.hpp"
#include "core/rigid_transform.hpp"
#include "core/task_runner.hpp"

namespace cosmos {

struct FreeMotionSearchParameters {
  bool enabled = true;
  // Searched when the registration's weakest motion is constrained less than this (its
  // eigenvalue over the inliers' total weight; 1e-3 is what registration treats as free).
  double max_constraint = 0.005;
  double turn_step_deg = 1.0;   // a turn: the whole circle in these steps
  double slide_range_mm = 6.0;  // a slide: this far each way
  double slide_step_mm = 0.25;
  // The best position must explain this much more of the scene (of its points, within the
  // support's inlier distance) than the registered pose does.
  double min_gain = 0.01;

  template <class Visitor>
  void visit(Visitor& v) {
    v("enabled", enabled, "search the motion registration leaves free (§6.8)");
    v("max_constraint", max_constraint,
      "searched when registration constrains its weakest motion less than this", Range{0, 1e6});
    v("turn_step_deg", turn_step_deg, "a turn is searched over the circle in these steps, deg",
      Range::above(0, 180));
    v("slide_range_mm", slide_range_mm, "a slide is searched this far each way, mm", Range{0, 1e3});
    v("slide_step_mm", slide_step_mm, "in these steps, mm", Range::above(0, 100));
    v("min_gain", min_gain, "the best position must explain this much more of the scene",
      Range{0, 1});
  }
};

// The position along `registered`'s weakest motion that explains the most of `scene` on
// `model` (points within `inlier_distance_mm`, one correspondence pass each), when it
// explains at least min_gain more than registered.T_model_scene does; else none. The
// positions are scored in shares on `tasks` and compared in their order along the motion.
std::optional<RigidTransform> search_free_motion(const RegistrationPoints& scene,
                                                 const RegistrationPoints& model,
                                                 const RegistrationResult& registered,
                                                 const RegistrationParameters& registration,
                                                 double inlier_distance_mm,
                                                 const FreeMotionSearchParameters& parameters,
                                                 const TaskRunner& tasks = one_after_another());

}  // namespace cosmos
