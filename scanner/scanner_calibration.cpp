#include "scanner/scanner_calibration.hpp"

namespace cosmos {

TriangulationGeometry calibrated_triangulation_geometry(const ScannerParameters& parameters,
                                                        const ScannerCalibration& calibration) {
  TriangulationGeometry geometry = scanner_triangulation_geometry(parameters);
  const CalibratedCamera& camera = calibration.camera;
  if (camera.calibrated) {
    CameraIntrinsics& k = geometry.camera;
    k.fx_px = camera.fx_px;
    k.fy_px = camera.fy_px;
    k.cx_px = camera.cx_px;
    k.cy_px = camera.cy_px;
    k.k1 = camera.k1;
    k.k2 = camera.k2;
    k.p1 = camera.p1;
    k.p2 = camera.p2;
    k.k3 = camera.k3;
  }
  // The designed sheet, held in the camera frame while the camera pose changes under it.
  CalibratedLaserPlane plane = laser_plane_in_camera(geometry);
  if (calibration.laser.calibrated) plane = calibration.laser;
  if (calibration.mount.calibrated) {
    geometry.R_scanner_camera = calibration.mount.T_scanner_camera.rotation;
    geometry.t_scanner_camera_mm = calibration.mount.T_scanner_camera.translation_mm;
  }
  const Eigen::Vector3d normal_camera =
      Eigen::Vector3d(plane.normal_x, plane.normal_y, plane.normal_z).normalized();
  geometry.laser_plane.normal_scanner = geometry.R_scanner_camera * normal_camera;
  geometry.laser_plane.offset_mm =
      plane.offset_mm + geometry.laser_plane.normal_scanner.dot(geometry.t_scanner_camera_mm);
  return geometry;
}

CalibratedLaserPlane laser_plane_in_camera(const TriangulationGeometry& geometry) {
  // n_s · (R p_c + t) = d_s  ⇔  (Rᵀ n_s) · p_c = d_s − n_s · t.
  const Eigen::Vector3d normal_camera =
      geometry.R_scanner_camera.transpose() * geometry.laser_plane.normal_scanner;
  CalibratedLaserPlane plane;
  plane.calibrated = true;
  plane.normal_x = normal_camera.x();
  plane.normal_y = normal_camera.y();
  plane.normal_z = normal_camera.z();
  plane.offset_mm = geometry.laser_plane.offset_mm -
                    geometry.laser_plane.normal_scanner.dot(geometry.t_scanner_camera_mm);
  return plane;
}

}  // namespace cosmos
