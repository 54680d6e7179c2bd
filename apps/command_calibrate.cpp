// `cosmos calibrate camera|laser|belt|cell`: the calibration of a real scanner cell, step by
// step (docs/calibration.md). Each step reads recorded frames (image files, or frame
// directories with frames.csv: calibration/frame_list.hpp), measures, and writes its section
// of the hardware YAML (`calibration:`) or the cell config (`scanner.encoder_mm_per_tick`,
// `conditioning:`, `cell.T_cell_scanner`), plus report.txt and pictures in --report. Any
// refusal (no board in an image, too few views, a target file that does not match the scan)
// is one line naming the input and the reason, and nothing is written.
//
// The simulated cell's side lives in command_calibrate_simulate.cpp (`calibrate simulate`,
// `calibrate truth`) and command_calibrate_check.cpp (`calibrate check`).
#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>
#include <string>

#include "apps/command_registry.hpp"
#include "calibration/belt_calibration.hpp"
#include "calibration/board_detection.hpp"
#include "calibration/calibration_report.hpp"
#include "calibration/camera_calibration.hpp"
#include "calibration/cell_frame_calibration.hpp"
#include "calibration/frame_list.hpp"
#include "calibration/laser_plane_calibration.hpp"
#include "calibration/stripe_points.hpp"
#include "calibration/target_file.hpp"
#include "calibration/yaml_update.hpp"
#include "core/input_error.hpp"
#include "realtime/config/cell_config.hpp"
#include "realtime/config/hardware_config.hpp"

