#pragma once
// Where a laser-triangulation scanner measures a surface point from: the camera that must see
// the point and the laser source that must light it, relative to the point's own spot in the
// laser sheet when it is measured (x across the belt, y along the travel, z up, mm; the sheet
// is the plane y = 0, its foot on the belt centre line). A surface facing away from either is
// never measured, whatever lies around it: the far wall of a channel, the downstream slope of a
// tall part. The scanner's own keys declare the geometry (scanner/scanner_model.hpp,
// ScannerParameters::sight); this is what the recognition reads of it.
#include <Eigen/Core>

namespace cosmos {

struct ScannerSight {
  // The camera's centre, relative to the sheet's foot on the belt centre line.
  Eigen::Vector3d camera_mm = Eigen::Vector3d::Zero();
  // The laser fan's source above the belt centre line; 0: a parallel sheet, every ray vertical.
  double laser_height_mm = 0.0;

  // Whether a point at `point_mm` (x and height; its y is the sheet's when measured) whose
  // surface normal is `normal` faces both the camera and the laser.
  bool measurable(const Eigen::Vector3d& point_mm, const Eigen::Vector3d& normal) const {
    const Eigen::Vector3d to_camera(camera_mm.x() - point_mm.x(), camera_mm.y(),
                                    camera_mm.z() - point_mm.z());
    const Eigen::Vector3d to_laser =
        laser_height_mm > 0 ? Eigen::Vector3d(-point_mm.x(), 0.0, laser_height_mm - point_mm.z())
                            : Eigen::Vector3d::UnitZ();
    return normal.dot(to_camera) > 0 && normal.dot(to_laser) > 0;
  }
};

}  // namespace cosmos
