#include "sim/twins/hardware_twin_source.hpp"

#include <stdexcept>
#include <utility>

namespace cosmos {
namespace {

const SimulatedConveyor& checked(const HardwareConfig& config,
                                 const std::unique_ptr<SimulatedConveyor>& conveyor) {
  if (!config.camera_simulated() || !config.gpio_simulated()) {
    throw std::invalid_argument(
        "hardware twins: the hardware config must name camera.device and gpio.chip simulated");
  }
  if (!conveyor) throw std::invalid_argument("hardware twins: no simulated conveyor");
  return *conveyor;
}

}  // namespace

HardwareTwinSource::HardwareTwinSource(const HardwareConfig& config,
                                       std::unique_ptr<SimulatedConveyor> conveyor,
                                       const SimulatedGpioSettings& gpio_settings,
                                       const FaultInjectionSettings& faults)
    : HardwareTwinSource(config, std::move(conveyor), nullptr, SimulatedMounting{}, gpio_settings,
                         faults) {}

HardwareTwinSource::HardwareTwinSource(const HardwareConfig& config,
                                       std::unique_ptr<SimulatedConveyor> conveyor,
                                       const ScannerParameters& told,
                                       const SimulatedMounting& truth,
                                       const SimulatedGpioSettings& gpio_settings,
                                       const FaultInjectionSettings& faults)
    : HardwareTwinSource(config, std::move(conveyor), &told, truth, gpio_settings, faults) {}

HardwareTwinSource::HardwareTwinSource(const HardwareConfig& config,
                                       std::unique_ptr<SimulatedConveyor> conveyor,
                                       const ScannerParameters* told,
                                       const SimulatedMounting& truth,
                                       const SimulatedGpioSettings& gpio_settings,
                                       const FaultInjectionSettings& faults)
    : conveyor_(std::move(conveyor)),
      clock_(checked(config, conveyor_).parameters()),
      faults_(faults),
      camera_(*conveyor_, clock_, config.camera, faults_, truth),
      gpio_(*conveyor_, clock_, config.gpio, gpio_settings, faults_),
      hardware_(config, told ? *told : conveyor_->parameters(), camera_, gpio_) {
  camera_.follow_laser_enable(gpio_);
}

HardwareTwinSource::~HardwareTwinSource() { hardware_.stop(); }

SourceStatus HardwareTwinSource::start() {
  hardware_.stop();  // the camera must be closed to rewind
  camera_.rewind();
  return hardware_.start();
}

}  // namespace cosmos