namespace cosmos::cli {
namespace {

namespace fs = std::filesystem;

struct CalibrateOptions {
  std::string hardware = "config/hardware-sim.yaml";
  std::string config = "config/cell.yaml";
  std::string report = "calibration-report";
  std::string input;         // images, views, belt or scan directory
  std::string block;         // belt: the ramp block's frames
  std::string block_turned;  // belt: the same block turned round (the sheet's pitch)
  std::string target;        // belt: ramp.yaml; cell: spheres.yaml
  CalibrationBoard board;
};

std::string text(const char* format, double a, double b = 0, double c = 0, double d = 0) {
  char line[256];
  std::snprintf(line, sizeof line, format, a, b, c, d);
  return line;
}

void refuse_unless(bool ok, const std::string& input, const std::string& reason) {
  if (!ok) throw InputError(input + ": " + reason + " (nothing written)");
}

void run_camera(const CalibrateOptions& options) {
  CalibrationReport report(options.report);
  std::vector<std::vector<cv::Point2f>> corners;
  cv::Size image_size;
  std::vector<cv::Mat> shown;
  for (const fs::path& file : png_files(options.input)) {
    const cv::Mat image = read_grey_image(file);
    const BoardDetection detection = detect_board(image, options.board);
    refuse_unless(detection.found, file.string(), detection.reason);
    if (corners.size() < 2)
      report.picture("corners-" + file.stem().string(),
                     corners_picture(image, detection.corners, options.board.pattern_size()));
    corners.push_back(detection.corners);
    image_size = image.size();
  }
  const CameraCalibrationResult result = calibrate_camera(corners, options.board, image_size);
  refuse_unless(result.ok, options.input, result.reason);
  const CalibratedCamera& c = result.camera;
  report.line("cosmos calibrate camera: " + std::to_string(corners.size()) + " views of " +
              options.input);
  report.line(
      text("fx %.3f px, fy %.3f px, cx %.3f px, cy %.3f px", c.fx_px, c.fy_px, c.cx_px, c.cy_px));
  report.line(text("k1 %.6f, k2 %.6f; RMS reprojection %.4f px", c.k1, c.k2, result.rms_px));
  for (std::size_t v = 0; v < result.view_rms_px.size(); ++v)
    report.line(text("view %.0f: RMS %.4f px", static_cast<double>(v + 1), result.view_rms_px[v]));
  report.picture("camera-residuals",
                 bars_picture("reprojection RMS per view", "px", result.view_rms_px));
  update_yaml_file(options.hardware, {{"calibration.camera", yaml_of(c)}});
  report.write();
  std::fputs(report.text().c_str(), stdout);
}

void run_laser(const CalibrateOptions& options) {
  const HardwareConfig hardware = read_hardware_config(options.hardware);
  refuse_unless(hardware.calibration.camera.calibrated, options.hardware,
                "calibration.camera is not calibrated: run `cosmos calibrate camera` first");
  CalibrationReport report(options.report);
  std::vector<LaserView> views;
  for (const fs::path& file : png_files(options.input)) {
    const std::string name = file.filename().string();
    if (name.rfind("board-", 0) != 0) continue;
    const fs::path stripe_file = file.parent_path() / ("stripe-" + name.substr(6));
    const cv::Mat board_image = read_grey_image(file);
    const cv::Mat stripe_image = read_grey_image(stripe_file);
    const BoardDetection detection = detect_board(board_image, options.board);
    refuse_unless(detection.found, file.string(), detection.reason);
    LaserView view{detection.corners, stripe_image_points(stripe_image, 0, hardware.stripe)};
    if (views.empty())
      report.picture("laser-stripe", points_picture(stripe_image, view.stripe_points));
    views.push_back(std::move(view));
  }
  const LaserPlaneResult result =
      calibrate_laser_plane(views, options.board, hardware.calibration.camera);
  refuse_unless(result.ok, options.input, result.reason);
  const CalibratedLaserPlane& p = result.plane;
  report.line("cosmos calibrate laser: " + std::to_string(views.size()) + " views of " +
              options.input);
  report.line(text("normal (%.6f, %.6f, %.6f) in the camera frame, offset %.4f mm", p.normal_x,
                   p.normal_y, p.normal_z, p.offset_mm));
  report.line(text("RMS point-to-plane %.4f mm over %.0f inliers", result.rms_mm, result.inliers));
  for (std::size_t v = 0; v < result.view_rms_mm.size(); ++v)
    report.line(text("view %.0f: RMS %.4f mm", static_cast<double>(v + 1), result.view_rms_mm[v]));
  report.picture("laser-residuals", bars_picture("stripe points off the plane, RMS per view", "mm",
                                                 result.view_rms_mm));
  update_yaml_file(options.hardware, {{"calibration.laser", yaml_of(p)}});
  report.write();
  std::fputs(report.text().c_str(), stdout);
}

void run_belt(const CalibrateOptions& options) {
  const HardwareConfig hardware = read_hardware_config(options.hardware);
  refuse_unless(hardware.calibration.camera.calibrated && hardware.calibration.laser.calibrated,
                options.hardware,
                "calibration.camera and calibration.laser must be calibrated first");
  const CellConfig config = load_cell_config(options.config);
  const RampBlock block = read_ramp_target(options.target);
  const BeltCalibrationResult result =
      calibrate_belt(read_frame_list(options.input), read_frame_list(options.block),
                     options.block_turned.empty() ? std::vector<StripeFrame>{}
                                                  : read_frame_list(options.block_turned),
                     block, config.scanner, hardware.calibration, hardware.stripe);
  refuse_unless(result.ok, options.block, result.reason);
  const ProfileSampling sampling =
      profile_sampling_for(config.scanner, config.conditioning, result.encoder_mm_per_tick);
  ConditioningParameters conditioning = sampling.conditioning;
  conditioning.belt_height_mm = result.belt_height_mm;
  conditioning.belt_slope_x = result.belt_slope_x;
  conditioning.sheet_pitch_deg = result.sheet_pitch_deg;
  CalibrationReport report(options.report);
  report.line("cosmos calibrate belt: empty belt " + options.input + ", ramp block " +
              options.block +
              (options.block_turned.empty() ? "" : ", turned round " + options.block_turned));
  report.line(text("roll %.4f deg, camera %.4f mm above the belt", result.roll_deg,
                   result.camera_height_mm));
  report.line(text("belt plane in the new frame: z = %.4f mm + %.6f x, RMS %.4f mm",
                   result.belt_height_mm, result.belt_slope_x, result.belt_rms_mm));
  report.line(
      text("encoder %.6f mm per tick (ramp line RMS %.4f mm over %.0f frames); grid %.6f mm",
           result.encoder_mm_per_tick, result.ramp.rms_mm,
           static_cast<double>(result.ramp.ticks_height.size()), conditioning.grid_mm));
  report.line(result.pitch_measured
                  ? text("laser sheet pitch %.4f deg (turned ramp line RMS %.4f mm over %.0f "
                         "frames)",
                         result.sheet_pitch_deg, result.ramp_turned.rms_mm,
                         static_cast<double>(result.ramp_turned.ticks_height.size()))
                  : std::string("laser sheet pitch not measured (no --block-turned scan): "
                                "taken as 0"));
  std::vector<Eigen::Vector2d> belt_xz;
  for (const Eigen::Vector3d& p : result.belt_points_scanner) belt_xz.emplace_back(p.x(), p.z());
  report.picture("belt-profile",
                 plot_picture("empty belt in the calibrated frame", "x mm", "z mm", {{belt_xz}}));
  report.picture(
      "belt-ramp",
      plot_picture("ramp block height per frame (both ways round)", "encoder ticks", "height mm",
                   {{result.ramp.ticks_height}, {result.ramp_turned.ticks_height}}));
  update_yaml_file(options.hardware, {{"calibration.mount", yaml_of(result.mount)}});
  update_yaml_file(options.config,
                   {{"scanner.encoder_mm_per_tick", YAML::Node(result.encoder_mm_per_tick)},
                    {"scanner.field_of_view_mm", YAML::Node(sampling.field_of_view_mm)},
                    {"conditioning", yaml_of(conditioning)}});
  report.write();
  std::fputs(report.text().c_str(), stdout);
}

void run_cell(const CalibrateOptions& options) {
  const HardwareConfig hardware = read_hardware_config(options.hardware);
  refuse_unless(hardware.calibration.mount.calibrated, options.hardware,
                "calibration.mount is not calibrated: run `cosmos calibrate belt` first");
  const CellConfig config = load_cell_config(options.config);
  const SpherePlate plate = read_sphere_target(options.target);
  const CellFrameResult result = calibrate_cell_frame(
      read_frame_list(options.input), plate,
      calibrated_triangulation_geometry(config.scanner, hardware.calibration),
      config.scanner.encoder_mm_per_tick, config.conditioning.sheet_pitch_deg, hardware.stripe);
  refuse_unless(result.ok, options.target, result.reason);
  CalibrationReport report(options.report);
  report.line("cosmos calibrate cell: " + std::to_string(plate.centres_cell_mm.size()) +
              " spheres of " + options.target + " in " + options.input);
  const Eigen::Vector3d& t = result.T_cell_scanner.translation_mm;
  report.line(text("T_cell_scanner translation (%.3f, %.3f, %.3f) mm, RMS %.4f mm", t.x(), t.y(),
                   t.z(), result.rms_mm));
  for (std::size_t k = 0; k < result.feature_residual_mm.size(); ++k)
    report.line(text("sphere %.0f: residual %.4f mm (sphere fit RMS %.4f mm)",
                     static_cast<double>(k + 1), result.feature_residual_mm[k],
                     result.sphere_rms_mm[k]));
  std::vector<Eigen::Vector2d> top_view;
  for (const Eigen::Vector3d& p : result.points_belt) top_view.emplace_back(p.x(), p.y());
  report.picture("cell-spheres", plot_picture("sphere caps seen (belt frame, top view)", "x mm",
                                              "y mm", {{top_view}}));
  report.picture("cell-residuals",
                 bars_picture("residual per sphere", "mm", result.feature_residual_mm));
  update_yaml_file(options.config,
                   {{"cell.T_cell_scanner", yaml_of_transform(result.T_cell_scanner)}});
  report.write();
  std::fputs(report.text().c_str(), stdout);
}

void add_board_options(CLI::App* command, CalibrateOptions& options) {
  command->add_option("--board-columns", options.board.inner_columns, "inner corners across")
      ->capture_default_str();
  command->add_option("--board-rows", options.board.inner_rows, "inner corners down")
      ->capture_default_str();
  command->add_option("--square-mm", options.board.square_mm, "chessboard square, mm")
      ->capture_default_str();
}

void install(CLI::App& root) {
  auto options = std::make_shared<CalibrateOptions>();
  CLI::App* calibrate = root.add_subcommand(
      "calibrate", "Calibrate the cell: camera, laser plane, belt and encoder, cell frame");
  calibrate->require_subcommand(1);
  const auto common = [&](CLI::App* command) {
    command->add_option("--hardware", options->hardware, "hardware YAML (calibration: section)")
        ->capture_default_str();
    command->add_option("--report", options->report, "report directory")->capture_default_str();
  };
  CLI::App* camera = calibrate->add_subcommand("camera", "Lens intrinsics from board images");
  camera->add_option("--images", options->input, "directory of board images (.png)")->required();
  common(camera);
  add_board_options(camera, *options);
  camera->callback([options] { run_camera(*options); });

  CLI::App* laser =
      calibrate->add_subcommand("laser", "The laser plane from board + stripe images");
  laser->add_option("--views", options->input, "directory of board-NN.png and stripe-NN.png")
      ->required();
  common(laser);
  add_board_options(laser, *options);
  laser->callback([options] { run_laser(*options); });

  CLI::App* belt = calibrate->add_subcommand("belt", "Scanner frame and encoder from the belt");
  belt->add_option("--belt", options->input, "frame directory of the empty belt")->required();
  belt->add_option("--block", options->block, "frame directory of the ramp block")->required();
  belt->add_option("--block-turned", options->block_turned,
                   "frame directory of the ramp block turned round (measures the sheet's pitch)");
  belt->add_option("--target", options->target, "the ramp block's target file")->required();
  belt->add_option("--config", options->config, "cell config to update")->capture_default_str();
  common(belt);
  belt->callback([options] { run_belt(*options); });

  CLI::App* cell = calibrate->add_subcommand("cell", "T_cell_scanner from the sphere plate");
  cell->add_option("--scan", options->input, "frame directory of the sphere plate")->required();
  cell->add_option("--target", options->target, "the sphere plate's target file")->required();
  cell->add_option("--config", options->config, "cell config to update")->capture_default_str();
  common(cell);
  cell->callback([options] { run_cell(*options); });
}

const CommandRegistration registration("calibrate", install);

}  // namespace
}  // namespace cosmos::cli
