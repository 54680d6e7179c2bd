#pragma once
// How tall a part stands on the belt and how wide it spans across it when the scanner sees it
// from near one of its views' directions. The extent of an object belongs to its description
// beside its shape (§3.1.1: "how big it is"); the part size gate (part_size_gate.hpp) bounds a
// part's extent whatever its pose, and with these figures the pose search's starts per view: a
// scene 40 mm tall and 90 mm across is not seen from a direction along which its part stands
// 25 mm tall or spans 60 mm at most, and the starts from such views cannot reach its pose.
//
// A start of the pose search is a view's direction; the scene's own may lie anywhere within the
// start views' spacing of it (its cell). So each figure is taken over every direction of the
// cell, from the part's convex hull (its silhouette and its height are its hull's): the height
// above the belt is the hull's width along the direction, the widths across are its widths
// along the directions square to it.
#include <Eigen/Core>
#include <limits>
#include <vector>

namespace cosmos {

struct ModelBase;

struct ViewExtent {
  // The greatest, over the cell, of the part's height along the direction: a scene seen from
  // within the cell is no taller. Infinite: not known (every scene fits).
  double highest_mm = std::numeric_limits<double>::infinity();
  // The greatest, over the cell, of the part's widest width across the direction, and of its
  // narrowest: a scene's own widths across are no greater.
  double widest_mm = std::numeric_limits<double>::infinity();
  double narrowest_mm = std::numeric_limits<double>::infinity();
};

// Over the directions within cell_radius_rad of `direction` (a unit vector in the part's frame).
ViewExtent view_extent(const std::vector<Eigen::Vector3d>& hull_vertices_mm,
                       const Eigen::Vector3d& direction, double cell_radius_rad);

// The angle within which every direction on the sphere has one of `directions` (unit vectors):
// the radius of each one's cell.
double covering_radius_rad(const std::vector<Eigen::Vector3d>& directions);

// Every view of the part the pose search starts from (the base's coarse views, or all of them
// when it has none) gets its extent over the start views' cells; the part's other views stay
// unbounded. Parts are independent: a builder may summarize them on several threads.
void summarize_view_extents(ModelBase& base, int part);

}  // namespace cosmos
