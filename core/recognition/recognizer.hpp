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
#include <functional>
#include <limits>
#include <optional>
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
#include "core/recognition/recognition_parameters.hpp"
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
  // Registered from the poses of another size of its shape (size_variants.hpp): it stands for
  // its part's pose search, and is trusted no more.
  bool from_scaled_size = false;
  bool searched_over_views() const { return from_pose_search || from_scaled_size; }
  // The decision may name it: it lies at rest on the belt and its surface is seen
  // (min_seen_fraction); set by the decision.
  bool qualified = false;
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
  // Then also the best qualified candidate's part of another shape (-1: none), compared with
  // the winner as the runner-up is.
  int other_shape_part = -1;
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
  // The winner's confusable parts (confusable_parts.hpp) the decision searched over their views,
  // in that order: those its list holds that the scene's size allows and no search had reached.
  std::vector<int> confusable_parts_searched;
  // The parts the search over every part, or the thin scene's, left out, too small or too thick
  // for the scene (part_size_gate.hpp).
  int parts_smaller_than_scene = 0;
  int parts_thicker_than_scene = 0;
  // The parts that search never quick-fitted: their signatures were far from the scene's, and
  // one of those it fitted first fitted closely, or the last tier fitted after them fitted no
  // better than the parts before it (signature_rank.hpp).
  int parts_left_out_by_signature = 0;
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
  // The same, analysing the scene with the caller's workspace (one per thread): a run of scans
  // reuses what the last one's analysis learnt, as the cell's part builders do.
  RecognitionResult recognize(const RangeImage& scene, ViewAnalysisWorkspace& workspace,
                              SceneParts parts = SceneParts::kOne) const;
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
    QuickFitPoints quick;  // what every part's quick fit runs on
    const RangeImage& image;
    SceneParts parts = SceneParts::kOne;
    SceneExtent extent;  // what the size gates compare with the parts' (part_size_gate.hpp)
    ViewSizeGate views;  // the start views the pose searches may start from
    // Its metric signature, heights above the belt (empty when its parts may not lie on the
    // belt alone, or signature_rank is off): what the parts are quick-fitted first by.
    ViewSignature signature;
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
  // Whether the scene's size allows the part (part_size_gate.hpp); a part it does not is
  // counted in the result as too small or too thick.
  bool admitted_by_size(int part, const SceneExtent& extent, SceneParts parts,
                        RecognitionResult& result) const;
  // The part's quick field fit (catalog_rank), what the search over every part ranks it by.
  QuickFieldFit quick_fit(int part, const ScenePoints& scene_points) const;

  // A scene without enough fitted surface, from its range points (thin_scene.hpp): sets the
  // result's part, pose and figures when accepted; returns why the scene is rejected, empty
  // when it is not. `parts` as for recognize: one part bounds the parts' extent.
  std::string recognize_thin_scene(const RangeImage& scene, SceneParts parts,
                                   RecognitionResult& result) const;
  // The size of the best-fitting shape that a ribbon's fits tell apart from its other sizes
  // (into `fits`; nullptr: none): of its sizes that explain the ribbon
  // (thin_scene.min_inlier_fraction of its points), the one standing least over measured
  // belt, when it explains as much of the ribbon as each other such size and each stands over
  // the belt by size_variants.fit_margin more: a larger size fitted to the whole ribbon
  // reaches over the belt beyond its ends. A smaller size's ribbon points left unexplained
  // tell nothing: a failed pose search leaves them too. One whose extra length lies in a
  // shadow fits alike and is not told apart. None is when the best fit by distance does not
  // explain the ribbon.
  const SettledPose* size_told_apart_on_ribbon(const std::vector<SettledPose>& fits) const;
  RecognitionCandidate verify(const ViewAnalysis& scene, const ScenePoints& scene_points,
                              const SpectralCandidate& selected, ModelSurfaces& surfaces,
                              double& matching_ms, double& registration_ms) const;
  // The poses the vote index proposes, one candidate per part, verified in vote order.
  void verify_voted_poses(const ViewAnalysis& scene, const ScenePoints& scene_points,
                          ModelSurfaces& surfaces, RecognitionResult& result) const;
  // The part's poses (T_part_scene) aligned in its field and registered on their nearest views
  // as one candidate (its flags unset); none when the part has no start view or no pose does.
  std::optional<RecognitionCandidate> register_part_poses(
      const ViewAnalysis& scene, const ScenePoints& scene_points, ModelSurfaces& surfaces, int part,
      std::span<const RigidTransform> T_part_scene, RecognitionResult& result) const;
  // Another size of `posed_part`'s shape (size_variants.hpp), registered from the registered
  // poses of `posed_part`, scaled, instead of searched over its views: one candidate.
  void register_scaled_size(const ViewAnalysis& scene, const ScenePoints& scene_points,
                            ModelSurfaces& surfaces, int part, int posed_part,
                            RecognitionResult& result) const;
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
  // The same for the field stages' poses, before any is registered: a pose whose lowest point
  // is farther than resting.field_height_error_mm from the belt floats (or sinks into it).
  bool floats(int part, const FieldHypothesis& hypothesis) const;
  // A pose that places more than max_fraction_over_belt of the part over the belt the scene's
  // image measured (free_space.hpp) stands over it.
  bool stands_over_belt(int part, const RangeImage& scene, const FieldHypothesis& hypothesis) const;
  void drop_floating_poses(int part, std::vector<FieldHypothesis>& field_poses) const;
  void drop_poses_over_belt(int part, const RangeImage& scene,
                            std::vector<FieldHypothesis>& field_poses) const;
  RestingCheck check_resting(const RecognitionCandidate& candidate) const;
  // Parts known to lie on the belt are registered held on it (belt_contact.hpp): a part's, in
  // its own frame and in a view's; free when they are not known to.
  BeltContact belt_contact_in_part_frame(int part) const;
  BeltContact belt_contact(int view) const;
  // `other` is another size of `part`'s shape in the base (size_variants.hpp).
  bool is_size_variant(int part, int other) const;
  // Of the parts the base lists as confusable with `part` (confusable_parts.hpp), those the
  // scene's size allows and `searched` does not hold, best quick fit in `result` first (those
  // without one after them, in list order).
  std::vector<int> confusable_parts_unsearched(int part, const ScenePoints& points,
                                               const RecognitionResult& result,
                                               const std::function<bool(int)>& searched) const;
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
