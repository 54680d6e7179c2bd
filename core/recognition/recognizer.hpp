#pragma once
// The recognizer (thesis ch. 5 and 6): from one part's range image to "which model-base part,
// in which pose", or a rejection.
//
//   features      the chapter-3 pipeline (analyze_view) and the scene's registration control
//                 points (§6.7.1);
//   selection     spectral model-view selection (§5.2): K best clusters, m best views;
//   matching      for each selected view, COSMOS verification by patch-group graph matching
//                 (§5.3) and the initial pose it implies (§5.3.5);
//   resting       when no selected view explains the scene: every part's stable resting
//                 poses turned about the belt's normal (resting_pose_search.hpp), searched
//                 in the parts' distance fields;
//   voting        (off by default) when none of that explains the scene: the scene's CSMP
//                 pairs vote for (part, pose) over the whole catalog (core/indexing/); the
//                 strongest poses are verified like selected views;
//   search        when none of that explains the scene: every part the scene's size allows
//                 (part_size_gate.hpp) is ranked by its quick field fit
//                 (part_pose_search.hpp), and the pose search over each
//                 part's views goes down that order until a part explains the scene and the
//                 next one, its rival, has been searched too;
//   registration  initial-pose hypotheses per candidate — the patch-group pose, the principal
//                 axes (§6.7.2) and turns about the viewing axis (scene and model views are
//                 both seen from the scanner, so the unknown is mostly that turn) — scored by
//                 one correspondence pass each; the best are refined by the minimum-variance
//                 estimator (§6.6) or Chen-Medioni;
//   thin scenes   a scene with too little fitted surface to register (a blade seen edge-on)
//                 is searched in the parts' distance fields with its range points, the parts
//                 set down on the belt and held inside its silhouette (thin_scene.hpp);
//   decision      each registered candidate is judged by its support (the fraction of scene
//                 control points within inlier_distance_mm of the model surface), its RMS
//                 residual and its COSMOS goodness; the best wins, and below the thresholds
//                 the part is rejected as unknown rather than forced onto a catalog part.
//                 When another part scores almost as well, the two are compared where their
//                 placed surfaces differ, and a scene they explain alike is rejected as
//                 ambiguous between them rather than guessed (part_ambiguity.hpp).
//
// Everything is counted in operations (views, hypotheses, iterations), so the result depends
// only on the input; only the timings vary between runs.
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "core/cosmos_parameters.hpp"
#include "core/indexing/patch_pair_table.hpp"
#include "core/indexing/vote_index_parameters.hpp"
#include "core/matching/patch_group_matching.hpp"
#include "core/matching/pose_from_patches.hpp"
#include "core/matching/spectral_view_selection.hpp"
#include "core/modelbase/model_base.hpp"
#include "core/modelbase/model_surface.hpp"
#include "core/parameter_visitor.hpp"
#include "core/range_image.hpp"
#include "core/recognition/part_ambiguity.hpp"
#include "core/recognition/part_pose_search.hpp"
#include "core/recognition/part_size_gate.hpp"
#include "core/recognition/part_support.hpp"
#include "core/recognition/resting_pose_search.hpp"
#include "core/recognition/size_variants.hpp"
#include "core/recognition/surface_seen.hpp"
#include "core/recognition/thin_scene.hpp"
#include "core/registration/free_motion_search.hpp"
#include "core/registration/registration_points.hpp"
#include "core/registration/view_registration.hpp"
#include "core/representation/cosmos_pipeline.hpp"
#include "core/rigid_transform.hpp"
#include "core/task_runner.hpp"

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
    v("surfaces", surfaces, "the model surfaces a recognition keeps unpacked");
    v("free_motion", free_motion, "the winner's pose along the motion registration left free");
    v("thin_scene", thin_scene, "a scene without a fitted surface, from its range points");
  }
};

enum class RecognitionStatus { kOk, kRejected };

struct RecognitionCandidate {
  int view = -1;  // index into ModelBase::views
  int part = -1;  // index into ModelBase::parts
  double spectral_distance = 0;
  double goodness = 0;  // COSMOS match score (§5.3.3)
  bool registered = false;
  // Its pose had the fine passes on every control point (fine_registration_support); false:
  // it is the coarse passes' pose.
  bool refined = false;
  RegistrationStatus registration_status = RegistrationStatus::kInvalidInput;
  double rms_mm = 0;
  double inlier_fraction = 0;
  double score = 0;  // the decision's figure of merit, in [0, 1]
  // How much of the matched view, placed, the scene shows (surface_seen.hpp).
  double seen_fraction = 0;
  RigidTransform T_model_scene;
  bool from_pose_search = false;     // proposed by the fallback search, not by §5.2 selection
  bool from_vote_index = false;      // proposed by the vote index (core/indexing/)
  bool from_resting_search = false;  // proposed by the resting-pose search
};

// A part's place in the search over every part (catalog_rank).
struct QuickFieldFit {
  int part = -1;
  // What the part ranks by: its best quick fit at a pose kept on the belt, or when the belt
  // kept none, its best quick fit at any height times catalog_rank.floating_fit_factor.
  double fit_mm2 = 0;
  bool on_belt = true;
};

