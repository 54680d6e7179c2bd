// `hil_check`: the verdict on a `cosmos cell` run inside the HIL guest (cell_check.hpp).
//   hil_check --config CELL.yaml --tape FILE --player-log FILE --lcm-log FILE
// Prints a line per check ("hil: PASS|FAIL|INFO …") and exits non-zero when one failed.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <string>

#include "realtime/config/cell_config.hpp"
#include "realtime/lcm/lcm_log_reader.hpp"
#include "tests/hil/cell_check.hpp"
#include "tests/hil/frame_tape.hpp"
#include "tests/hil/player_log.hpp"

int main(int argc, char** argv) {
  CLI::App app("HIL: check a cell run against the player and the conveyor's truth");
  std::string config_file, tape_file, player_file, lcm_file;
  double required = 0.9;
  app.add_option("--config", config_file, "the cell YAML the cell ran with")->required();
  app.add_option("--tape", tape_file, "the conveyor the player played")->required();
  app.add_option("--player-log", player_file, "the player's log")->required();
  app.add_option("--lcm-log", lcm_file, "lcm-logger's record of the cell's messages")->required();
  app.add_option("--required-fraction", required, "parts that must be identified")
      ->capture_default_str();
  CLI11_PARSE(app, argc, argv);
  try {
    const cosmos::CellConfig config = cosmos::load_cell_config(config_file);
    const cosmos::hil::FrameTapeReader tape(tape_file);
    const cosmos::hil::PlayerLog player = cosmos::hil::read_player_log(player_file);
    cosmos::hil::CellRun run;
    run.tape = &tape.header();
    run.player = &player;
    run.poses = cosmos::read_logged_poses(lcm_file);
    run.statuses = cosmos::read_logged_statuses(lcm_file);
    run.profiles = cosmos::read_logged_profiles(lcm_file, config.lcm.profile_channel);
    run.T_cell_scanner = config.cell.T_cell_scanner;
    run.mm_per_tick = config.scanner.encoder_mm_per_tick;
    run.required_fraction = required;
    return cosmos::hil::print_checks(cosmos::hil::check_cell_run(run)) == 0 ? 0 : 1;
  } catch (const std::exception& error) {
    std::printf("hil: FAIL check: %s\n", error.what());
    return 1;
  }
}
