#pragma once
// What the recognizer (recognizer.hpp) is told: every threshold and budget of selection,
// verification, registration, the searches and the decision, each with its reason, and the
// parameters of the stages it calls. Declared once here; `cosmos config docs` lists them,
// and every recognizer (the cell's, the evaluation's, the benches') uses these defaults.
#include "core/indexing/vote_index_parameters.hpp"
#include "core/matching/patch_group_matching.hpp"
#include "core/matching/pose_from_patches.hpp"
#include "core/matching/spectral_view_selection.hpp"
#include "core/modelbase/model_surface.hpp"
#include "core/parameter_visitor.hpp"
#include "core/recognition/confusable_parts.hpp"
#include "core/recognition/part_ambiguity.hpp"
#include "core/recognition/part_pose_search.hpp"
#include "core/recognition/part_size_gate.hpp"
#include "core/recognition/part_support.hpp"
#include "core/recognition/resting_pose_search.hpp"
#include "core/recognition/signature_rank.hpp"
#include "core/recognition/size_variants.hpp"
#include "core/recognition/surface_seen.hpp"
#include "core/recognition/thin_scene.hpp"
#include "core/registration/free_motion_search.hpp"
#include "core/registration/part_distance_field.hpp"
#include "core/registration/registration_points.hpp"
#include "core/registration/view_registration.hpp"

