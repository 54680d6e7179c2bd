#pragma once
// Pose search over all views of one part: the fallback when the views that spectral selection
// proposed (§5.2) do not register. Shape-spectrum moments are invariant to the view's
// orientation but not very selective among the views of one part: views with similar spectra
// lie all over the view sphere, so the few selected views may all be 40 degrees or more from
// the scene's true viewing direction, beyond what registration (ch. 6) converges from. Here
// every view of the part proposes initial poses (principal axes, §6.7.2, and turns about the
// viewing axis, pose_hypotheses.hpp), settled by a registration iteration and scored by one
// correspondence pass on a small, evenly spread subset of the scene's control points. That
// ranks a start 15 degrees off the truth little better than a wrong view's: the best
// `refined_hypotheses` therefore take a few
// registration iterations on the subset first and are ranked again, and only the best few of
// those are returned for full registration. Budgets of scored hypotheses (views x turns) and
// of subset iterations bound the work.
#include <vector>

#include "core/model_base.hpp"
#include "core/registration_points.hpp"
#include "core/rigid_transform.hpp"
#include "core/view_registration.hpp"

namespace cosmos {

struct PartPoseSearchParameters {
  // Scene control points used to score a hypothesis: 100 rank as well as 200 (measured on
  // the 20-part catalog), at half the cost.
  int scoring_points = 100;
  int in_plane_turns = 12;
  // Registration iterations each start takes before it is scored, with correspondences up to
  // the coarse distance: a centroid-aligned turn is often 10 mm off in translation, which one
  // correspondence pass at the fine 5 mm scores as badly as a wrong view. One iteration fixed
  // 6 of the 27 failures of the 1,000-scan acceptance run (2 and 3 fixed no more).
  int coarse_iterations = 1;
  double coarse_correspondence_distance_mm = 10.0;
  int refined_hypotheses = 32;  // registered on the subset before the final ranking
  int refinement_iterations = 8;
  int best_hypotheses = 4;  // returned, best first
};

struct ViewPoseHypothesis {
  int view = -1;  // index into ModelBase::views
  RigidTransform T_model_scene;
  double truncated_mean_square_mm2 = 0;
};

std::vector<ViewPoseHypothesis> search_part_pose(const RegistrationPoints& scene,
                                                 const ModelBase& base, int part,
                                                 const RegistrationParameters& registration,
                                                 const PartPoseSearchParameters& parameters);

}  // namespace cosmos
