// `hil_probe`: the bridge's checks against the real kernel drivers inside the HIL guest.
//   hil_probe loop --hardware FILE --output /dev/videoN [--frames N]
//     for each pixel format: a frame written to vivid's output comes back through V4l2Camera
//   hil_probe gpio --hardware FILE --gpio-sim /sys/kernel/config/gpio-sim/NAME
//     LibgpiodLines against gpio-sim: outputs, quadrature counting, the photo eye
// Prints one line per check, "hil: PASS ...", "hil: FAIL ..." or "hil: INFO ..." (a measured
// fact), and exits non-zero when any check failed.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <string>

#include "realtime/config/hardware_config.hpp"
#include "tests/hil/gpio_probe.hpp"
#include "tests/hil/loop_probe.hpp"

namespace {

struct LoopOptions {
  std::string hardware;
  std::string output = "/dev/video1";
  std::string capture_timings = "1280x720p24";
  std::string output_timings = "1280x720p60";
  int frames = 5;
};

int run_loop(const LoopOptions& options) {
  const cosmos::HardwareConfig hardware = cosmos::read_hardware_config(options.hardware);
  cosmos::hil::VividLoopSettings loop;
  loop.capture_timings = options.capture_timings;
  loop.output_timings = options.output_timings;
  int failed = 0;
  for (const cosmos::PixelFormat format : {cosmos::PixelFormat::kGrey8, cosmos::PixelFormat::kY10,
                                           cosmos::PixelFormat::kY12, cosmos::PixelFormat::kY16}) {
    const cosmos::hil::LoopProbeResult result =
        cosmos::hil::probe_loop(options.output, hardware.camera, loop, format, options.frames);
    std::printf("hil: %s %s\n", result.ok ? "PASS" : "FAIL", result.line.c_str());
    failed += result.ok ? 0 : 1;
  }
  return failed == 0 ? 0 : 1;
}

struct GpioOptions {
  std::string hardware;
  std::string gpio_sim = "/sys/kernel/config/gpio-sim/cosmos";
};

int run_gpio(const GpioOptions& options) {
  const cosmos::HardwareConfig hardware = cosmos::read_hardware_config(options.hardware);
  int failed = 0;
  for (const cosmos::hil::ProbeCheck& check :
       cosmos::hil::probe_gpio(hardware.gpio, options.gpio_sim)) {
    std::printf("hil: %s %s\n",
                check.info ? "INFO"
                : check.ok ? "PASS"
                           : "FAIL",
                check.line.c_str());
    failed += check.ok ? 0 : 1;
  }
  return failed == 0 ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app("HIL bridge checks against vivid and gpio-sim");
  app.require_subcommand(1);
  LoopOptions loop;
  CLI::App* loop_command = app.add_subcommand("loop", "frames through vivid's loop and V4l2Camera");
  loop_command->add_option("--hardware", loop.hardware, "hardware YAML")->required();
  loop_command->add_option("--output", loop.output, "vivid output node");
  loop_command->add_option("--capture-timings", loop.capture_timings, "capture DV timings");
  loop_command->add_option("--output-timings", loop.output_timings, "output DV timings");
  loop_command->add_option("--frames", loop.frames, "frames compared per format");
  GpioOptions gpio;
  CLI::App* gpio_command = app.add_subcommand("gpio", "LibgpiodLines against gpio-sim");
  gpio_command->add_option("--hardware", gpio.hardware, "hardware YAML")->required();
  gpio_command->add_option("--gpio-sim", gpio.gpio_sim, "gpio-sim configfs device");
  CLI11_PARSE(app, argc, argv);
  try {
    if (loop_command->parsed()) return run_loop(loop);
    if (gpio_command->parsed()) return run_gpio(gpio);
  } catch (const std::exception& error) {
    std::printf("hil: FAIL %s\n", error.what());
    return 1;
  }
  return 1;
}
