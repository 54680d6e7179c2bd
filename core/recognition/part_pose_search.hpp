#pragma once
// Pose search over all views of one part: the fallback when the views that spectral selection
// proposed (§5.2) do not register. Shape-spectrum moments are invariant to the view's
// orientation but not very selective among the views of one part: views with similar spectra
// lie all over the view sphere, so the few selected views may all be 40 degrees or more from
// the scene's true viewing direction, beyond what registration (ch. 6) converges from. Here
// every coarse view of the part proposes starts (turns about the viewing axis, the centroids
// aligned), which are scored and aligned against the part's distance field
// (part_distance_field.hpp) on a small, evenly spread subset of the scene's control points,
// in stages that keep fewer and align more. Against one view a start near the truth scored
// no better than a wrong one (its view, up to 15 degrees away, lacks much of what the scene
// shows; its centroid is 10-40 mm off); against the whole part it does. The best poses then
// move onto the part's view nearest to their viewing direction, take a few registration
// iterations there (ch. 6) and are ranked by that view's fit. Every stage has a fixed budget.
#include <vector>

#include "core/modelbase/model_base.hpp"
#include "core/modelbase/model_surface.hpp"
#include "core/parameter_visitor.hpp"
#include "core/recognition/part_size_gate.hpp"
#include "core/registration/part_distance_field.hpp"
#include "core/registration/registration_points.hpp"
#include "core/registration/view_registration.hpp"
#include "core/rigid_transform.hpp"
#include "core/task_runner.hpp"

namespace cosmos {

struct PartPoseSearchParameters {
  // Scene control points used to score and align a hypothesis: twice as many rank the
  // hypotheses of the 20-part catalog no better, at twice the cost.
  int scoring_points = 100;
  int start_scoring_points = 50;  // the first two stages (the starts, one alignment step)
  int in_plane_turns = 12;
  double field_truncation_mm = 10.0;  // farther points count as this far, and do not align
  int field_candidates = 512;         // kept after scoring the starts as they are
  int field_aligned = 128;            // kept after one alignment step
  int field_iterations = 3;           // alignment steps for those
  int refined_hypotheses = 32;        // registered on their nearest view
  int refinement_iterations = 8;
  FieldGate refinement_gate;  // those that fail it are not registered, nor returned
  int best_hypotheses = 4;    // returned, best first, no two poses of the part within:
  double same_pose_rad = 0.02;
  double same_pose_mm = 0.5;
  // and none whose field score exceeds factor x the best's + margin (a wrong pose scores
  // 10-100 times the true one's 0.05-0.3 mm^2).
  double kept_score_factor = 3.0;
  double kept_score_margin_mm2 = 0.5;
  // The worst field score kept beside a best one of best_mm2 (the rule above; the recognizer
  // applies it to whole parts too).
  double worst_kept_score_mm2(double best_mm2) const {
    return kept_score_factor * best_mm2 + kept_score_margin_mm2;
  }

