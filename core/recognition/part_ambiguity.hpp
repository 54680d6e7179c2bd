#pragma once
// Whether the recognizer's best candidate is decided against the best candidate of another
// part, or the scene is ambiguous between the two. The thesis trusts verification's best
// match because "the matching score for the correct hypothesis is significantly higher than
// the matching scores for the incorrect hypotheses" (§5.3.6, Table 5.1), and its system has
// no reject option (§5.4); a work cell needs one for exactly the case where that margin is
// missing: a wrong part on the wire makes the robot pick the wrong thing, a rejection only
// sends the part to the manual bin.
//
// Two parts that explain a scene almost equally (support and residual after registration,
// ch. 6) are told apart only where the two placed parts differ, both ways. One way, the scene
// points that one of them explains (within support.inlier_distance_mm of its surface,
// part_support.hpp) and the other does not; the points both explain say nothing about which
// part it is, so they are left out. The other way, each part's own placed surface that the
// scene contradicts (surface_seen.hpp: where the scanner saw belt or a lower surface): a plate
// explains every point of a bracket's face, but puts surface where the bracket has none. Each
// part's evidence is the share of the scene only it explains plus the share of the other's
// surface the scene contradicts beyond contradiction_floor: the winner stands when it has at least
// min_discriminating_share of the evidence and the evidence is at least
// min_discriminating_fraction; else the scene is rejected as ambiguous between the two parts
// rather than guessed.
//
// Symmetry: candidates of one part are never rivals, whatever their poses. A part declared
// symmetric fits its scene equally in every pose its symmetry maps onto itself (the matching
// of §5.3 does not model symmetry, §5.3.6 Fig. 5.5), and which of them is found does not
// change what is picked. The rival is always another part, and the comparison is between the
// two parts' surfaces placed in their own registered poses, so a symmetric winner's or
// rival's pose ambiguity does not count against the decision.
#include <span>
#include <vector>

#include "core/modelbase/model_base.hpp"
#include "core/modelbase/model_surface.hpp"
#include "core/parameter_visitor.hpp"
#include "core/recognition/part_support.hpp"
#include "core/registration/registration_points.hpp"
#include "core/registration/view_registration.hpp"
#include "core/rigid_transform.hpp"

namespace cosmos {

struct PartAmbiguityParameters {
  // A rival whose score is within this of the winner's is examined on the surfaces where the
  // two differ; one further behind has lost already.
  double examined_score_margin = 0.1;
  double min_discriminating_share = 0.6;
  double min_discriminating_fraction = 0.03;
  // A part's placed view is contradicted this much even in its true pose (its silhouette a
  // pixel off, the degrees between the matched view and the scene's viewing direction, a
  // registration a little off): only what is contradicted beyond it is evidence.
  double contradiction_floor = 0.15;
  // Of the candidates within examined_score_margin of the best score, one whose two-way fit
  // (the share of the scene it explains times the share of its view seen) is better by this
  // wins instead: a smaller difference is registration noise between near-identical parts.
  double two_way_fit_margin = 0.1;
  // A winner must also fit the scene best both ways among the parts of other shapes: a
  // candidate of one fitting better by more than two_way_fit_noise, whatever its score, makes
  // the scene ambiguous, as does one scoring higher that the winner does not outfit by
  // two_way_fit_margin. The score (support, residual and COSMOS match) and the fit both ways
  // then name different parts; where a bracket's view is a channel's or a plate's, each
  // measure is fooled by one of them, and which it is cannot be told from the scene. Fits
  // closer than two_way_fit_noise differ by registration noise and name no part: the score
  // decides between shapes, and sizes of one shape, which the fit alone tells apart
  // (size_variants.hpp), are then ambiguous.
  double two_way_fit_noise = 0.01;
  // Verification stops at the first view that explains sufficient_support of the scene; then
  // up to this many further selected views, each of a part not verified yet, are verified so
  // that the winner has a rival to be compared with.
  int rival_verifications = 1;
  // The rival part, when only verification proposed it, is searched over all its views
  // (part_pose_search.hpp) before the comparison, unless the search over every part found its
  // quick fit hopeless (RecognitionResult::rival_left_unsearched).
  bool search_rival_part = true;
  // A scene that more than max_uncompared_close_parts parts fit about as closely as a scene
  // fits its own part (their quick field fits within close_fit_mm2, part_pose_search.hpp),
  // none of them registered, is rejected as ambiguous: the winner was compared with none of
  // them. In a catalog of hundreds, a few flat faces of a prismatic part fit dozens of larger
  // parts, the search registers the first few, and the scene's own part was often not among
  // them; a correct winner rarely has more than one such part beside it.
  double close_fit_mm2 = 0.05;
  int max_uncompared_close_parts = 2;

  template <class Visitor>
  void visit(Visitor& v) {
    v("examined_score_margin", examined_score_margin,
      "a rival part scoring within this of the winner is examined (§5.3.6)", Range{0, 1});
    v("min_discriminating_share", min_discriminating_share,
      "of the evidence telling the two apart, the winner's share at least", Range{0, 1});
    v("min_discriminating_fraction", min_discriminating_fraction,
      "the evidence (scene share one explains, view share contradicted) at least", Range{0, 1});
    v("contradiction_floor", contradiction_floor,
      "a placed view's contradicted share below this is no evidence", Range{0, 1});
    v("two_way_fit_margin", two_way_fit_margin,
      "a close candidate fitting this much better both ways wins instead", Range{0, 1});
    v("two_way_fit_noise", two_way_fit_noise, "two-way fits closer than this tell no parts apart",
      Range{0, 1});
    v("rival_verifications", rival_verifications,
      "views of other parts verified after a sufficient one", Range{0, 1000});
    v("search_rival_part", search_rival_part, "the rival part's views searched before comparing");
    v("close_fit_mm2", close_fit_mm2, "a part whose quick field fit is this close fits alike, mm^2",
      Range{0, 1e6});
    v("max_uncompared_close_parts", max_uncompared_close_parts,
      "more such parts never registered: rejected as ambiguous", Range{0, 100000});
  }
};

// One placed part: its candidate's view (ModelBase::views), T_model_scene onto it, and the
// fraction of that view the scene shows there (SurfaceSeen::seen_fraction).
struct PlacedCandidate {
  int view = -1;
  RigidTransform T_model_scene;
  double seen_fraction = 1;
  std::span<const int> part_views;  // the views of its part (part_support.hpp)
};

struct PartAmbiguity {
  bool ambiguous = false;
  int winner_only_points = 0;  // scene points the winner explains and the rival does not
  int rival_only_points = 0;   // and the other way round
  // The winner's evidence over both parts' (winner_only / scene points + the rival's
  // contradicted fraction, and the other way round), and their sum.
  double discriminating_share = 1;
  double discriminating_fraction = 0;
};

// The comparison above, on `scene` (the recognizer's control points). Only called for a
// rival within examined_score_margin: the caller compares the scores.
PartAmbiguity judge_part_ambiguity(const RegistrationPoints& scene, const ModelBase& base,
                                   const PlacedCandidate& winner, const PlacedCandidate& rival,
                                   const RegistrationParameters& registration,
                                   const PartSupportParameters& support,
                                   const PartAmbiguityParameters& parameters,
                                   ModelSurfaces& surfaces);

}  // namespace cosmos
