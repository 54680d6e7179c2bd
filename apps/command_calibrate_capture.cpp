// `cosmos calibrate capture board|pair|frames`: the frames a calibration reads, taken from the
// cell's own camera and encoder through the hardware source's devices (a real V4L2 camera and
// libgpiod lines, or the simulated twins of config/hardware-sim.yaml):
//   board   one board image with the laser off, as the next free DIR/board-NN.png (the camera
//           calibration's input; move the board and run again, ten times or more);
//   pair    board-NN.png with the laser off, then stripe-NN.png with it on, the board unmoved
//           (the laser-plane calibration's input, one pair per height or tilt);
//   frames  --frames N stripe frames with the laser on, one each --every-mm of belt, with
//           DIR/frames.csv (file, encoder count, ROI top): the empty belt, the ramp block or
//           the sphere plate carried past the scanner (the belt and cell calibrations).
// Nothing is written unless every frame was taken.
#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <opencv2/imgcodecs.hpp>
#include <string>

#include "apps/cell_world.hpp"
#include "apps/command_registry.hpp"
#include "calibration/frame_capture.hpp"
#include "calibration/frame_list.hpp"
#include "core/input_error.hpp"
#include "realtime/config/cell_config.hpp"
#include "realtime/config/hardware_config.hpp"

namespace cosmos::cli {
namespace {

namespace fs = std::filesystem;

struct CaptureOptions {
  std::string hardware = "config/hardware-sim.yaml";
  std::string config = "config/cell.yaml";
  std::string out;
  int frames = 100;
  double every_mm = 0;
  int settle_frames = 2;
};

// The cell's hardware source, started: its devices are what the capture reads.
class StartedHardware {
 public:
  explicit StartedHardware(const CaptureOptions& options)
      : config_(load_cell_config(options.config)), world_(config_) {
    CellSourceChoice choice;
    choice.source = "hardware";
    choice.hardware = options.hardware;
    source_ = &world_.open_source(choice);
    if (source_->start() != SourceStatus::kOk) throw InputError(std::string(source_->last_error()));
    hardware_ = world_.hardware_source();
    device_ = read_hardware_config(options.hardware).camera.device;
  }
  ~StartedHardware() { source_->stop(); }
  StartedHardware(const StartedHardware&) = delete;
  StartedHardware& operator=(const StartedHardware&) = delete;

  std::vector<StripeFrame> capture(FrameCaptureSettings settings) {
    settings.device = device_;
    return capture_frames(hardware_->camera(), hardware_->gpio(), settings);
  }
  const CellConfig& config() const { return config_; }

 private:
  CellConfig config_;
  CellWorld world_;
  ScannerSource* source_ = nullptr;
  HardwareSource* hardware_ = nullptr;
  std::string device_;
};

// The first NN with neither DIR/board-NN.png nor DIR/stripe-NN.png.
int next_free_index(const fs::path& directory) {
  for (int index = 0;; ++index) {
    char board[32], stripe[32];
    std::snprintf(board, sizeof board, "board-%02d.png", index);
    std::snprintf(stripe, sizeof stripe, "stripe-%02d.png", index);
    if (!fs::exists(directory / board) && !fs::exists(directory / stripe)) return index;
  }
}

fs::path numbered(const fs::path& directory, const char* prefix, int index) {
  char name[32];
  std::snprintf(name, sizeof name, "%s-%02d.png", prefix, index);
  return directory / name;
}

void write_image(const fs::path& file, const StripeFrame& frame) {
  if (!cv::imwrite(file.string(), frame.image)) throw InputError(file.string() + ": cannot write");
  std::printf("capture: %s (%dx%d, encoder %lld)\n", file.string().c_str(), frame.image.cols,
              frame.image.rows, static_cast<long long>(frame.encoder_ticks));
}

fs::path output_directory(const CaptureOptions& options) {
  const fs::path out(options.out);
  std::error_code error;
  fs::create_directories(out, error);
  if (error) throw InputError(out.string() + ": cannot create: " + error.message());
  return out;
}

void run_board(const CaptureOptions& options, bool with_stripe) {
  StartedHardware hardware(options);
  FrameCaptureSettings settings;
  settings.settle_frames = options.settle_frames;
  settings.laser_on = false;
  const StripeFrame board = hardware.capture(settings).front();
  StripeFrame stripe;
  if (with_stripe) {
    settings.laser_on = true;
    stripe = hardware.capture(settings).front();
  }
  const fs::path out = output_directory(options);
  const int index = next_free_index(out);
  write_image(numbered(out, "board", index), board);
  if (with_stripe) write_image(numbered(out, "stripe", index), stripe);
}

void run_frames(const CaptureOptions& options) {
  StartedHardware hardware(options);
  FrameCaptureSettings settings;
  settings.frames = options.frames;
  settings.laser_on = true;
  settings.settle_frames = options.settle_frames;
  const double mm_per_tick = hardware.config().scanner.encoder_mm_per_tick;
  settings.every_ticks = static_cast<std::int64_t>(std::llround(options.every_mm / mm_per_tick));
  const std::vector<StripeFrame> frames = hardware.capture(settings);
  const fs::path out = output_directory(options);
  if (fs::exists(out / "frames.csv"))
    throw InputError((out / "frames.csv").string() +
                     ": already there (a frame directory holds one capture; nothing written)");
  write_frame_list(out, frames);
  std::printf("capture: %zu frames in %s, encoder %lld to %lld\n", frames.size(),
              out.string().c_str(), static_cast<long long>(frames.front().encoder_ticks),
              static_cast<long long>(frames.back().encoder_ticks));
}

void install(CLI::App& root) {
  CLI::App* calibrate = root.get_subcommand("calibrate");
  auto options = std::make_shared<CaptureOptions>();
  CLI::App* capture = calibrate->add_subcommand(
      "capture", "Take calibration frames from the cell's camera and encoder");
  capture->require_subcommand(1);
  const auto common = [&](CLI::App* command) {
    command->add_option("--hardware", options->hardware, "hardware YAML (the devices)")
        ->capture_default_str();
    command->add_option("--config", options->config, "cell config (the scanner: section)")
        ->capture_default_str();
    command->add_option("--out", options->out, "directory the frames go to")->required();
    command
        ->add_option("--settle-frames", options->settle_frames,
                     "frames dropped after the laser switched")
        ->capture_default_str()
        ->check(CLI::Range(0, 100));
  };
  CLI::App* board =
      capture->add_subcommand("board", "One board image, laser off (as board-NN.png)");
  common(board);
  board->callback([options] { run_board(*options, false); });
  CLI::App* pair = capture->add_subcommand(
      "pair", "A board image (laser off) and a stripe image (laser on), board unmoved");
  common(pair);
  pair->callback([options] { run_board(*options, true); });
  CLI::App* frames =
      capture->add_subcommand("frames", "Stripe frames of the moving belt, with frames.csv");
  common(frames);
  frames->add_option("--frames", options->frames, "frames to take")
      ->capture_default_str()
      ->check(CLI::Range(1, 100000));
  frames->add_option("--every-mm", options->every_mm, "belt travel between frames, mm (0: every)")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1000.0));
  frames->callback([options] { run_frames(*options); });
}

const CommandRegistration registration("calibrate_capture", install);

}  // namespace
}  // namespace cosmos::cli
