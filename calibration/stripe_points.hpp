#pragma once
// The laser stripe of one frame as sub-pixel image points (the project's stripe extraction,
// firmware_bridge/laser_stripe_extraction.hpp, one point per column with a valid peak), and
// image points as rays of the calibrated camera meeting a plane: the board's plane for the
// laser calibration, the laser plane for every later step.
#include <Eigen/Core>
#include <opencv2/core/mat.hpp>
#include <vector>

#include "firmware_bridge/laser_stripe_extraction.hpp"
#include "scanner/scanner_calibration.hpp"

namespace cosmos {

// Full-sensor (u, v) of the stripe in `frame`, whose first row is sensor row roi_top_px.
std::vector<cv::Point2f> stripe_image_points(const cv::Mat& frame, int roi_top_px,
                                             const StripeExtractionParameters& extraction);

// Undistorted normalized coordinates (x/z, y/z) of pixel points.
std::vector<Eigen::Vector2d> normalized_points(const std::vector<cv::Point2f>& pixels,
                                               const CalibratedCamera& camera);

// The camera-frame points where the rays of `normalized` meet the plane n · p = offset;
// rays parallel to it or meeting it behind the camera are left out.
std::vector<Eigen::Vector3d> rays_on_plane(const std::vector<Eigen::Vector2d>& normalized,
                                           const Eigen::Vector3d& normal, double offset_mm);

}  // namespace cosmos

namespace cosmos {

// The scanner-frame points of a frame's stripe through `geometry` (camera, laser plane and
// camera pose): what the cell's triangulation makes of it, undistorting exactly.
std::vector<Eigen::Vector3d> stripe_scanner_points(const cv::Mat& frame, int roi_top_px,
                                                   const TriangulationGeometry& geometry,
                                                   const StripeExtractionParameters& extraction);

}  // namespace cosmos
