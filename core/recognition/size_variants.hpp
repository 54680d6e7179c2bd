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
#include <span>
#include <vector>

#include "core/modelbase/model_base.hpp"
#include "core/parameter_visitor.hpp"
#include "core/rigid_transform.hpp"

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
  // The other sizes are registered from the registered poses of the size that won, scaled
  // (scaled_size_starts), instead of by a search over all their views: the sizes of one shape
  // lie alike, and a pose of one is a pose of another up to where the scale moves the scene.
  bool from_winner_poses = true;

  template <class Visitor>
  void visit(Visitor& v) {
    v("search", search, "register every size of the winner's shape and choose by fit");
    v("corner_tolerance", corner_tolerance,
      "hull corners this close after scaling (of the diameter): one shape", Range{0, 1});
    v("min_diameter_difference_mm", min_diameter_difference_mm,
      "sizes nearer than this: left to the ambiguity test, mm", Range{0, 1e4});
    v("fit_margin", fit_margin, "a two-way fit this much better tells sizes apart", Range{0, 1});
    v("from_winner_poses", from_winner_poses,
      "register the other sizes from the winner's poses, scaled, not by a search over their views");
  }
};

// Whether `b` is `a` at another (or the same) scale about the part origin, by their hulls.
bool same_shape_scaled(const ModelPart& a, const ModelPart& b, double corner_tolerance);

// For each base part, the other parts of its size family whose diameter differs from its own
// by at least min_diameter_difference_mm (ascending indices; empty for most parts).
std::vector<std::vector<int>> find_size_variants(const ModelBase& base,
                                                 const SizeVariantParameters& parameters);

// Poses of the scene in another size's frame (T_part_scene), scale times the size of the part
// posed by `T_part_scene` (scale about the part origin, as the hulls are compared): each pose
// turned alike, once moved so that the scene's centroid lands where the scale carries it, and
// once as it is (a part on the belt keeps its rest, and a scene seen from one side is often
// nearer one end of the part than its centroid says). The field alignment takes them the rest
// of the way.
std::vector<RigidTransform> scaled_size_starts(std::span<const RigidTransform> T_part_scene,
                                               double scale,
                                               const Eigen::Vector3d& scene_centroid_mm);

}  // namespace cosmos
