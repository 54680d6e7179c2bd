#include "tests/hil/conveyor_frames.hpp"

#include <stdexcept>
#include <string>

namespace cosmos::hil {

std::unique_ptr<SimulatedConveyor> make_hil_conveyor(const CellConfig& config,
                                                     const PartCatalog& catalog, int parts) {
  // As the cell builds its simulated conveyor, twins or not (apps/cell_world_simulated.cpp).
  SimulatedConveyorSettings settings = config.sim_source;
  if (parts > 0) settings.parts = parts;
  return std::make_unique<SimulatedConveyor>(catalog, config.scanner, settings);
}

ConveyorFrames::ConveyorFrames(const SimulatedConveyor& conveyor, const HardwareConfig& hardware)
    : conveyor_(conveyor),
      clock_(conveyor.parameters()),
      camera_(conveyor, clock_, hardware.camera),
      gpio_(conveyor, clock_, hardware.gpio) {
  if (camera_.start() != CameraStatus::kOk) {
    throw std::runtime_error("simulated camera: " + std::string(camera_.last_error()));
  }
}

ConveyorFrames::~ConveyorFrames() { camera_.stop(); }

bool ConveyorFrames::next(FrameView& frame) {
  if (holding_) {
    camera_.release_frame(lent_);
    holding_ = false;
  }
  const CameraStatus status = camera_.next_frame(0, lent_);
  if (status == CameraStatus::kEndOfStream) return false;
  if (status != CameraStatus::kOk) {
    throw std::runtime_error("simulated camera: " + std::string(camera_.last_error()));
  }
  holding_ = true;
  frame = lent_;
  ++next_profile_;
  return true;
}

}  // namespace cosmos::hil