// The parts that fit the scene at a pose on the belt within close_fit_mm2
// (ambiguity.close_fit_mm2: about as closely as a scene fits its own part), in the order of
// `quick_fits`.
std::vector<int> close_fitting_parts(std::span<const QuickFieldFit> quick_fits,
                                     double close_fit_mm2);

struct RecognitionTimings {
  double features_ms = 0;
  double selection_ms = 0;
  double matching_ms = 0;
  double registration_ms = 0;
  double total_ms = 0;
};

struct RecognitionResult {
  RecognitionStatus status = RecognitionStatus::kRejected;
  std::string reason;  // why rejected; empty when ok
  int part = -1;       // ModelBase::parts index of the winner, -1 when rejected
  int view = -1;       // ModelBase::views index of the winner
  // The part of the best registered candidate, also when it was rejected (-1: none registered).
  int best_candidate_part = -1;
  // The winner's pose was moved along the motion its registration left free
  // (free_motion_search.hpp): it explains more of the scene there.
  bool free_motion_refined = false;
  double score = 0;
  double spectral_distance = 0;
  double registration_rms_mm = 0;
  double inlier_fraction = 0;
  // The best registered candidate of another part than the winner (-1: none), and its score:
  // how near the decision came to naming that part instead.
  int runner_up_part = -1;
  double runner_up_score = 0;
  // When the two are sizes of one shape (size_variants.hpp): their two-way fits, by which
  // they were told apart or not.
  double size_fit = 0, runner_up_size_fit = 0;
  // The two compared where they differ (part_ambiguity.hpp); `examined` false when the
  // runner-up was too far behind (or there was none) to be.
  bool ambiguity_examined = false;
  PartAmbiguity ambiguity;
  // How much of the winner's and the runner-up's matched views the scene shows.
  double seen_fraction = 0;
  double runner_up_seen_fraction = 0;
  // The scene's pose in its own image frame: T_scene_model (registration) composed with the
  // model view's T_scanner_part.
  RigidTransform T_scanner_part;
  MomentVector moments{};
  int scene_patches = 0;
  int scene_points = 0;
  int views_examined = 0;  // model views compared with the scene (selected + searched)
  // The pose search over every part (neither the selected views, the resting poses nor the
  // vote index's poses explained the scene) ran every part's field stages: no part in the
  // order of the quick fits explained the scene before. For parts known to rest it runs only
  // over the parts whose resting poses are poorly known, and this stays false.
  bool catalog_searched = false;
  // The resting poses of every part were searched (the selected views explained nothing).
  bool resting_searched = false;
  // The scene had no fitted surface to register and was searched with its range points
  // (thin_scene.hpp); no candidate is registered then.
  bool thin_scene = false;
  // The order of the search over every part, best first; empty when it did not run in the
  // order of the quick field fits.
  std::vector<QuickFieldFit> quick_fits;
  // The best full field fit that search reached (its parts' field stages; infinity when it did
  // not run in quick order): a part whose quick fit is hopeless beside it is searched no
  // further, there or as a rival (search.kept_score_factor, kept_score_margin_mm2).
  double best_field_fit_mm2 = std::numeric_limits<double>::infinity();
  // The decision's rival was not searched over its part's views, its quick fit being hopeless
  // beside best_field_fit_mm2: it was compared as its selected view registered it.
  bool rival_left_unsearched = false;
  // The parts that search left out, too small or too thick for the scene (part_size_gate.hpp).
  int parts_smaller_than_scene = 0;
  int parts_thicker_than_scene = 0;
  std::vector<RecognitionCandidate> candidates;  // spectral order
  RecognitionTimings timings;
};

class Recognizer {
 public:
  // The base must outlive the recognizer. `cosmos` must be what the base was built with.
  // `tasks` (outliving the recognizer too) runs the independent work of a recognition: the
  // first selected views' verifications, the parts' quick fits, a searched part's field
  // stages and short registrations, the points of each registration pass and support
  // measurement, the free-motion positions; none: one after another. The results are the same
  // with any runner (task_runner.hpp).
  Recognizer(const ModelBase& model_base, const CosmosParameters& cosmos,
             const RecognitionParameters& parameters, const TaskRunner* tasks = nullptr);

  // `parts`: whether the scene holds one part, as a scan of a single part does, or possibly
  // several touching (part_size_gate.hpp: only one part bounds a part's size by the scene's).
  RecognitionResult recognize(const RangeImage& scene, SceneParts parts = SceneParts::kOne) const;
  // For a scene whose chapter-3 analysis already exists (the incremental builder's).
  RecognitionResult recognize_analyzed(const RangeImage& scene, const ViewAnalysis& analysis,
                                       double features_ms = 0,
                                       SceneParts parts = SceneParts::kOne) const;

  const SpectralViewSelector& selector() const { return selector_; }
  // What the pose search needs of each base part (built with the recognizer).
  const PartSearchModel& part_search_model(int part) const {
    return part_search_models_[static_cast<std::size_t>(part)];
  }
  const RecognitionParameters& parameters() const { return parameters_; }
  const PatchPairTable& patch_pair_table() const { return patch_pair_table_; }

