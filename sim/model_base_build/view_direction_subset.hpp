#pragma once
// Which of the 320 view directions (sim/view_sphere.hpp, two subdivisions: §4.5) a model base
// built with fewer views uses. `--views N` takes the first N of a fixed spread order:
//   1. the 20 icosahedron face centres (direction 16 f + 15: the middle child of the middle
//      child of face f is exactly the face centre), so --views 20 is the plain icosahedron;
//   2. the other 60 middles of the once-subdivided faces (16 f + 4 c + 3, c = 0..2, each
//      within 0.04 degrees of a once-subdivided face centre), so --views 80 is one
//      subdivision;
//   3. the remaining 240.
// Inside a tier, each next direction is the one farthest from all taken so far (ties to the
// lower index), so any N in between is spread evenly too. Indices keep meaning directions of
// the full set, so a view of a small base is the same view (and scan noise) as in a full one.
#include <vector>

namespace cosmos {

inline constexpr int kViewSphereSubdivisions = 2;
inline constexpr int kFullViewCount = 320;

// Indices into view_directions(2), ascending; count in [1, 320] (std::invalid_argument
// otherwise).
std::vector<int> spread_view_subset(int count);

}  // namespace cosmos
