#pragma once
// Laser triangulation of one camera frame: stripe peaks (sensor column, sub-pixel row) →
// points on the laser plane in the scanner frame (x across the belt, z up).
//
// Columns are fixed and only the row varies, so the lens undistortion (iterative, the costly
// part) is precomputed at set-up with cv::undistortPoints on the integer (column, row) grid
// of the ROI. A frame then costs, per column, one linear interpolation of the undistorted
// ray along the row and one ray–plane intersection: no OpenCV call, no allocation, no
// iteration on the acquisition thread. Interpolating the ray rather than the 3D point keeps
// the result exact for a pinhole camera (normalized coordinates are affine in the pixel
// coordinates) where the point itself is a ratio of linear functions of the row.
#include <vector>

#include "firmware_bridge/laser_stripe_extraction.hpp"
#include "scanner/triangulation_geometry.hpp"

namespace cosmos {

// Per stripe column: the triangulated point's x and z (scanner frame, mm), NaN where the
// column had no peak or its ray misses the plane. Owned by the caller, reused per frame.
struct TriangulatedStripe {
  std::vector<float> x_mm;
  std::vector<float> z_mm;
  int valid_points = 0;
};

class LaserTriangulator {
 public:
  // Lookup table for sensor rows [first_row_px, first_row_px + row_count) of every sensor
  // column. Allocates width × row_count entries and runs cv::undistortPoints once.
  LaserTriangulator(const TriangulationGeometry& geometry, int first_row_px, int row_count);
  // Table for the geometry's ROI rows.
  explicit LaserTriangulator(const TriangulationGeometry& geometry);

  void reserve(int max_columns, TriangulatedStripe& stripe) const;

  // One frame's peaks → points. Rows outside the table give NaN. Never throws; allocates
  // only if `stripe` is narrower than the peaks and was not reserved.
  void triangulate(const StripePeaks& peaks, TriangulatedStripe& stripe) const noexcept;

  const TriangulationGeometry& geometry() const { return geometry_; }

 private:
  // Undistorted normalized camera coordinates (x/z, y/z) of a pixel's ray.
  struct NormalizedRay {
    float x;
    float y;
  };

  TriangulationGeometry geometry_;
  int first_row_px_ = 0;
  int row_count_ = 0;
  // Ray–plane intersection in the camera frame, precomputed: for a ray d = (x, y, 1),
  // s = plane_distance_ / (plane_normal_camera_ · d) and p_scanner = t + s · R d.
  Eigen::Vector3d plane_normal_camera_;
  double plane_distance_mm_ = 0.0;
  // [column * row_count_ + row]: a column's rows are adjacent, so the interpolation reads
  // one cache line.
  std::vector<NormalizedRay> table_;
};

}  // namespace cosmos
