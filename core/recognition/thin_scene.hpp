#pragma once
// Scenes too thin for a surface: a blade or a plate seen edge-on. Chapter 3's local fits need
// a full window of range data (§3.5.1: 5 x 5 pixels), and so do the control points that
// registration works on (§6.7.1). A part narrower than a window in the image, such as a blade
// under a millimetre thick standing on its edge, leaves a ribbon of range points and no fitted
// surface: nothing for the COSMOS to describe, and the thesis's recognizer, whose views are
// surfaces (§4.5), has nothing to match. The ribbon's points still lie on the part, and the
// part still stands where the scanner measured no belt. So each part's distance field
// (part_distance_field.hpp), which covers every side of it, is searched with the range points
// in place of control points, and the free-space constraint (free_space.hpp) keeps only the
// parts that fit inside the thin silhouette: a wider part fitted to the ribbon reaches over
// the belt on either side of it. Without a belt mask (RangeImage::belt_known) nothing tells
// the parts apart, and the search does not run.
#include <Eigen/Core>
#include <optional>
#include <vector>

#include "core/modelbase/model_base.hpp"
#include "core/parameter_visitor.hpp"
#include "core/range_image.hpp"
#include "core/recognition/part_pose_search.hpp"
#include "core/recognition/resting_pose_search.hpp"
#include "core/registration/registration_points.hpp"
#include "core/rigid_transform.hpp"

namespace cosmos {

struct ThinSceneParameters {
  bool enabled = true;
  int min_points = 20;        // fewer range points: too little to tell the parts apart
  int max_points = 400;       // an even sample of the range points, at most
  int searched_parts = 4;     // in the order of their quick field fit, every pose searched
  int hypotheses = 128;       // field poses of a searched part, set down on the belt and judged
  int settle_rounds = 3;      // each pose aligned in the field and set down again, in turns
  int settle_iterations = 2;  // alignment steps per round
  // The distance field is built from the views' control points, which stop half a fit window
  // short of a rim: a ribbon along the rim lies that far from them.
  double inlier_distance_mm = 1.5;
  double min_inlier_fraction = 0.9;
  // At the final pose, stricter than the search's rough poses (max_fraction_over_belt), but
  // with a wider margin: the ribbon fits the field a millimetre inside the rim, and a blade
  // under a millimetre thick moved so is off its silhouette.
  double max_fraction_over_belt = 0.05;
  int belt_margin_px = 3;
  // A second part whose truncated mean square distance is within this factor of the winner's
  // makes the scene ambiguous.
  double ambiguity_factor = 2.0;

  template <class Visitor>
  void visit(Visitor& v) {
    v("enabled", enabled, "recognize scenes without a fitted surface from their range points");
    v("min_points", min_points, "fewer range points: rejected", Range{1, 1000000});
    v("max_points", max_points, "range points searched, an even sample", Range{1, 1000000});
    v("searched_parts", searched_parts, "parts searched in full, in quick-fit order",
      Range{1, 100000});
    v("hypotheses", hypotheses, "field poses of a searched part judged", Range{1, 100000});
    v("settle_rounds", settle_rounds, "rounds of alignment and setting down on the belt",
      Range{0, 1000});
    v("settle_iterations", settle_iterations, "alignment steps per round", Range{1, 1000});
    v("inlier_distance_mm", inlier_distance_mm, "range points this close to the part are on it, mm",
      Range::above(0, 100));
    v("min_inlier_fraction", min_inlier_fraction, "less of the range points on it: rejected",
      Range{0, 1});
    v("max_fraction_over_belt", max_fraction_over_belt,
      "more of the part placed over measured belt: rejected", Range{0, 1});
    v("belt_margin_px", belt_margin_px,
      "a point lies over the belt when every pixel this near it saw the belt", Range{1, 100});
    v("ambiguity_factor", ambiguity_factor,
      "another part fitting within this factor of the best: ambiguous", Range{1, 1e6});
  }
};

// The scene's range points (every pixel with data, in row-major order, every k-th so that at
// most max_points remain) as registration points: positions, normals towards the sensor (the
// ribbon has none of its own), no local fit. The distance-field stages read positions only.
RegistrationPoints range_points(const RangeImage& scene, int max_points);

// One pose of a part set down on the belt, and how it fits the range points and the scene's
// free space.
struct SettledPose {
  int part = -1;
  RigidTransform T_part_scene;
  double mean_square_mm2 = 0;  // the range points' truncated mean square field distance
  double fraction_over_belt = 0;
  double inlier_fraction = 0;  // of the range points within inlier_distance_mm
};

// A thin scene's range points against the parts' distance fields. The field's zero set lies
// inside a rim (the views' control points stop short of it), so a ribbon along the rim pulls
// a part up off the belt, or slides it onto its face: each pose is aligned in the field and
// set down on the belt in turns, and judged where the part lies. The whole part must stand
// inside the image, whatever lies beyond it counting as belt: in the cell a piece that a
// shadow cut off a part is thin too, and beyond its blob's rows, where the rest of that part
// lies, any part fitted to it would stand unseen.
class ThinSceneFit {
 public:
  // All must outlive the fit.
  ThinSceneFit(const RangeImage& scene, const RegistrationPoints& points,
               const ThinSceneParameters& parameters, const RestingSearchParameters& resting,
               double field_truncation_mm);

  SettledPose settle(int part, const ModelPart& model_part, const PartSearchModel& model,
                     const RigidTransform& T_part_scene) const;
  // The best fit of the poses that, settled, place at most max_fraction_over_belt of the
  // part over the belt, with its inlier fraction; none when none does.
  std::optional<SettledPose> best_settled(int part, const ModelPart& model_part,
                                          const PartSearchModel& model,
                                          const std::vector<FieldHypothesis>& poses,
                                          double max_fraction_over_belt) const;

 private:
  const RangeImage& scene_;
  const RegistrationPoints& points_;
  const ThinSceneParameters& parameters_;
  const RestingSearchParameters& resting_;
  double field_truncation_mm_;
};

}  // namespace cosmos
