#pragma once
// A coarse, conservative height map of a placed part: for each cell of a grid over the belt
// (belt frame, xy), an upper bound of the part's height over that cell (the highest vertex of
// every triangle whose bounding box touches it). It lets the scanner skip rays that cannot
// meet the part:
//   - clears(p, q): no part surface can lie on the segment p → q (q above p), e.g. a belt
//     point's line of sight to the camera that rises above the part before reaching it;
//   - x_extent(y): where across the belt the part can be at belt position y, so the probe
//     rays of a profile stay inside the part's real outline, not its bounding box.
// Both answers are conservative: "maybe" whenever the coarse bound cannot decide.
#include <Eigen/Geometry>
#include <vector>

#include "sim/mesh.hpp"

namespace cosmos {

class HeightBoundGrid {
 public:
  HeightBoundGrid() = default;
  // Bounds of `mesh` placed by T_belt_part, on cells of cell_mm (> 0).
  HeightBoundGrid(const TriangleMesh& mesh, const Eigen::Isometry3d& T_belt_part, double cell_mm);

  // True when the segment certainly meets no part surface (from.z <= to.z is assumed: the
  // segment's lowest point in a cell is where it enters it).
  bool clears(const Eigen::Vector3d& from, const Eigen::Vector3d& to) const;
  // Lines of sight from the belt points (z = 0) of one laser line (belt y) to one camera
  // centre share their y and z, so the grid's box limits them all to one interval of the
  // segment parameter; per point only x is left to test. A cheap pre-test before clears() for
  // the many belt samples of a profile.
  struct BeltSight {
    double y_mm = 0.0;
    Eigen::Vector3d camera_mm = Eigen::Vector3d::Zero();
    double s_begin = 0.0;
    double s_end = -1.0;  // empty when s_end < s_begin
  };
  BeltSight belt_sight(double y_mm, const Eigen::Vector3d& camera_mm) const;
  // False when the line of sight from belt point (x_mm, sight.y_mm, 0) certainly misses the box.
  bool may_block(const BeltSight& sight, double x_mm) const;
  // The belt points of one laser line (sample i at x0_mm + i dx_mm) whose line of sight may
  // pass over a cell no higher than the part's bound there: the only ones for which clears()
  // can be false. Adds 1 at difference[first] and -1 at difference[last + 1] for each such
  // run of samples (difference has samples + 1 entries), widened by a sample each side
  // against rounding. Per cell under the sight lines, not per sample: the lines share y(s)
  // and z(s), so each cell holds back one interval of x.
  void mark_belt_sights(const BeltSight& sight, double x0_mm, double dx_mm, int samples,
                        int* difference) const;

  // The x interval [x_low, x_high] the part can occupy at belt y; false when it is absent there.
  bool x_extent(double y_mm, double& x_low, double& x_high) const;

 private:
  float cell(int ix, int iy) const {
    return heights_[static_cast<std::size_t>(iy) * columns_ + ix];
  }

  double x0_mm_ = 0.0;
  double y0_mm_ = 0.0;
  double cell_mm_ = 1.0;
  int columns_ = 0;
  int rows_ = 0;
  double max_z_mm_ = 0.0;
  std::vector<float> heights_;     // -inf where no triangle reaches
  std::vector<int> first_column_;  // per row: first and last occupied cell, -1 when empty
  std::vector<int> last_column_;
};

}  // namespace cosmos
