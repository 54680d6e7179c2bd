// `hil_probe`: the bridge's checks against the real kernel drivers inside the HIL guest.
//   hil_probe loop --hardware FILE [--output /dev/videoN] [--frames N]
//     for each pixel format: a frame written to vivid's output comes back through V4l2Camera
//   hil_probe lifecycle --hardware FILE     the camera's lifecycle twice, nothing leaked
//   hil_probe formats --hardware FILE       what vivid offers, taken and refused
//   hil_probe gpio --hardware FILE [--gpio-sim DIR]
//     LibgpiodLines against gpio-sim: outputs, quadrature counting, the photo eye
//   hil_probe faults --hardware FILE --config CELL.yaml --plan FILE --player-log FILE
//     HardwareSource on the player's faults (bridge_probe.hpp)
// Prints one line per check ("hil: PASS|FAIL|INFO …") and exits non-zero when one failed.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <string>

#include "realtime/config/cell_config.hpp"
#include "realtime/config/hardware_config.hpp"
#include "tests/hil/bridge_probe.hpp"
#include "tests/hil/gpio_probe.hpp"
#include "tests/hil/lifecycle_probe.hpp"
#include "tests/hil/loop_probe.hpp"

namespace {

int run_loop(const cosmos::HardwareConfig& hardware, const std::string& output, int frames) {
  const cosmos::hil::VividLoopSettings loop;
  std::vector<cosmos::hil::ProbeCheck> checks;
  for (const cosmos::PixelFormat format : {cosmos::PixelFormat::kGrey8, cosmos::PixelFormat::kY10,
                                           cosmos::PixelFormat::kY12, cosmos::PixelFormat::kY16}) {
    const cosmos::hil::LoopProbeResult result =
        cosmos::hil::probe_loop(output, hardware.camera, loop, format, frames);
    checks.push_back({result.ok, result.line, false});
  }
  return cosmos::hil::print_checks(checks);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app("HIL bridge checks against vivid and gpio-sim");
  app.require_subcommand(1);
  std::string hardware_file, output = "/dev/video1",
                             gpio_sim = "/sys/kernel/config/gpio-sim/cosmos";
  std::string config_file, plan_file, player_log;
  int frames = 5;
  CLI::App* loop = app.add_subcommand("loop", "frames through vivid's loop and V4l2Camera");
  CLI::App* lifecycle = app.add_subcommand("lifecycle", "the camera's lifecycle, twice");
  CLI::App* formats = app.add_subcommand("formats", "format negotiation with vivid");
  CLI::App* gpio = app.add_subcommand("gpio", "LibgpiodLines against gpio-sim");
  CLI::App* faults = app.add_subcommand("faults", "HardwareSource on the player's faults");
  for (CLI::App* command : {loop, lifecycle, formats, gpio, faults})
    command->add_option("--hardware", hardware_file, "hardware YAML")->required();
  loop->add_option("--output", output, "vivid output node");
  loop->add_option("--frames", frames, "frames compared per format");
  gpio->add_option("--gpio-sim", gpio_sim, "gpio-sim configfs device");
  faults->add_option("--config", config_file, "cell YAML (the scanner section)")->required();
  faults->add_option("--plan", plan_file, "the player's plan")->required();
  faults->add_option("--player-log", player_log, "the player's log")->required();
  CLI11_PARSE(app, argc, argv);
  try {
    const cosmos::HardwareConfig hardware = cosmos::read_hardware_config(hardware_file);
    int failed = 0;
    if (loop->parsed()) failed = run_loop(hardware, output, frames);
    if (lifecycle->parsed())
      failed = cosmos::hil::print_checks(cosmos::hil::probe_lifecycle(hardware.camera));
    if (formats->parsed())
      failed = cosmos::hil::print_checks(cosmos::hil::probe_formats(hardware.camera));
    if (gpio->parsed())
      failed = cosmos::hil::print_checks(cosmos::hil::probe_gpio(hardware.gpio, gpio_sim));
    if (faults->parsed()) {
      cosmos::hil::BridgeProbeSettings settings;
      settings.hardware = hardware;
      settings.scanner = cosmos::load_cell_config(config_file).scanner;
      settings.plan_file = plan_file;
      settings.player_log = player_log;
      failed = cosmos::hil::print_checks(cosmos::hil::probe_bridge(settings));
    }
    return failed == 0 ? 0 : 1;
  } catch (const std::exception& error) {
    std::printf("hil: FAIL %s\n", error.what());
    return 1;
  }
}
