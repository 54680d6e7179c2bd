#pragma once
// The small world the hardware-twin tests share: a conveyor of three procedural parts (a
// ball and a brick, no catalog meshes needed), and the camera and GPIO settings that name
// the simulator's own camera mode (its sensor columns, its ROI rows) and the simulated chip.
#include <memory>
#include <vector>

#include "firmware_bridge/camera_config.hpp"
#include "firmware_bridge/gpio_config.hpp"
#include "realtime/config/hardware_config.hpp"
#include "scanner/triangulation_geometry.hpp"
#include "sim/procedural_meshes.hpp"
#include "sim/source/simulated_conveyor.hpp"

namespace cosmos::testing {

inline std::vector<SimPartModel> twin_test_parts() {
  return {{"ball", make_icosphere(15.0, 2), 0}, {"brick", make_box(40.0, 25.0, 12.0), 1}};
}

inline SimulatedConveyorSettings twin_test_settings(int parts = 3) {
  SimulatedConveyorSettings settings;
  settings.parts = parts;
  settings.seed = 5;
  settings.part_gap_mm = 30.0;
  return settings;
}

inline std::unique_ptr<SimulatedConveyor> twin_test_conveyor(
    const ScannerParameters& parameters = {}, int parts = 3) {
  return std::make_unique<SimulatedConveyor>(twin_test_parts(), parameters,
                                             twin_test_settings(parts));
}

// The frames camera mode draws: every sensor column, the scanner's ROI rows.
inline CameraConfig simulator_camera(const ScannerParameters& parameters = {}) {
  const TriangulationGeometry geometry = scanner_triangulation_geometry(parameters);
  CameraConfig camera;
  camera.device = std::string(kSimulatedDevice);
  camera.width_px = parameters.sensor_width_px;
  camera.height_px = geometry.roi_height_px;
  camera.roi_top_px = geometry.roi_row_offset_px;
  return camera;
}

inline GpioConfig simulated_gpio() {
  GpioConfig gpio;
  gpio.chip = std::string(kSimulatedDevice);
  return gpio;
}

}  // namespace cosmos::testing
