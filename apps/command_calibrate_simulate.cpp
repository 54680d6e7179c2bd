// `cosmos calibrate simulate --config CELL --out DIR`: the calibration targets of the
// simulated cell, rendered through its true geometry (the config's sim_source.truth:), as the
// files a real cell's procedure records: DIR/camera/ (board images), DIR/laser/ (board and
// stripe image pairs), DIR/belt/, DIR/block/ and DIR/block-turned/ (frame directories of the
// empty belt and the ramp block, either way round) with DIR/ramp.yaml, DIR/spheres/ with
// DIR/spheres.yaml, and DIR/truth.txt, the values a perfect calibration would find.
//
// `cosmos calibrate truth --config CELL --hardware HW`: writes that perfect calibration into
// HW's calibration: section and CELL's encoder, grid and T_cell_scanner, the reference of the
// end-to-end comparison (scripts/calibration_e2e.sh).
#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>
#include <numbers>
#include <opencv2/imgcodecs.hpp>
#include <string>

#include "apps/command_registry.hpp"
#include "calibration/belt_calibration.hpp"
#include "calibration/frame_list.hpp"
#include "calibration/target_file.hpp"
#include "calibration/yaml_update.hpp"
#include "core/input_error.hpp"
#include "realtime/config/cell_config.hpp"
#include "sim/calibration_targets/calibration_target_simulator.hpp"

namespace cosmos::cli {
namespace {

namespace fs = std::filesystem;

struct SimulateOptions {
  std::string config = "config/cell.yaml";
  std::string out = "calibration-frames";
  std::string hardware;
  std::uint64_t seed = 1;
  int camera_views = 24;
  int laser_views = 6;
};

std::string numbered(const char* prefix, std::size_t i) {
  char name[64];
  std::snprintf(name, sizeof name, "%s-%02zu.png", prefix, i);
  return name;
}

void write_truth(const fs::path& file, const CalibrationTruth& truth) {
  std::ofstream out(file);
  const CalibratedCamera& c = truth.camera;
  const CalibratedLaserPlane& p = truth.laser;
  const Eigen::Vector3d& t = truth.T_cell_scanner.translation_mm;
  char text[1024];
  std::snprintf(text, sizeof text,
                "camera: fx %.3f fy %.3f cx %.3f cy %.3f k1 %.5f\n"
                "laser (camera frame): normal (%.6f, %.6f, %.6f) offset %.4f mm\n"
                "belt: roll %.4f deg, camera %.4f mm above the belt\n"
                "encoder: %.6f mm per tick\n"
                "laser sheet pitch: %.4f deg\n"
                "T_cell_scanner translation (%.3f, %.3f, %.3f) mm\n",
                c.fx_px, c.fy_px, c.cx_px, c.cy_px, c.k1, p.normal_x, p.normal_y, p.normal_z,
                p.offset_mm, truth.roll_deg, truth.camera_height_mm, truth.encoder_mm_per_tick,
                truth.sheet_pitch_deg, t.x(), t.y(), t.z());
  out << text;
  if (!out) throw InputError(file.string() + ": cannot write");
}

void run_simulate(const SimulateOptions& options) {
  const CellConfig config = load_cell_config(options.config);
  CalibrationTargetSimulator simulator(config.scanner, config.sim_source.truth, options.seed);
  const fs::path out = options.out;
  const CalibrationBoard board;
  fs::create_directories(out / "camera");
  const std::vector<BoardImage> boards = simulator.board_images(board, options.camera_views);
  for (std::size_t i = 0; i < boards.size(); ++i)
    cv::imwrite((out / "camera" / numbered("board", i)).string(), boards[i].image);
  fs::create_directories(out / "laser");
  const std::vector<LaserImagePair> pairs = simulator.laser_views(board, options.laser_views);
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    cv::imwrite((out / "laser" / numbered("board", i)).string(), pairs[i].board_image);
    cv::imwrite((out / "laser" / numbered("stripe", i)).string(), pairs[i].stripe_image);
  }
  const RampBlock block;
  write_frame_list(out / "belt", simulator.empty_belt_frames(4));
  write_frame_list(out / "block", simulator.ramp_frames(block, 20));
  write_frame_list(out / "block-turned",
                   simulator.ramp_frames(block, 20, RampPlacement::kHighEndUpstream));
  write_ramp_target(out / "ramp.yaml", block);
  const SpherePlateScan plate = simulator.sphere_plate_scan(16);
  write_frame_list(out / "spheres", plate.frames);
  write_sphere_target(out / "spheres.yaml", plate.plate);
  write_truth(out / "truth.txt", simulator.truth());
  std::printf("calibrate simulate: targets of %s rendered into %s\n", options.config.c_str(),
              options.out.c_str());
}

void run_truth(const SimulateOptions& options) {
  if (options.hardware.empty()) throw InputError("calibrate truth: --hardware FILE is required");
  const CellConfig config = load_cell_config(options.config);
  const CalibrationTruth truth =
      CalibrationTargetSimulator(config.scanner, config.sim_source.truth, options.seed).truth();
  ScannerCalibration calibration;
  calibration.camera = truth.camera;
  calibration.laser = truth.laser;
  calibration.mount = {true, truth.T_scanner_camera};
  ProfileSampling sampling =
      profile_sampling_for(config.scanner, config.conditioning, truth.encoder_mm_per_tick);
  sampling.conditioning.sheet_pitch_deg = truth.sheet_pitch_deg;
  update_yaml_file(options.hardware, {{"calibration", yaml_of(calibration)}});
  update_yaml_file(options.config,
                   {{"scanner.encoder_mm_per_tick", YAML::Node(truth.encoder_mm_per_tick)},
                    {"scanner.field_of_view_mm", YAML::Node(sampling.field_of_view_mm)},
                    {"conditioning", yaml_of(sampling.conditioning)},
                    {"cell.T_cell_scanner", yaml_of_transform(truth.T_cell_scanner)}});
  std::printf("calibrate truth: the simulated cell's true calibration written to %s and %s\n",
              options.hardware.c_str(), options.config.c_str());
}

void install(CLI::App& root) {
  CLI::App* calibrate = root.get_subcommand("calibrate");
  auto options = std::make_shared<SimulateOptions>();
  CLI::App* simulate = calibrate->add_subcommand(
      "simulate", "Render the simulated cell's calibration targets through its true geometry");
  simulate->add_option("--config", options->config, "cell config (sim_source.truth:)")
      ->capture_default_str();
  simulate->add_option("--out", options->out, "output directory")->capture_default_str();
  simulate->add_option("--seed", options->seed, "noise and board poses")->capture_default_str();
  simulate->callback([options] { run_simulate(*options); });

  CLI::App* truth = calibrate->add_subcommand(
      "truth", "Write the simulated cell's true calibration (the perfectly calibrated cell)");
  truth->add_option("--config", options->config, "cell config to update")->capture_default_str();
  truth->add_option("--hardware", options->hardware, "hardware YAML to update")->required();
  truth->callback([options] { run_truth(*options); });
}

// Registered after "calibrate" (the registry installs in name order), which it extends.
const CommandRegistration registration("calibrate_simulate", install);

}  // namespace
}  // namespace cosmos::cli
