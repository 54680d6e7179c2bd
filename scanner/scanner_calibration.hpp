#pragma once
// The measured geometry of a real scanner, as `cosmos calibrate` writes it into the hardware
// YAML's `calibration:` section (realtime/config/hardware_config.hpp) and the cell's
// triangulation uses it. Each part carries its own `calibrated` flag: until a procedure has
// measured it, the designed geometry of scanner/scanner_model.hpp stands in for it.
//   camera: the lens (OpenCV pinhole + distortion), from board images
//   laser:  the laser sheet in the camera frame, n · p_camera = offset_mm
//   mount:  the camera in the scanner frame the belt defines (z up from the belt, y the
//           sheet's normal, x along the belt's laser line, origin below the optical axis)
#include "core/parameter_visitor.hpp"
#include "core/rigid_transform.hpp"
#include "scanner/scanner_model.hpp"
#include "scanner/triangulation_geometry.hpp"

namespace cosmos {

struct CalibratedCamera {
  bool calibrated = false;
  double fx_px = 0.0;
  double fy_px = 0.0;
  double cx_px = 0.0;
  double cy_px = 0.0;
  double k1 = 0.0;
  double k2 = 0.0;
  double p1 = 0.0;
  double p2 = 0.0;
  double k3 = 0.0;

  template <class Visitor>
  void visit(Visitor& v) {
    v("calibrated", calibrated, "false: the designed camera of the scanner: section");
    v("fx_px", fx_px, "focal length along the columns, px", Range{0, 1e6});
    v("fy_px", fy_px, "focal length along the rows, px", Range{0, 1e6});
    v("cx_px", cx_px, "principal point column, px", Range{-1e5, 1e5});
    v("cy_px", cy_px, "principal point row, px", Range{-1e5, 1e5});
    v("k1", k1, "radial distortion r^2", Range{-10, 10});
    v("k2", k2, "radial distortion r^4", Range{-100, 100});
    v("p1", p1, "tangential distortion", Range{-1, 1});
    v("p2", p2, "tangential distortion", Range{-1, 1});
    v("k3", k3, "radial distortion r^6", Range{-1000, 1000});
  }
};

struct CalibratedLaserPlane {
  bool calibrated = false;
  // Unit normal in the camera frame; the camera centre lies on the side offset_mm > 0 faces
  // away from.
  double normal_x = 0.0;
  double normal_y = 0.0;
  double normal_z = 1.0;
  double offset_mm = 0.0;

  template <class Visitor>
  void visit(Visitor& v) {
    v("calibrated", calibrated, "false: the designed vertical sheet y = 0");
    v("normal_x", normal_x, "laser-plane normal in the camera frame, x", Range{-1, 1});
    v("normal_y", normal_y, "laser-plane normal in the camera frame, y", Range{-1, 1});
    v("normal_z", normal_z, "laser-plane normal in the camera frame, z", Range{-1, 1});
    v("offset_mm", offset_mm, "n . p_camera = offset_mm on the plane, mm", Range{-1e5, 1e5});
  }
};

struct CalibratedMount {
  bool calibrated = false;
  // p_scanner = T_scanner_camera p_camera.
  RigidTransform T_scanner_camera;

  template <class Visitor>
  void visit(Visitor& v) {
    v("calibrated", calibrated, "false: the designed camera pose");
    v("T_scanner_camera", T_scanner_camera,
      "camera frame in the scanner frame: rotation_deg [rx, ry, rz] (R = Rz Ry Rx), "
      "translation_mm [x, y, z]");
  }
};

struct ScannerCalibration {
  CalibratedCamera camera;
  CalibratedLaserPlane laser;
  CalibratedMount mount;

  template <class Visitor>
  void visit(Visitor& v) {
    v("camera", camera, "lens intrinsics and distortion (cosmos calibrate camera)");
    v("laser", laser, "the laser plane in the camera frame (cosmos calibrate laser)");
    v("mount", mount, "the camera in the belt's scanner frame (cosmos calibrate belt)");
  }
};

// The designed geometry of `parameters` with every calibrated part of `calibration` in its
// place: the laser plane is carried into the scanner frame through the (calibrated or
// designed) camera pose.
TriangulationGeometry calibrated_triangulation_geometry(const ScannerParameters& parameters,
                                                        const ScannerCalibration& calibration);

// The laser plane of `geometry` in its camera frame, n · p_camera = offset.
CalibratedLaserPlane laser_plane_in_camera(const TriangulationGeometry& geometry);

}  // namespace cosmos
