#include "scanner/simulated_mounting.hpp"

#include <Eigen/Geometry>
#include <numbers>

namespace cosmos {

TriangulationGeometry true_triangulation_geometry(const ScannerParameters& nominal,
                                                  const SimulatedMounting& mounting) {
  TriangulationGeometry geometry =
      scanner_triangulation_geometry(true_scanner_parameters(nominal, mounting));
  constexpr double kRadPerDeg = std::numbers::pi / 180.0;
  // Both turns are about axes through the origin, so the optical axis still meets the belt's
  // laser line there: the image of the belt stays inside the ROI.
  const Eigen::Matrix3d turn =
      (Eigen::AngleAxisd(mounting.roll_deg * kRadPerDeg, Eigen::Vector3d::UnitY()) *
       Eigen::AngleAxisd(mounting.laser_plane_tilt_deg * kRadPerDeg, Eigen::Vector3d::UnitX()))
          .toRotationMatrix();
  geometry.R_scanner_camera = turn * geometry.R_scanner_camera;
  geometry.t_scanner_camera_mm = turn * geometry.t_scanner_camera_mm;
  geometry.t_scanner_camera_mm.z() += mounting.height_offset_mm;
  CameraIntrinsics& k = geometry.camera;
  k.fx_px *= mounting.focal_scale;
  k.fy_px *= mounting.focal_scale;
  k.cx_px += mounting.principal_shift_u_px;
  k.cy_px += mounting.principal_shift_v_px;
  k.k1 = mounting.k1;
  return geometry;
}

ScannerParameters true_scanner_parameters(const ScannerParameters& nominal,
                                          const SimulatedMounting& mounting) {
  ScannerParameters truth = nominal;
  if (mounting.encoder_mm_per_tick > 0.0) truth.encoder_mm_per_tick = mounting.encoder_mm_per_tick;
  if (mounting.field_of_view_mm > 0.0) truth.field_of_view_mm = mounting.field_of_view_mm;
  return truth;
}

bool moves_camera(const SimulatedMounting& m) {
  return m.laser_plane_tilt_deg != 0.0 || m.roll_deg != 0.0 || m.height_offset_mm != 0.0 ||
         m.focal_scale != 1.0 || m.principal_shift_u_px != 0.0 || m.principal_shift_v_px != 0.0 ||
         m.k1 != 0.0;
}

}  // namespace cosmos
