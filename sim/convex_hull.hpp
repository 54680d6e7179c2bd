#pragma once
// The convex hull of a point set (Qhull, reentrant library): the faces a rigid part can rest
// on. Coplanar triangles are merged into one face (Qhull's default precision merging), so a
// box has six faces, not twelve.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

namespace cosmos {

struct HullFace {
  Eigen::Vector3d normal;                // unit, outward
  double offset = 0.0;                   // normal · p + offset = 0 on the face plane
  std::vector<Eigen::Vector3d> corners;  // counter-clockwise seen from outside
};

struct ConvexHull {
  std::vector<HullFace> faces;
  double volume = 0.0;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();  // of the solid hull
};

// std::invalid_argument when the points span no volume (fewer than 4, or all coplanar):
// such a set has no hull to rest on.
ConvexHull convex_hull(const std::vector<Eigen::Vector3f>& points);

// Is the projection of `point` onto the face's plane inside the face (by at least margin)?
bool projects_inside(const HullFace& face, const Eigen::Vector3d& point, double margin = 0.0);

// Solid angle (steradians) the face subtends at `point` (inside the hull).
double solid_angle(const HullFace& face, const Eigen::Vector3d& point);

}  // namespace cosmos
