#pragma once
// The goodness measure of a correspondence (§5.3.3, the `quality` and `goodness` functions).
//
// The goodness of one MappedPair is the product of four similarities in [0, 1]:
//   area       1 - |a1 - a2| / (a1 + a2) on percentage areas, exactly as §5.3.3 defines it;
//   shape index  closeness of the groups' mean S_I. §5.3.3 gives no formula; we use
//              max(0, 1 - |dS_I| / shape_index_scale) over the curved patches (planar S_I is
//              symbolic, so it cannot enter a mean), times 1 - |p1 - p2| on the planar area
//              shares p, so a planar group never resembles a curved one;
//   curvedness the area form applied to mean curvedness, 1 - |R1 - R2| / (R1 + R2 + floor):
//              the floor keeps near-planar groups (R ~ 0, noisy ratio) from scoring 0;
//   neighbour  the shape-index similarity above applied to the patches adjacent to each
//              group (§5.3.3: "how close is the mean shape index of the neighbours"), times
//              the area form on the numbers of adjacent patches, so a group with more or
//              fewer neighbours than its partner scores lower.
// The quality of a correspondence is the area-weighted mean of the pairs' goodness, the
// weight of a pair being the mean of its two percentage areas (so the weights of a complete
// correspondence add up to 1, and the quality lies in [0, 1]).
//
// §5.3.3's "factor to reflect the overall coarseness" is given no formula either; we
// multiply each pair's goodness by its fineness: the geometric mean over its two sides of
// the area share of the side's largest patch, raised to coarseness_exponent. A pair of
// single patches has fineness 1; the trivial correspondence of two three-patch views about
// 0.5; a patch grouped with a sliver barely loses anything, so merging away spurious small
// patches (the point of patch groups, §5.3.1) stays cheap, while lumping equal patches
// together costs the most.
#include <span>

#include "core/matching/patch_group.hpp"
#include "core/parameter_visitor.hpp"

namespace cosmos {

struct GoodnessParameters {
  // |dS_I| at which the S_I similarity reaches 0: two of the 1/8-wide shape categories of
  // §3.2.1, so a cap (S_I 1) and a ridge (0.75) are already fully dissimilar.
  double shape_index_scale = 0.25;
  // About the curvedness of a sphere of radius 100 mm: below it, curvedness differences are
  // noise for the 5x5 fits of §3.5.1.
  double curvedness_floor_per_mm = 0.01;
  double coarseness_exponent = 1.0;

  template <class Visitor>
  void visit(Visitor& v) {
    v("shape_index_scale", shape_index_scale, "|dS_I| at which S_I similarity reaches 0",
      Range::above(0, 1));
    v("curvedness_floor_per_mm", curvedness_floor_per_mm,
      "curvedness differences below this are noise, 1/mm", Range{0, 10});
    v("coarseness_exponent", coarseness_exponent, "weight of a match's coarseness", Range{0, 10});
  }
};

// One side of a MappedPair as §5.3.3 sees it: the group and the patches adjacent to it.
struct GroupDescriptor {
  GroupSummary group;
  GroupSummary neighbors;
  int neighbor_patches = 0;
};
GroupDescriptor describe_group(const PatchGraph& graph, PatchSet group);

struct PairGoodness {
  double area = 1;
  double shape_index = 1;
  double curvedness = 1;
  double neighbor = 1;
  double goodness = 1;  // area * shape_index * curvedness * neighbor
  double fineness = 1;  // sqrt(largest share scene * largest share model)
  double weight = 0;    // mean percentage area of the two groups
  double score = 0;     // goodness * fineness^coarseness_exponent
};
PairGoodness evaluate_pair(const GroupDescriptor& scene, const GroupDescriptor& model,
                           const GoodnessParameters& parameters);

// fineness^coarseness_exponent of a pair of groups: the factor evaluate_pair applies.
double coarseness_factor(const GroupSummary& scene, const GroupSummary& model,
                         const GoodnessParameters& parameters);

// Planar patches match only planar ones: a group made only of planar patches cannot pair
// with a group holding none.
bool planar_compatible(const GroupSummary& scene, const GroupSummary& model);

struct GroupPair {
  PatchSet scene = 0;
  PatchSet model = 0;
};

// §5.3.3 quality with the coarseness factor: sum over pairs of weight * score.
double correspondence_quality(const PatchGraph& scene, const PatchGraph& model,
                              std::span<const GroupPair> pairs,
                              const GoodnessParameters& parameters);

}  // namespace cosmos
