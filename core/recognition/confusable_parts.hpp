#pragma once
// Which parts a part may be taken for: those of whose views it fits one as closely as a scan
// fits its own part. Verification trusts the best match because the correct hypothesis scores
// well above the others (§5.3.6, Table 5.1); in a catalog of flat-faced families (brackets,
// channels, plates, sections) that margin is missing for whole ranges of viewing directions.
// A channel seen from where one of its walls hides the others is, to the scanner, a bracket's
// view, and a bracket fits it exactly. The search over every part (recognizer.hpp) ends at the
// first part that explains the scene and its rival; when the scene's own part ranked lower by
// its quick fit, it was never registered and the other part was named, unopposed.
//
// The model base knows those pairs before any scan: each part's views are scenes like any
// scan's (the same scanner, the same control points, §4.5 and §6.7.1), so every other part's
// quick field fit (part_pose_search.hpp) to a few of them, taken at build time, lists the
// pairs of parts one of which explains a view of the other. The recognizer registers that list's
// parts beside a winner that has one, as it registers a winner's other sizes (size_variants.hpp),
// and the decision compares them where they differ (part_ambiguity.hpp): the scene's own part wins,
// or the scene is rejected as ambiguous, instead of guessed.
#include <span>
#include <vector>

#include "core/modelbase/model_base.hpp"
#include "core/parameter_visitor.hpp"
#include "core/recognition/part_pose_search.hpp"
#include "core/recognition/part_size_gate.hpp"
#include "core/task_runner.hpp"

namespace cosmos {

// How the base lists each part's confusable parts (recorded in the base's parameters).
struct ConfusablePartParameters {
  bool enabled = true;
  // The views of each part that every other part is fitted to, spread over its view sphere.
  int views_per_part = 24;
  // A part whose quick fit of a view is this close explains it: about as closely as a scan
  // fits its own part (ambiguity.close_fit_mm2).
  double close_fit_mm2 = 0.05;
  // The fits themselves, as the recognizer's search over every part runs them: the extent
  // bound first (a part narrower than the view cannot explain it), then the quick field fit.
  PartSizeGateParameters size_gate;
  PartPoseSearchParameters search;
  CatalogRankParameters quick_fit;

  template <class Visitor>
  void visit(Visitor& v) {
    v("enabled", enabled, "list the pairs of parts one of which fits a view of the other closely");
    v("views_per_part", views_per_part, "views of each part fitted by every other part",
      Range{1, 100000});
    v("close_fit_mm2", close_fit_mm2, "a quick fit this close explains the view, mm^2",
      Range{0, 1e6});
    v("size_gate", size_gate, "the extent bound of the fits (as the recognizer's)");
    v("search", search, "the field search the quick fits run in (as the recognizer's)");
    v("quick_fit", quick_fit, "the quick field fits (as the recognizer's catalog_rank)");
  }
};

// What the recognizer does with a winner's list.
struct ConfusableSearchParameters {
  // Register the winner's confusable parts that the scene's size allows before deciding.
  bool search = true;
  // At most this many, those fitting the scene best by their quick fit first: a flat part's
  // list can be long, and each costs a pose search over the part's views.
  int searched_parts = 3;
  // A winner with listed parts the scene's size allows left unsearched is named only when this
  // much of its matched view is where the scene is (surface_seen.hpp); less, and the scene is
  // rejected as ambiguous. The scene's own part shows its view whole; a part taken for it
  // explains the scene's points but puts surface where the scanner saw none, and which of the
  // parts left unsearched would have done better is not known.
  double min_seen_fraction = 0.85;

  template <class Visitor>
  void visit(Visitor& v) {
    v("search", search, "register the winner's confusable parts before deciding");
    v("searched_parts", searched_parts, "at most this many, best quick fit first",
      Range{0, 100000});
    v("min_seen_fraction", min_seen_fraction,
      "with some left unsearched, less of the winner's view seen: rejected as ambiguous",
      Range{0, 1});
  }
};

// The views of `part` the listing fits, at most views_per_part of those with control points,
// spread evenly through the part's views in base order (the view sphere's, face by face).
std::vector<int> confusion_probe_views(const PartSearchModel& part, int views_per_part);

// For each part W of the base, the parts Q (ascending, never W) one of whose probe views W's
// quick field fit (free of the belt: a view is no scan on the belt) explains within
// close_fit_mm2, or whose quick fit explains one of W's; empty lists when not enabled. Both
// ways, because a few probe views find one side of a pair more often than both: the views a
// channel explains of a bracket and those a bracket explains of a channel come from the same
// walls. `models`: every part's build_part_search_model.
// Each probe view's fits are independent: they run in shares on `tasks`, and the lists are
// the same for any runner.
std::vector<std::vector<int>> find_confusable_parts(const ModelBase& base,
                                                    std::span<const PartSearchModel> models,
                                                    const ConfusablePartParameters& parameters,
                                                    const TaskRunner& tasks = one_after_another());

}  // namespace cosmos
