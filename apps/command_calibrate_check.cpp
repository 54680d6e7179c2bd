// `cosmos calibrate check --config CELL --hardware HW [--parts N]`: how well the simulated
// cell recognizes with the calibration it is told. The cell of `cosmos cell --source
// hardware` runs on the hardware twins, which render through the true geometry
// (sim_source.truth:); every pose is compared with the conveyor's ground truth in the cell
// frame, T_cell_part = T_cell_scanner(true) T_scanner_belt(e, true mm per tick) T_belt_part,
// and the identification rate and the pose errors of the correctly identified parts are
// printed (median and 90th percentile of translation, mm, and rotation, degrees).
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "apps/cell_world.hpp"
#include "apps/command_registry.hpp"
#include "core/input_error.hpp"
#include "core/recognition/recognizer.hpp"
#include "realtime/cell/cell_runner.hpp"
#include "realtime/config/cell_config.hpp"
#include "realtime/config/hardware_config.hpp"
#include "realtime/lcm/memory_publisher.hpp"
#include "scanner/simulated_mounting.hpp"
#include "sim/conveyor_scene.hpp"
#include "sim/part_catalog.hpp"
#include "sim/twins/hardware_twin_source.hpp"

namespace cosmos::cli {
namespace {

struct CheckOptions {
  std::string config = "config/cell.yaml";
  std::string hardware = "config/hardware-sim.yaml";
  int parts = 100;
};

double quantile(std::vector<double> values, double q) {
  if (values.empty()) return NAN;
  std::sort(values.begin(), values.end());
  return values[std::min(values.size() - 1,
                         static_cast<std::size_t>(q * static_cast<double>(values.size())))];
}

void run_check(const CheckOptions& options) {
  const CellConfig config = load_cell_config(options.config);
  const HardwareConfig hardware = read_hardware_config(options.hardware);
  if (!hardware.camera_simulated())
    throw InputError(options.hardware + ": calibrate check needs the simulated twins");
  const SimulatedMounting& truth = config.sim_source.truth;
  const ScannerParameters true_scanner = true_scanner_parameters(config.scanner, truth);
  SimulatedSourceSettings settings = config.sim_source;
  settings.parts = options.parts;
  const PartCatalog catalog = read_part_catalog(config.cell.catalog);
  HardwareTwinSource source(hardware,
                            std::make_unique<SimulatedConveyor>(catalog, true_scanner, settings),
                            config.scanner, truth);
  if (source.start() != SourceStatus::kOk) throw InputError(std::string(source.last_error()));
  if (std::abs(source.mm_per_profile() - config.conditioning.grid_mm) > 1e-9)
    throw InputError(options.config + ": conditioning.grid_mm must equal the belt travel per " +
                     "profile (" + std::to_string(source.mm_per_profile()) + " mm)");
  const CellWorld world(config);
  const CellModelBase loaded = world.load_model_base();
  RecognitionParameters recognition;
  recognition.surface_seen.sight = scanner_sight(config.scanner);
  const Recognizer recognizer(loaded.base, loaded.cosmos, recognition);
  ScanLoop loop({.conditioning = config.conditioning,
                 .tracking = config.tracking.tracker,
                 .cosmos = loaded.cosmos,
                 .max_part_rows = config.max_part_rows(),
                 .parts = config.realtime.parts,
                 .wait_for_recognizer = true});
  PartRecognitionContext context;
  context.recognizer = &recognizer;
  context.model_base = &loaded.base;
  context.cosmos = loaded.cosmos;
  context.catalog_index_of_base_part = world.catalog_indices(loaded.base);
  context.T_cell_scanner = config.cell.T_cell_scanner;
  context.mm_per_tick = config.scanner.encoder_mm_per_tick;
  context.grid_mm = config.conditioning.grid_mm;
  context.x0_loop_mm = loop.x0_loop_mm();
  CellRunSettings run_settings;
  run_settings.paced = false;
  run_settings.deterministic_output = true;
  run_settings.threads = config.realtime.threads;
  MemoryPublisher publisher;

  int identified = 0;
  std::vector<double> translation_mm;
  std::vector<double> rotation_deg;
  const CellRunSummary summary = run_cell(
      source, loop, context, publisher, run_settings, [&](const PartRecognition& recognition) {
        const PlacedSimPart* placed =
            source.placed_part_scanned_in(recognition.first_profile, recognition.last_profile);
        const PartPose& pose = recognition.pose;
        if (!placed || pose.status != PoseStatus::kOk || pose.part_name != placed->name) return;
        ++identified;
        const Eigen::Isometry3d T_scanner_part =
            T_scanner_belt(true_scanner, pose.encoder_ticks) * placed->T_belt_part;
        const RigidTransform T_cell_part_true =
            truth.T_cell_scanner *
            RigidTransform{T_scanner_part.rotation(), T_scanner_part.translation()};
        translation_mm.push_back(
            (pose.translation_cell_part_mm - T_cell_part_true.translation_mm).norm());
        rotation_deg.push_back(
            rotation_angle_between_rad(pose.rotation_cell_part.toRotationMatrix(),
                                       T_cell_part_true.rotation) *
            180.0 / std::numbers::pi);
      });
  if (!summary.source_error.empty()) throw InputError(summary.source_error);
  std::printf(
      "calibrate check: %d of %d parts identified (%.1f %%); pose error in the cell frame: "
      "translation median %.3f mm, p90 %.3f mm; rotation median %.3f deg, p90 %.3f deg\n",
      identified, options.parts, 100.0 * identified / options.parts, quantile(translation_mm, 0.5),
      quantile(translation_mm, 0.9), quantile(rotation_deg, 0.5), quantile(rotation_deg, 0.9));
}

void install(CLI::App& root) {
  CLI::App* calibrate = root.get_subcommand("calibrate");
  auto options = std::make_shared<CheckOptions>();
  CLI::App* check = calibrate->add_subcommand(
      "check", "Run the simulated cell on its twins and compare its poses with the truth");
  check->add_option("--config", options->config, "cell config")->capture_default_str();
  check->add_option("--hardware", options->hardware, "hardware YAML of the twins")
      ->capture_default_str();
  check->add_option("--parts", options->parts, "parts sent down the belt")
      ->check(CLI::Range(1, 100000))
      ->capture_default_str();
  check->callback([options] { run_check(*options); });
}

// Registered after "calibrate" (the registry installs in name order), which it extends.
const CommandRegistration registration("calibrate_check", install);

}  // namespace
}  // namespace cosmos::cli
