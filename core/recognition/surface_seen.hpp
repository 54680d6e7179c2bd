#pragma once
// Whether a placed part's surface is where the scene shows surface: the other half of the
// support (part_support.hpp), which only asks whether the scene's points lie on the part. A
// wrong part can explain most of a scene's points and still put surface where the scanner saw
// the belt or a lower surface: a larger mechanical part over a smaller one, a tooth ring where
// the scene has a flange. Its matched view's control points (the part's surface as the
// scanner sees it from that side, ch. 6) are brought into the scene's image under the
// registered pose (T_scene_model = T_model_scene^-1) and looked up at their pixels: a point
// within depth_tolerance_mm of the scene's height there is seen; one the scene shows surface
// above (nearer the scanner) is hidden, which says nothing; one where the scene shows the belt
// or only lower surface is contradicted, since the scanner would have seen it. Where the
// scene has no data and the scanner did not measure the belt either (RangeImage::belt_seen),
// the point lay in a camera or laser shadow, which a laser-triangulation scanner casts into
// every hollow: it counts as hidden. Without the belt mask no data counts against. A pixel's 3 x 3
// neighbourhood is asked, so silhouettes a pixel off and the few degrees between the matched
// view and the scene's viewing direction do not count against the part. A point whose surface
// faces away from the scanner's camera or laser (core/scanner_sight.hpp) is hidden whatever the
// scene shows there: the matched view, taken from another side, holds surface no scan from this
// side measures, such as the steep downstream slope of a tall part, where the scene's image
// (cropped to what was measured) may not even reach.
#include <optional>

#include "core/parameter_visitor.hpp"
#include "core/range_image.hpp"
#include "core/registration/registration_points.hpp"
#include "core/rigid_transform.hpp"
#include "core/scanner_sight.hpp"

namespace cosmos {

struct SurfaceSeenParameters {
  double depth_tolerance_mm = 1.0;
  // Where the scene's scanner measures from: set by whoever makes the recognizer, from its
  // scanner's keys (scanner_sight(), scanner/scanner_model.hpp), so not a key itself. Unset, no
  // point is taken for one facing away.
  std::optional<ScannerSight> sight;

  template <class Visitor>
  void visit(Visitor& v) {
    v("depth_tolerance_mm", depth_tolerance_mm,
      "a placed model point this close to the scene's height is seen, mm", Range::above(0, 100));
  }
};

struct SurfaceSeen {
  int seen = 0;
  int hidden = 0;
  int contradicted = 0;
  // seen / (seen + contradicted); 1 when nothing could be told.
  double seen_fraction() const {
    return seen + contradicted > 0 ? static_cast<double>(seen) / (seen + contradicted) : 1.0;
  }
};

// `model`: the matched view's control points (its frame); T_model_scene registers the scene's
// points onto them.
SurfaceSeen measure_surface_seen(const RangeImage& scene, const RegistrationPoints& model,
                                 const RigidTransform& T_model_scene,
                                 const SurfaceSeenParameters& parameters);

}  // namespace cosmos
