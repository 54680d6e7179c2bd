#pragma once
// Which parts the search over every part fits first: those whose views' metric signatures
// (core/modelbase/view_signature.hpp) lie closest to the scan's. That search ranks the parts the
// size gate admits by a quick field fit of each (part_pose_search.hpp); in a catalog of hundreds
// of parts that is most of a recognition, and it grows with the catalog. The spectra rank
// parts too poorly to stand in for it: they are scale-free (§4.2), and a catalog's size
// families and look-alike brackets differ by size and proportion. A signature holds both,
// and nearly always puts the scan's own part among the first few, close to the best.
//
// So the quick fits run first on the parts whose closest view is within ratio times the
// closest part's distance (at least min_parts of them). When none of those fits the scan as
// closely as a scan fits its own part (fit_mm2), the scan's own part may be among the others,
// and they are fitted too, tier_parts at a time in signature order, for as long as each tier
// holds a part that fits better than every part fitted before it: a scan none of whose first
// parts fits closely is most often a poor scan (shadowed, seen on a rim) that no part fits
// closely, and the parts ever farther by signature fit it no better. A part left out this way
// can cost a poorer ranking, never a guess among the wrong parts alone.
//
// A scan's heights are taken above the belt, a view's above its part's lowest point: the
// signatures compare only scans of one part lying on the belt.
#include <span>
#include <vector>

#include "core/modelbase/model_base.hpp"
#include "core/parameter_visitor.hpp"
#include "core/recognition/part_pose_search.hpp"

namespace cosmos {

struct SignatureRankParameters {
  bool enabled = true;
  double ratio = 2.5;
  int min_parts = 8;
  double fit_mm2 = 0.3;
  int tier_parts = 8;

  template <class Visitor>
  void visit(Visitor& v) {
    v("enabled", enabled,
      "quick-fit first the parts whose views' metric signatures are closest to the scene's");
    v("ratio", ratio,
      "those whose closest view is within this factor of the closest part's signature distance",
      Range{1, 1e6});
    v("min_parts", min_parts, "and at least this many of them", Range{1, 100000});
    v("fit_mm2", fit_mm2,
      "when none of them fits this closely, the other parts are quick-fitted too, mm^2",
      Range{0, 1e6});
    v("tier_parts", tier_parts,
      "those this many at a time, while each tier holds a part fitting better than all before",
      Range{1, 100000});
  }
};

struct PartSignatureDistance {
  int part = 0;
  double distance_mm = 0;  // to the part's closest view; infinite when it has none
};

// Each of `parts` with the signature distance of its closest view (among models[part].views),
// closest first (ties: in the order given).
std::vector<PartSignatureDistance> rank_by_signature(const ViewSignature& scene,
                                                     std::span<const int> parts,
                                                     const ModelBase& base,
                                                     std::span<const PartSearchModel> models);

// How many of the ranked parts are fitted first: those within ratio of the first's distance,
// at least min_parts (all when fewer).
std::size_t parts_fitted_first(std::span<const PartSignatureDistance> ranked,
                               const SignatureRankParameters& parameters);

}  // namespace cosmos
