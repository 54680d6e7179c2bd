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

ScannerParameters parameters_of(const std::unique_ptr<SimulatedConveyor>& conveyor) {
  return conveyor ? conveyor->parameters() : ScannerParameters{};
}

}  // namespace

HardwareTwinSource::HardwareTwinSource(const HardwareConfig& config,
                                       std::unique_ptr<SimulatedConveyor> conveyor,
                                       const SimulatedGpioSettings& gpio_settings)
    : HardwareTwinSource(config, std::move(conveyor), parameters_of(conveyor), {}, gpio_settings) {}

HardwareTwinSource::HardwareTwinSource(const HardwareConfig& config,
                                       std::unique_ptr<SimulatedConveyor> conveyor,
                                       const ScannerParameters& told,
                                       const SimulatedMounting& truth,
                                       const SimulatedGpioSettings& gpio_settings)
    : conveyor_(std::move(conveyor)),
      clock_(checked(config, conveyor_).parameters()),
      camera_(*conveyor_, clock_, config.camera, truth),
      gpio_(*conveyor_, clock_, config.gpio, gpio_settings),
      hardware_(config, told, camera_, gpio_) {}

HardwareTwinSource::~HardwareTwinSource() { hardware_.stop(); }

SourceStatus HardwareTwinSource::start() {
  hardware_.stop();  // the camera must be closed to rewind
  camera_.rewind();
  return hardware_.start();
}

}  // namespace cosmos
