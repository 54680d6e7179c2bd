#pragma once
// Which parts the scene can be by size alone, before any part is fitted to it. The extent of
// an object belongs to its description beside its shape (§3.1.1: "how big it is"), and a
// recognizer that matches the scene against every model of a large base prunes the models
// that cannot match first (§1.2; the unary constraints of constrained search, §2.1.3). The
// search over every part (part_pose_search.hpp) fits each part's field to the scene; its cost
// grows with the catalog, and in a catalog of hundreds of parts many of them cannot be the
// scene's by two measures that need no fit:
//
//   extent     a scene of one part lies on that part: the part's diameter (its farthest two
//              vertices) is at least the scene's width along any direction;
//   thickness  a part that touches the belt reaches at least its thinnest width above it, and
//              its highest point is seen from above (nothing of the part lies higher to hide
//              it), so a part whose thinnest width exceeds the scene's top is not on the belt.
//
// The same bounds, taken per direction the part may be seen from, leave out the pose search's
// starts from views the scene cannot be seen from (view_extent.hpp): seen from near a view, the
// part stands at most so tall (a scene on the belt is no taller) and spans at most so wide
// across the viewing direction, both ways (the scene's widths across are no greater). Only the
// scene's own part's views near its pose need to pass, and they do; a part none of whose
// views passes is not fitted at all.
//
// Both are bounds, not fits: the scene's width is measured on its control points (on the
// surface, never beyond it), its top on its range pixels (a noisy pixel only raises it), each
// with a tolerance for the scan's noise and sampling, so that the scene's own part always
// passes. A scene that may hold several parts (touching parts in one blob) bounds no part's
// extent; the thickness still holds for each of them.
#include "core/modelbase/model_base.hpp"
#include "core/modelbase/view_extent.hpp"
#include "core/parameter_visitor.hpp"
#include "core/range_image.hpp"
#include "core/registration/registration_points.hpp"

namespace cosmos {

// What the caller knows of the scene: one part (a scan of a single part), or possibly several
// touching (a blob in the cell, which the tracker cannot tell from one part).
enum class SceneParts { kOne, kOneOrMore };

struct PartSizeGateParameters {
  bool enabled = true;
  // The scene's width may exceed a part's diameter by this much (noise, a silhouette's
  // mixed pixels) and the part still be the scene's.
  double extent_tolerance_mm = 3.0;
  // A part's thinnest width may exceed the scene's top by this much (a sharp top between two
  // scan lines, the fitted mesh's facets) and the part still lie on the belt.
  double height_tolerance_mm = 5.0;
  // Leave out the starts from views the scene cannot be seen from.
  bool views = true;
  // The scene's top may exceed the part's height seen from a view by this much (the range
  // pixels' noise) and the view still fit; its widths across use extent_tolerance_mm.
  double view_height_tolerance_mm = 1.5;

  template <class Visitor>
  void visit(Visitor& v) {
    v("enabled", enabled, "leave out of the search parts too small or too thick for the scene");
    v("extent_tolerance_mm", extent_tolerance_mm,
      "a part whose diameter is this much under the scene's width is too small, mm", Range{0, 1e4});
    v("height_tolerance_mm", height_tolerance_mm,
      "a part whose thinnest width is this much over the scene's top is too thick, mm",
      Range{0, 1e4});
    v("views", views,
      "leave out the pose search's starts from views too short or narrow for the scene");
    v("view_height_tolerance_mm", view_height_tolerance_mm,
      "a view whose part stands this much lower than the scene's top still fits, mm",
      Range{0, 1e4});
  }
};

struct PartExtent {
  double diameter_mm = 0;        // its farthest two mesh vertices
  double thinnest_width_mm = 0;  // its hull's width along the direction it is narrowest
};

// From the part's convex hull (ModelPart::hull_vertices_mm) and diameter; a part without a
// hull has thinnest width 0 (no part is too thick then).
PartExtent part_extent(const ModelPart& part);

struct SceneExtent {
  double width_mm =
      0;  // at most the scene's largest width: its control points' along fixed directions
  double top_mm = 0;  // its highest range pixel above the belt
  // Its control points' widest and narrowest widths across the viewing direction (in the
  // belt's plane): at most the part's there.
  double widest_across_mm = 0;
  double narrowest_across_mm = 0;
};

SceneExtent scene_extent(const RegistrationPoints& points, const RangeImage& image);

enum class SizeVerdict { kFits, kSmallerThanScene, kThickerThanScene };

// `parts_touch_belt`: the scene's parts lie on the belt (the thickness bound holds).
SizeVerdict judge_part_size(const PartExtent& part, const SceneExtent& scene, SceneParts parts,
                            bool parts_touch_belt, const PartSizeGateParameters& parameters);

// The views' bound for one scene (view_fits).
struct ViewSizeGate {
  bool enabled = false;  // off: every view fits
  SceneExtent scene;
  bool bounds_height =
      false;  // the scene's part lies on the belt: its top bounds the part's height
  double height_tolerance_mm = 0;
  double width_tolerance_mm = 0;

  bool fits(const ViewExtent& view) const;
};

// Off for a scene that may hold several parts: neither its widths nor its top bound any one
// of them.
ViewSizeGate view_size_gate(const SceneExtent& scene, SceneParts parts, bool parts_touch_belt,
                            const PartSizeGateParameters& parameters);

}  // namespace cosmos