  template <class Visitor>
  void visit(Visitor& v) {
    v("scoring_points", scoring_points, "scene control points that score a pose", Range{1, 100000});
    v("start_scoring_points", start_scoring_points, "the same for the first two stages",
      Range{1, 100000});
    v("in_plane_turns", in_plane_turns, "turns about the viewing axis per coarse view",
      Range{1, 360});
    v("field_truncation_mm", field_truncation_mm, "farther points count as this far, mm",
      Range::above(0, 1e3));
    v("field_candidates", field_candidates, "kept after scoring the starts", Range{1, 1000000});
    v("field_aligned", field_aligned, "kept after one alignment step", Range{1, 1000000});
    v("field_iterations", field_iterations, "alignment steps for those", Range{0, 1000});
    v("refined_hypotheses", refined_hypotheses, "registered on their nearest view",
      Range{1, 100000});
    v("refinement_iterations", refinement_iterations, "registration iterations there",
      Range{0, 1000});
    v("refinement_gate", refinement_gate, "poses that fail it are not registered");
    v("best_hypotheses", best_hypotheses, "poses returned, best first", Range{1, 1000});
    v("same_pose_rad", same_pose_rad, "closer poses are one, rad", Range{0, 3.15});
    v("same_pose_mm", same_pose_mm, "closer poses are one, mm", Range{0, 1e3});
    v("kept_score_factor", kept_score_factor, "poses scoring worse than factor x best ...",
      Range{1, 1e6});
    v("kept_score_margin_mm2", kept_score_margin_mm2, "... + margin are dropped, mm^2",
      Range{0, 1e6});
  }
};

// What the search needs of one part, gathered from the base: its distance field (the
// distance transform of the part's stored surface voxels, part_surface_summary.hpp) and, per
// view, the centroid of its control points.
struct PartSearchModel {
  PartDistanceField field;
  // Every view of the part that has control points (indices into ModelBase::views, in base
  // order) and their centroid in that view's frame. The searches look a part's views up here,
  // never among the base's: a catalog of hundreds of parts has tens of thousands of views, and
  // going through them all for every pose tried made a recognition's cost grow with the
  // catalog. The pose search puts the scene's centroid on a start view's;
  // the resting search on that of the view nearest the vertical (resting_pose_search.hpp),
  // of every view, since a coarse one can be 20 degrees off.
  std::vector<int> views;
  std::vector<Eigen::Vector3d> view_centroid_mm;
  // The coarse views the pose search starts from (every view when the base has no coarse
  // ones): positions in `views`.
  std::vector<std::size_t> start_views;
  // An even sample of the views' control points in the part's frame (the whole part, every
  // side): what a pose hypothesis must not place over measured belt (free_space.hpp).
  Eigen::Matrix3Xd surface_sample_mm;
  // When the parts lie on the belt, every alignment and registration of the search holds the
  // part on it (belt_contact.hpp): its hull corners, in its own frame. build_part_search_model
  // leaves it free; the recognizer holds it when its parameters say the parts touch the belt.
  BeltContact belt;
};

PartSearchModel build_part_search_model(const ModelBase& base, int part);

struct ViewPoseHypothesis {
  int view = -1;  // index into ModelBase::views
  RigidTransform T_model_scene;
  double truncated_mean_square_mm2 = 0;
};

// A pose of the scene in the part's frame and its fit to the part's distance field.
struct FieldHypothesis {
  RigidTransform T_part_scene;
  double truncated_mean_square_mm2 = 0;
};

// The part's view nearest to the direction the scanner looks from under T_part_scene, of
// those with control points (`model`: the part's); -1 when it has none.
int nearest_view(const ModelBase& base, const PartSearchModel& model,
                 const RigidTransform& T_part_scene);

// The search's field stages from the given starts (T_part_scene): all scored, the best
// field_candidates aligned one step, the best field_aligned of those field_iterations steps;
// at most refined_hypotheses returned, best first.
std::vector<FieldHypothesis> rank_field_starts(const RegistrationPoints& scene,
                                               const PartSearchModel& model,
                                               std::vector<FieldHypothesis> starts,
                                               const PartPoseSearchParameters& parameters,
                                               const TaskRunner& tasks = one_after_another());

// The search's field stages alone, from the turns of every start view `views` fits (all by
// default): at most parameters.refined_hypotheses poses, best first. Their best score already
// tells the scene's part from the others, at half the cost of the whole search. Each stage's
// hypotheses are aligned and scored in shares on `tasks`; the poses are the same for any runner.
std::vector<FieldHypothesis> field_pose_hypotheses(const RegistrationPoints& scene,
                                                   const ModelBase& base,
                                                   const PartSearchModel& model,
                                                   const PartPoseSearchParameters& parameters,
                                                   const TaskRunner& tasks = one_after_another(),
                                                   const ViewSizeGate& views = {});

// How well the part can fit the scene, at a small fraction of the field stages' cost: the turns
// of every start view `views` fits scored on start_points scene points, the best `aligned` of them
// aligned `iterations` steps on about aligned_points evenly spread ones and those, the best score.
// The scoring points are a farthest-point subset (farthest_point_indices): the scene's ends and
// small features decide between the starts, which an even subset of a scene that is mostly
// one flat face cannot; the even ones hold the alignment to the whole surface. It orders the search
// over every part: the scene's own part comes first in nearly every scan, where the spectra put it
// first in a third of them.
struct CatalogRankParameters {
  bool enabled = true;  // false: the search over every part goes in spectral order
  int start_points = 12;
  // Flat-faced parts of one kind (brackets, channels, plates) score many wrong starts as well
  // as their right one on a dozen points: with too few aligned, the scene's own part missed
  // its pose and ranked behind parts it resembles, which then explained the scene unrivalled.
  int aligned = 32;
  int aligned_points = 50;
  int iterations = 2;
  // The quick poses are rough, their heights too: a part whose quick poses all float above
  // the belt or stand over it may still lie on it at a pose the full stages find. It ranks by
  // its best quick fit at any height times this factor (1: as though that pose lay on the
  // belt) instead of not at all.
  double floating_fit_factor = 1.0;

