#pragma once
// The hardware source run on the hardware twins: a simulated conveyor (the same world as
// SimulatedSource's, sim/source/simulated_conveyor.hpp), its belt clock, a SimulatedCamera
// and SimulatedGpioLines over them, and the cell's real HardwareSource reading those two, so
// `cosmos cell --source hardware --hardware config/hardware-sim.yaml` runs the hardware
// path — stripe extraction, triangulation, encoder and photo-eye decoding, the outputs —
// end to end without hardware, with the conveyor's ground truth at hand.
//
// Every ScannerSource call goes to the HardwareSource. start() first puts the belt back at
// frame 0, so a restarted source replays the identical stream (as SimulatedSource does);
// the stream ends after the conveyor's last profile. Profile k is camera frame k, exposed at
// encoder tick k · encoder_ticks_per_profile: seq and encoder_ticks mean what the simulated
// source's mean, and placed_part_scanned_in() pairs a pose with its truth the same way.
#include <cstdint>
#include <memory>

#include "realtime/config/hardware_config.hpp"
#include "realtime/sources/hardware_source.hpp"
#include "realtime/sources/scanner_source.hpp"
#include "sim/source/fault_plan.hpp"
#include "sim/source/simulated_conveyor.hpp"
#include "sim/twins/simulated_belt_clock.hpp"
#include "sim/twins/simulated_camera.hpp"
#include "sim/twins/simulated_gpio_lines.hpp"

namespace cosmos {

class HardwareTwinSource final : public ScannerSource {
 public:
  // std::invalid_argument unless config names the simulated camera and GPIO chip.
  // `faults`: injected at the devices (SimulatedCamera, SimulatedGpioLines); none by default.
  HardwareTwinSource(const HardwareConfig& config, std::unique_ptr<SimulatedConveyor> conveyor,
                     const SimulatedGpioSettings& gpio_settings = {},
                     const FaultInjectionSettings& faults = {});
  // A mis-mounted cell (scanner/simulated_mounting.hpp): the conveyor runs by the true
  // parameters and the camera renders through `truth`, while the hardware source triangulates
  // and steps the belt with `told`, the parameters the cell was given.
  HardwareTwinSource(const HardwareConfig& config, std::unique_ptr<SimulatedConveyor> conveyor,
                     const ScannerParameters& told, const SimulatedMounting& truth,
                     const SimulatedGpioSettings& gpio_settings = {},
                     const FaultInjectionSettings& faults = {});
  ~HardwareTwinSource() override;
  HardwareTwinSource(const HardwareTwinSource&) = delete;
  HardwareTwinSource& operator=(const HardwareTwinSource&) = delete;

  SourceStatus start() override;
  void reserve(Profile& profile) const override { hardware_.reserve(profile); }
  SourceStatus next(Profile& out) noexcept override { return hardware_.next(out); }
  void stop() noexcept override { hardware_.stop(); }

  double mm_per_profile() const override { return hardware_.mm_per_profile(); }
  std::string_view last_error() const noexcept override { return hardware_.last_error(); }
  SourceHealth health() const noexcept override { return hardware_.health(); }

  const SimulatedConveyor& conveyor() const { return *conveyor_; }
  const PlacedSimPart* placed_part_scanned_in(std::int64_t first_profile,
                                              std::int64_t last_profile) const {
    return conveyor_->placed_part_scanned_in(first_profile, last_profile);
  }
  HardwareSource& hardware() { return hardware_; }
  const HardwareSource& hardware() const { return hardware_; }
  const SimulatedCamera& camera() const { return camera_; }
  SimulatedCamera& camera() { return camera_; }
  const SimulatedGpioLines& gpio() const { return gpio_; }

 private:
  // Both public constructors: `told` null = the conveyor's own parameters.
  HardwareTwinSource(const HardwareConfig& config, std::unique_ptr<SimulatedConveyor> conveyor,
                     const ScannerParameters* told, const SimulatedMounting& truth,
                     const SimulatedGpioSettings& gpio_settings,
                     const FaultInjectionSettings& faults);

  std::unique_ptr<SimulatedConveyor> conveyor_;
  SimulatedBeltClock clock_;
  FaultPlan faults_;
  SimulatedCamera camera_;
  SimulatedGpioLines gpio_;
  HardwareSource hardware_;  // declared after the devices it reads
};

}  // namespace cosmos