 private:
  // The scene's control points, the spread subset of coarse_points taken once, the scene's
  // image, where a placed candidate's surface is looked up (surface_seen.hpp), and whether it
  // holds one part (part_size_gate.hpp).
  struct ScenePoints {
    RegistrationPoints all;
    RegistrationPoints coarse;
    const RangeImage& image;
    SceneParts parts = SceneParts::kOne;
  };
  // The candidate reaches sufficient_support, at rest, with sufficient_seen_fraction of its
  // view seen (min_seen_fraction for a part with other sizes): no other part is likely to
  // explain the scene better, so the search may end.
  bool explains_scene(const RecognitionCandidate& candidate) const;
  // The decision over the registered candidates (recognizer_decision.cpp): sets the result's
  // part, pose and figures, and its status when accepted; returns why the scene is rejected,
  // empty when it is not. May search the rival's part and the winner's other sizes first.
  std::string decide(const ViewAnalysis& analysis, const ScenePoints& points,
                     ModelSurfaces& surfaces, RecognitionResult& result) const;
  // The part's quick field fit (catalog_rank), what the search over every part ranks it by.
  QuickFieldFit quick_fit(int part, const ScenePoints& scene_points) const;

  // A scene without enough fitted surface, from its range points (thin_scene.hpp): sets the
  // result's part, pose and figures when accepted; returns why the scene is rejected, empty
  // when it is not.
  std::string recognize_thin_scene(const RangeImage& scene, RecognitionResult& result) const;
  RecognitionCandidate verify(const ViewAnalysis& scene, const ScenePoints& scene_points,
                              const SpectralCandidate& selected, ModelSurfaces& surfaces,
                              double& matching_ms, double& registration_ms) const;
  // The poses the vote index proposes, one candidate per part, verified in vote order.
  void verify_voted_poses(const ViewAnalysis& scene, const ScenePoints& scene_points,
                          ModelSurfaces& surfaces, RecognitionResult& result) const;
  // The fallback: every view of the candidates' parts (part_pose_search.hpp), or with
  // `resting_poses` only their resting poses (resting_pose_search.hpp). Over every part (no
  // `only_parts`), in the order of their quick field fit (catalog_rank). `only_parts` not
  // empty: those parts alone, in that order. True when every part's field stages ran, false
  // when a part explained the scene before.
  bool search_candidate_parts(const ViewAnalysis& scene, const ScenePoints& scene_points,
                              ModelSurfaces& surfaces, RecognitionResult& result,
                              const std::vector<int>& only_parts = {},
                              bool resting_poses = false) const;
  // Parts known to lie on the belt (resting.parts_touch_belt): a candidate floating above it or
  // sunk into it is not the part lying there; known to rest (resting.parts_rest): nor is one
  // tilted off every resting pose of its part.
  bool at_rest(const RecognitionCandidate& candidate) const;
  // The same for the field stages' poses, before any is registered: those whose lowest point
  // is farther than resting.field_height_error_mm from the belt are dropped.
  void drop_floating_poses(int part, std::vector<FieldHypothesis>& field_poses) const;
  // And those that place more than max_fraction_over_belt of the part over the belt the
  // scene's image measured (free_space.hpp).
  void drop_poses_over_belt(int part, const RangeImage& scene,
                            std::vector<FieldHypothesis>& field_poses) const;
  RestingCheck check_resting(const RecognitionCandidate& candidate) const;
  // `other` is another size of `part`'s shape in the base (size_variants.hpp).
  bool is_size_variant(int part, int other) const;
  // Registers from each start on its view, keeps the pose its view supports best (the
  // candidate's view becomes that one), then judges it against the part's views around it
  // (part_support.hpp).
  void register_candidate(const ScenePoints& scene_points,
                          const std::vector<ViewPoseHypothesis>& starts, ModelSurfaces& surfaces,
                          RecognitionCandidate& candidate) const;
  // The winner moved along the motion its registration left free (free_motion_search.hpp)
  // and registered again; kept (in `candidate`) when its part explains more of the scene.
  // True when it moved.
  bool refine_free_motion(const ScenePoints& scene_points, ModelSurfaces& surfaces,
                          RecognitionCandidate& candidate) const;

  const ModelBase& model_base_;
  const TaskRunner& tasks_;
  CosmosParameters cosmos_;
  RecognitionParameters parameters_;
  SpectralViewSelector selector_;
  std::vector<PartSearchModel> part_search_models_;
  PatchPairTable patch_pair_table_;
  // Parts whose resting poses cover less than resting.min_coverage of the chance.
  std::vector<int> poorly_covered_parts_;
  // Per part, the other sizes of its shape in the base (size_variants.hpp).
  std::vector<std::vector<int>> size_variants_;
  // Per part, its diameter and thinnest width (part_size_gate.hpp).
  std::vector<PartExtent> part_extents_;
};

const char* to_string(RecognitionStatus status);

}  // namespace cosmos