  template <class Visitor>
  void visit(Visitor& v) {
    v("enabled", enabled, "order the search over every part by a quick field fit");
    v("start_points", start_points,
      "scene control points, farthest from each other, that score every start", Range{1, 100000});
    v("aligned", aligned, "the best starts, aligned", Range{1, 100000});
    v("aligned_points", aligned_points,
      "evenly spread scene control points that align them, with the scoring ones",
      Range{1, 100000});
    v("iterations", iterations, "alignment steps for each", Range{0, 1000});
    v("floating_fit_factor", floating_fit_factor,
      "a part whose quick poses all float or stand over the belt ranks by its best quick fit "
      "times this",
      Range{1, 1e6});
  }
};

// The scene points every part's quick fit runs on, chosen once per scene.
struct QuickFitPoints {
  RegistrationPoints aligning;  // an even subset and the scoring points
  RegistrationPoints scoring;   // start_points, farthest from each other
};
QuickFitPoints quick_fit_points(const RegistrationPoints& scene,
                                const CatalogRankParameters& parameters);

// The quick stage's aligned poses, best first (empty when the scene or the field is); the
// first one's truncated mean square distance is the part's quick fit.
std::vector<FieldHypothesis> quick_field_poses(const QuickFitPoints& scene, const ModelBase& base,
                                               const PartSearchModel& model,
                                               const PartPoseSearchParameters& search,
                                               const CatalogRankParameters& parameters,
                                               const ViewSizeGate& views = {});

// The search's second half: those poses moved onto the part's views nearest to them,
// registered there and ranked by that view's fit. The registrations run in shares on `tasks`
// when their views fit in `surfaces` together; the poses are the same for any runner.
std::vector<ViewPoseHypothesis> register_field_hypotheses(
    const RegistrationPoints& scene, const ModelBase& base, const PartSearchModel& model,
    const std::vector<FieldHypothesis>& hypotheses, const RegistrationParameters& registration,
    const PartPoseSearchParameters& parameters, ModelSurfaces& surfaces,
    const TaskRunner& tasks = one_after_another());

// Both halves. `model`: the part's build_part_search_model.
// The views' surfaces come from (and stay in) `surfaces`.
std::vector<ViewPoseHypothesis> search_part_pose(const RegistrationPoints& scene,
                                                 const ModelBase& base,
                                                 const PartSearchModel& model,
                                                 const RegistrationParameters& registration,
                                                 const PartPoseSearchParameters& parameters,
                                                 ModelSurfaces& surfaces);

// The same against the part's field, for the few starts verification has on one selected view
// (§5.3.5 patch groups, §6.7.2 principal axes, turns): a start half a view away from the
// truth fits that view no better than a wrong one, but the whole part clearly better, and
// aligning in the field takes it the rest of the way without correspondences.
struct FieldAlignedStartParameters {
  int scoring_points = 100;
  int aligned_starts = 4;  // the best-scoring starts, aligned
  int field_iterations = 10;
  double field_truncation_mm = 10.0;

  template <class Visitor>
  void visit(Visitor& v) {
    v("scoring_points", scoring_points, "scene control points that score a start",
      Range{1, 100000});
    v("aligned_starts", aligned_starts, "the best-scoring starts, aligned", Range{1, 1000});
    v("field_iterations", field_iterations, "alignment steps for each", Range{0, 1000});
    v("field_truncation_mm", field_truncation_mm, "farther points count as this far, mm",
      Range::above(0, 1e3));
  }
};

// `starts` are T_model_scene on `view` (a view of the part `model` belongs to). Returns at
// most `count` distinct poses, best first, each on the part's view nearest its viewing
// direction, with the distinctness and score cut of `search`.
std::vector<ViewPoseHypothesis> align_view_starts_in_field(
    const RegistrationPoints& scene, const ModelBase& base, int view,
    const std::vector<RigidTransform>& starts, const PartSearchModel& model,
    const FieldAlignedStartParameters& parameters, const PartPoseSearchParameters& search,
    int count);

}  // namespace cosmos
