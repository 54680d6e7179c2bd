// `hil_player`: the simulated conveyor, recorded on the host (hil_render), played into vivid
// and gpio-sim inside the HIL guest (frame_player.hpp, encoder_player.hpp), for the cell or
// the bridge probe to scan.
//   hil_player --tape FILE --hardware HW.yaml [--faults cell|probe|none] [--output /dev/videoN]
//              [--gpio-sim DIR] [--lead-in-s S] --plan FILE --log FILE
// Writes the plan (where the stream ends, how long the cell must run) as soon as it is known,
// and the log of every capture and fault when done. Exit 0 when it played the whole conveyor.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <string>

#include "realtime/config/hardware_config.hpp"
#include "tests/hil/fault_plan.hpp"
#include "tests/hil/frame_player.hpp"
#include "tests/hil/frame_tape.hpp"
#include "tests/hil/gpio_sim_lines.hpp"

int main(int argc, char** argv) {
  CLI::App app("HIL player: the simulated conveyor into vivid and gpio-sim");
  std::string tape_file, hardware_file, faults = "none";
  std::string gpio_sim = "/sys/kernel/config/gpio-sim/cosmos";
  std::string plan_file, log_file;
  cosmos::hil::FramePlayerSettings settings;
  app.add_option("--tape", tape_file, "the conveyor's frames (hil_render)")->required();
  app.add_option("--hardware", hardware_file, "hardware YAML (camera ROI and format, lines)")
      ->required();
  app.add_option("--faults", faults, "fault plan: cell, probe or none")->capture_default_str();
  app.add_option("--output", settings.output_node, "vivid output node")->capture_default_str();
  app.add_option("--gpio-sim", gpio_sim, "gpio-sim configfs device")->capture_default_str();
  app.add_option("--lead-in-s", settings.lead_in_s, "empty belt before the conveyor")
      ->capture_default_str();
  app.add_option("--capture-timings", settings.loop.capture_timings, "capture DV timings")
      ->capture_default_str();
  app.add_option("--output-timings", settings.loop.output_timings, "output DV timings")
      ->capture_default_str();
  app.add_option("--plan", plan_file, "where the plan is written")->required();
  app.add_option("--log", log_file, "where the log is written")->required();
  CLI11_PARSE(app, argc, argv);
  try {
    const cosmos::HardwareConfig hardware = cosmos::read_hardware_config(hardware_file);
    cosmos::hil::FrameTapeReader tape(tape_file);
    cosmos::hil::GpioSimLines lines(gpio_sim);
    const cosmos::hil::FaultPlan plan = cosmos::hil::plan_faults(faults, tape.header());
    settings.capture_node = hardware.camera.device;
    settings.loop.pixel_format = hardware.camera.pixel_format;
    settings.faults = plan.faults;
    settings.bouncing_arrivals = plan.bouncing_arrivals;
    settings.plan_file = plan_file;
    const cosmos::hil::PlayerLog log = cosmos::hil::play_conveyor(tape, lines, hardware, settings);
    cosmos::hil::write_player_log(log_file, log);
    std::printf(
        "hil: player: %lld captures (%lld conveyor profiles after %lld lead-in frames), %lld "
        "sequence gaps, %lld stale, %lld merged events, %lld encoder edges\n",
        static_cast<long long>(log.count("captures")),
        static_cast<long long>(log.plan.conveyor_frames),
        static_cast<long long>(log.plan.lead_in_frames),
        static_cast<long long>(log.count("sequence_gaps")),
        static_cast<long long>(log.count("stale_captures")),
        static_cast<long long>(log.count("merged_events")),
        static_cast<long long>(log.count("encoder_edges")));
  } catch (const std::exception& error) {
    std::printf("hil: FAIL player: %s\n", error.what());
    return 1;
  }
  return 0;
}
