#pragma once
// The simulated conveyor the HIL player plays: the same world the cell's `sim_source:`
// section describes (apps/cell_source.cpp builds it the same way), seen through the
// hardware twins' SimulatedCamera, so the frames are the simulator's camera-mode frames of
// the hardware config's ROI and pixel format, profile after profile, and its photo-eye beam
// interruptions (SimulatedGpioLines::beam_interruptions) in conveyor ticks.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "realtime/config/cell_config.hpp"
#include "realtime/config/hardware_config.hpp"
#include "sim/part_catalog.hpp"
#include "sim/source/simulated_conveyor.hpp"
#include "sim/twins/simulated_belt_clock.hpp"
#include "sim/twins/simulated_camera.hpp"
#include "sim/twins/simulated_gpio_lines.hpp"

namespace cosmos::hil {

// The conveyor of `config`'s sim_source section, `parts` parts (<= 0: the section's count).
std::unique_ptr<SimulatedConveyor> make_hil_conveyor(const CellConfig& config,
                                                     const PartCatalog& catalog, int parts);

class ConveyorFrames {
 public:
  // The conveyor must outlive this.
  ConveyorFrames(const SimulatedConveyor& conveyor, const HardwareConfig& hardware);
  ~ConveyorFrames();

  // Renders the next profile's frame (profile 0 first) and returns it; valid until the next
  // call. False after the conveyor's last profile.
  bool next(FrameView& frame);
  // The profile the next call renders.
  std::int64_t next_profile() const { return next_profile_; }
  std::int64_t last_profile() const { return conveyor_.last_profile(); }
  const std::vector<BeamInterruption>& beam_interruptions() const {
    return gpio_.beam_interruptions();
  }
  int ticks_per_profile() const { return clock_.ticks_per_frame(); }

 private:
  const SimulatedConveyor& conveyor_;
  SimulatedBeltClock clock_;
  SimulatedCamera camera_;
  SimulatedGpioLines gpio_;
  FrameView lent_;
  bool holding_ = false;
  std::int64_t next_profile_ = 0;
};

}  // namespace cosmos::hil