namespace cosmos {

struct RecognitionParameters {
  SpectralSelectionParameters selection;
  PatchGroupMatchParameters matching;
  PoseFromPatchesParameters pose;
  RegistrationParameters registration;
  // Scene control points every 4th pixel (1.6 mm on the 0.4 mm grid): up to a few thousand
  // points on a catalog part, enough to fix 6 parameters many times over.
  RegistrationPointParameters scene_points{.stride_px = 4};
  int min_dense_scene_points = 600;  // fewer: halve the stride (down to every pixel)
  // More: an even subset of this many. Every registration pass and support measurement costs
  // per point, and a large view (a part seen whole, a group of pieces) fixes its six
  // parameters as well from fewer; with all of its points it would be the slowest to
  // recognize, the cell's latency tail.
  int max_scene_points = 2000;
  int in_plane_hypotheses = 12;  // turns about the viewing axis tried per candidate view
  // Verification's initial poses are ranked and aligned against the part's distance field
  // (part_pose_search.hpp), and at most this many distinct ones registered per selected view
  // (a single one lost hard scans whose best-ranked start was not the true pose, and saved
  // little time).
  FieldAlignedStartParameters field_starts;
  int registered_hypotheses = 2;
  FieldGate registration_gate;  // a start that fails it is not registered
  // Registration converges on this many evenly spread scene control points (and the
  // principal-axes estimate uses them) before at most fine_registration_iterations passes on
  // all the points.
  int coarse_points = 300;
  // The coarse passes stop at convergence or after this many: from the starts the search
  // and the hypotheses give, further passes on the subset changed no decision on the
  // acceptance run's hardest scans, and only cost time.
  int coarse_registration_iterations = 20;
  // ... rejecting no point nearer than this (registration.min_rejection_distance_mm holds for
  // the fine passes). A start a few tenths of a millimetre off on a prismatic part converged
  // onto a pose where one face fits exactly and the others miss by a few tenths: the fine
  // floor rejects those faces' points, the very ones that would pull the pose right, and the
  // part explained half of its own scene.
  double coarse_min_rejection_distance_mm = 0.5;
  int fine_registration_iterations = 10;
  // A start whose coarse pose explains less of the spread subset than this (the view's own
  // support, inlier_distance_mm) skips the fine passes and is judged on the subset: the fine
  // passes of a wrong part or a wrong pose drift for their whole budget over every point and
  // cost the tail most of its time, while a start near the true pose explains far more of
  // the subset already.
  double fine_registration_support = 0.2;
  // Verification stops at the first selected view whose part support reaches this: the
  // others cannot beat it by much, and a wrong part rarely explains 90 % of a scene. Below
  // it the pose search runs too, so a mechanical part whose flat faces another explains at
  // 60-80 % gets the chance to be explained better by its own views.
  double sufficient_support = 0.9;
  // ... and whose matched view the scene shows at least this much of (surface_seen.hpp): a
  // scene that is a subset of a larger part (a bracket's face, which every plate and channel
  // contains) is explained one way by many parts, and ending there left the scene's own part
  // unregistered.
  double sufficient_seen_fraction = 0.75;
  // Verification hands over to the searches below after this many selected views that do
  // not explain the scene, and verifies the others only when no search explains it either:
  // the search over every part, whose quick field fits put the scene's part first in nearly
  // every scan, finds it at less cost than the later views, of which every failing one costs
  // a registration and a part support.
  int views_before_search = 2;
  PartSupportParameters support;  // what counts as explained scene surface
  // When no selected view reaches sufficient_support: the poses the catalog-wide vote index
  // proposes, verified like selected views.
  VoteIndexParameters vote_index;
  // Before them, the parts' resting poses; and whether a part must rest to be recognized.
  RestingSearchParameters resting;
  // When none of them reaches it either: the pose search over every view of up to
  // `searched_parts` parts (the first by SpectralViewSelector::rank_parts), until one reaches
  // it. Every part of any base: a part the spectra rank below the cut was never registered,
  // and its scans went to whichever searched part explained them best (a joint or a pinion
  // taken for an anchor), a wrong part rather than a rejection.
  int searched_parts = 1000;
  // Its order: the parts' quick field fits (part_pose_search.hpp); with it off, the spectral
  // order.
  CatalogRankParameters catalog_rank;
  // Which parts it quick-fits first, and which only when none of those fits closely: in a
  // large catalog a few (signature_rank.hpp).
  SignatureRankParameters signature_rank;
  // The parts the search over every part leaves out: too small or too thick to be the
  // scene's (part_size_gate.hpp).
  PartSizeGateParameters size_gate;
  // The spectral order is a poor guide for the scans that need the search (in the cell, the
  // scene's part often ranks far down), the search's field stages a sharp one: a part whose best
  // field pose fits this well (mean square distance of the scene to the part,
  // part_pose_search.hpp) is registered at once; the others after every part's field stages,
  // best fit first, and not at all when they fit worse than search.kept_score_factor x the
  // best part's + search.kept_score_margin_mm2. Scenes fit their own part at 0.02-0.16 mm^2,
  // other parts at 2 mm^2 and more.
  double convincing_field_fit_mm2 = 0.5;
  // A part whose fit is not convincing has its poses registered best field fit first, and
  // when the first, registered, explains less than this of the scene, the others are not
  // tried: the part rarely explains more in its next poses (its field fit was already poor),
  // and each costs a registration and a part support. A convincing fit keeps all its poses,
  // since a part of near symmetry (a turbine's blades) fits its wrong turns first; so does a
  // part whose first pose did not register, which measured nothing.
  double abandoned_part_support = 0.2;
  // Of the others, at most this many are registered: each costs as much as the field stages
  // of several parts, and a part whose fit ranks below the first few has not explained a
  // scene its better-fitting rivals did not.
  int registered_waiting_parts = 3;
  // In all, convincing or waiting, at most this many parts are registered (besides the rival
  // of a part that explained the scene): a small or partial scene (a feature its shadow cut
  // off a part, a part's piece floating above the belt) fits convincingly in nearly every
  // part's field, and registering each made a scene that no part explains the costliest of
  // all, with the part that does explain it nearly always among the first few in quick order.
  int registered_parts = 6;
  PartPoseSearchParameters search;
  // Decision thresholds (rejection as unknown part).
  double min_inlier_fraction = 0.6;
  // A registered candidate whose support on the coarse points is below this is judged on
  // them alone (it cannot pass min_inlier_fraction on all points).
  double plausible_support = 0.45;
  double max_rms_mm = 0.12;
  // Support and residual each near its limit is no fit: a winner must score (its support,
  // residual and COSMOS match together) about what a candidate at min_inlier_fraction scores
  // with a residual of half max_rms_mm. One near the support limit must fit closely, and a
  // loose fit must explain more of the scene. In a large catalog, a scene whose own part did
  // not register otherwise went to another part that explained most of it loosely.
  double min_score = 0.4;
  int min_scene_points = 30;
  // The winner's placed surface must be where the scene shows surface (surface_seen.hpp): a
  // candidate with less of its matched view seen than this neither wins nor rivals. Wrong
  // parts that explained 75-80 % of a mechanical part's scene showed 10-20 % of their own
  // surface; correct ones nearly always more than half.
  SurfaceSeenParameters surface_seen;
  double min_seen_fraction = 0.4;
  // ... and a winner the search over every part proposed is accepted only with at least this
  // much of it seen. That search registers the first few of many parts (registered_parts): in
  // a large catalog a scene whose own part was not among them (a few flat faces that dozens
  // of parts contain) went to another part that explained its points and showed about half
  // of its view, with no rival left to compare; the scene's own part, found, shows nearly all
  // of it. Selected views and resting poses are not cut short so, and a hollow part lying
  // open side up shows little more than half of its view.
  double min_accepted_seen_fraction = 0.65;
  // The field stages' poses of the search over every part that place more than this
  // fraction of the part over belt the scanner measured are dropped before the parts are
  // ranked or registered (free_space.hpp): the field fit cannot tell a part fitted to a few
  // faces from the scene's own part. 1: none dropped.
  double max_fraction_over_belt = 0.3;
  // Rejection as ambiguous between two parts (§5.3.6, §5.4).
  PartAmbiguityParameters ambiguity;
  // One shape at several sizes (size_variants.hpp).
  SizeVariantParameters size_variants;
  // The parts the base lists as confusable with the winner (confusable_parts.hpp).
  ConfusableSearchParameters confusable;
  // The model surfaces a recognition keeps unpacked at once (model_surface.hpp).
  ModelSurfaceCacheParameters surfaces;
  // The winner's pose along the motion its registration left free (free_motion_search.hpp).
  FreeMotionSearchParameters free_motion;
  // A scene without a fitted surface, recognized from its range points (thin_scene.hpp).
  ThinSceneParameters thin_scene;

