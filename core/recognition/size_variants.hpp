#pragma once
// A catalog's size families: one shape at several sizes, as parts are often made. The shape
// spectrum is normalized by the visible area (§4.1), and the shape index is independent of
// scale (§3.2), so §5.2's selection proposes a family's sizes alike and cannot tell them
// apart; only the metric fit can (curvedness and extent, §3.2). The recognizer therefore
// registers every size of a winner's family and weighs them by how well each fits both ways:
// the share of the scene the part explains (part_support.hpp: a larger size explains a smaller
// one's scene too) times the share of its placed surface the scene shows (surface_seen.hpp: a
// larger size puts surface where the scanner saw the belt).
//
// Two parts are sizes of one shape when the catalog builds them from one mesh file
// (ModelPart::mesh), or when the corners of their convex hulls (ModelPart::hull_vertices_mm,
// about the part origin) are the same up to one scale factor, so a catalog declares nothing and
// renamed copies of a mesh are found too. (Hulls alone miss some: nearly coplanar corners of a
// gear's teeth are kept at one scale and dropped at another.)
#include <vector>

#include "core/modelbase/model_base.hpp"
#include "core/parameter_visitor.hpp"

namespace cosmos {

struct SizeVariantParameters {
  // Register every size of the winner's family and let the two-way fit choose among them.
  bool search = true;
  // Hull corners this close after scaling (a fraction of the larger part's diameter): the same
  // shape.
  double corner_tolerance = 1e-3;
  // Sizes whose diameters differ by less are not told apart by their fit (a few pixels of
  // extent are within the scan's noise and the views' spacing): the ambiguity test decides,
  // and rejects a near-copy rather than guess.
  double min_diameter_difference_mm = 2.0;
  // A size whose two-way fit is this much better than its rival's is told apart from it
  // without the ambiguity test (part_ambiguity.hpp), which weighs only the scene's points.
  double fit_margin = 0.03;

  template <class Visitor>
  void visit(Visitor& v) {
    v("search", search, "register every size of the winner's shape and choose by fit");
    v("corner_tolerance", corner_tolerance,
      "hull corners this close after scaling (of the diameter): one shape", Range{0, 1});
    v("min_diameter_difference_mm", min_diameter_difference_mm,
      "sizes nearer than this: left to the ambiguity test, mm", Range{0, 1e4});
    v("fit_margin", fit_margin, "a two-way fit this much better tells sizes apart", Range{0, 1});
  }
};

// Whether `b` is `a` at another (or the same) scale about the part origin, by their hulls.
bool same_shape_scaled(const ModelPart& a, const ModelPart& b, double corner_tolerance);

// For each base part, the other parts of its size family whose diameter differs from its own
// by at least min_diameter_difference_mm (ascending indices; empty for most parts).
std::vector<std::vector<int>> find_size_variants(const ModelBase& base,
                                                 const SizeVariantParameters& parameters);

}  // namespace cosmos