  template <class Visitor>
  void visit(Visitor& v) {
    v("selection", selection, "spectral model-view selection (§5.2)");
    v("matching", matching, "patch-group graph matching (§5.3)");
    v("pose", pose, "the pose a patch correspondence implies (§5.3.5)");
    v("registration", registration, "view registration (ch. 6)");
    v("scene_points", scene_points, "the scene's control points (§6.7.1)");
    v("min_dense_scene_points", min_dense_scene_points, "fewer: halve the stride",
      Range{0, 1000000});
    v("max_scene_points", max_scene_points, "more: an even subset of this many",
      Range{1, 100000000});
    v("in_plane_hypotheses", in_plane_hypotheses, "turns about the viewing axis per view",
      Range{0, 360});
    v("field_starts", field_starts, "verification's starts aligned in the part's field");
    v("registered_hypotheses", registered_hypotheses, "starts registered per selected view",
      Range{1, 1000});
    v("registration_gate", registration_gate, "a start that fails it is not registered");
    v("coarse_points", coarse_points, "spread scene points of the coarse passes",
      Range{1, 1000000});
    v("coarse_min_rejection_distance_mm", coarse_min_rejection_distance_mm,
      "the coarse passes reject no nearer point, mm", Range{0, 100});
    v("coarse_registration_iterations", coarse_registration_iterations, "coarse passes, at most",
      Range{0, 1000});
    v("fine_registration_iterations", fine_registration_iterations, "passes on all points, at most",
      Range{0, 1000});
    v("fine_registration_support", fine_registration_support,
      "a start explaining less of the coarse points skips the fine passes", Range{0, 1});
    v("sufficient_support", sufficient_support, "verification stops at this part support",
      Range{0, 1});
    v("sufficient_seen_fraction", sufficient_seen_fraction,
      "... with this much of its matched view seen in the scene", Range{0, 1});
    v("views_before_search", views_before_search,
      "selected views verified before the searches, the others after them", Range{0, 1000});
    v("support", support, "what counts as explained scene surface");
    v("vote_index", vote_index, "votes for (part, pose) over the whole catalog");
    v("resting", resting, "the parts' stable poses on the belt, searched first");
    v("searched_parts", searched_parts, "parts the pose search falls back to", Range{0, 100000});
    v("catalog_rank", catalog_rank, "the order of the search over every part");
    v("signature_rank", signature_rank,
      "the parts that search quick-fits first, by their views' metric signatures");
    v("convincing_field_fit_mm2", convincing_field_fit_mm2,
      "a part whose best field pose fits this well is registered at once, mm^2", Range{0, 1e6});
    v("abandoned_part_support", abandoned_part_support,
      "a part fitting less well whose first registered pose explains less has no more tried",
      Range{0, 1});
    v("registered_waiting_parts", registered_waiting_parts,
      "of the parts that fit less well, at most this many are registered", Range{0, 100000});
    v("registered_parts", registered_parts,
      "parts the search registers in all, at most (besides an explaining part's rival)",
      Range{1, 100000});
    v("search", search, "the pose search over a part's views");
    v("min_inlier_fraction", min_inlier_fraction, "less support: rejected as unknown", Range{0, 1});
    v("plausible_support", plausible_support, "below this on the coarse points: judged on them",
      Range{0, 1});
    v("max_rms_mm", max_rms_mm, "larger RMS residual: rejected, mm", Range::above(0, 100));
    v("min_score", min_score,
      "a lower score (support, residual and COSMOS match together): rejected as unknown",
      Range{0, 1});
    v("min_scene_points", min_scene_points, "fewer scene control points: rejected",
      Range{0, 1000000});
    v("surface_seen", surface_seen, "where the placed winner's surface is looked up");
    v("min_seen_fraction", min_seen_fraction,
      "less of its matched view seen in the scene: a candidate neither wins nor rivals",
      Range{0, 1});
    v("min_accepted_seen_fraction", min_accepted_seen_fraction,
      "a winner the search over every part proposed, with less of its view seen: rejected",
      Range{0, 1});
    v("max_fraction_over_belt", max_fraction_over_belt,
      "a searched pose placing more of its part over measured belt is dropped", Range{0, 1});
    v("size_gate", size_gate, "parts the search over every part leaves out by size");
    v("ambiguity", ambiguity, "rejection as ambiguous between two parts (§5.3.6, §5.4)");
    v("size_variants", size_variants, "one shape at several sizes: told apart by the fit");
    v("confusable", confusable, "the winner's confusable parts, registered before deciding");
    v("surfaces", surfaces, "the model surfaces a recognition keeps unpacked");
    v("free_motion", free_motion, "the winner's pose along the motion registration left free");
    v("thin_scene", thin_scene, "a scene without a fitted surface, from its range points");
  }
};

}  // namespace cosmos
