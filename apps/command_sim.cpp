// `cosmos sim scan` and `cosmos sim views`: the simulated laser-line scanner on a catalog part
// or a mesh file (sim/simulated_scanner.hpp, sim/model_views.hpp).
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "apps/command_registry.hpp"
#include "apps/option_range.hpp"
#include "apps/sim_frame_dump.hpp"
#include "core/input_error.hpp"
#include "core/io/range_image_file.hpp"
#include "realtime/config/cell_config.hpp"
#include "scanner/scanner_config.hpp"
#include "sim/mesh.hpp"
#include "sim/model_views.hpp"
#include "sim/part_catalog.hpp"
#include "sim/part_pose.hpp"
#include "sim/part_scan.hpp"
#include "sim/seeded_random.hpp"

namespace cosmos::cli {
namespace {

namespace fs = std::filesystem;

// Numbers are taken as text and converted here: CLI11's own conversion failures print a
// two-line report, and the CLI contract is one line naming the option.
struct SimOptions {
  std::string part;
  std::string catalog;
  std::string mesh;
  std::string size_mm;
  std::vector<std::string> rotation_deg;
  bool random_pose = false;
  bool resting = false;
  std::string seed = "1";
  std::string noise_mm;
  std::string mode = "profile";
  std::string frames;
  std::string config;
  std::string out;
  std::string count = "320";
};

[[noreturn]] void fail(const std::string& command, const std::string& reason) {
  throw InputError("sim " + command + ": " + reason);
}

template <class Number>
Number parse_number(const std::string& command, const char* option, const std::string& text,
                    const char* expected) {
  Number value{};
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, value);
  if (text.empty() || error != std::errc() || stop != end) {
    fail(command, std::string(option) + " '" + text + "': expected " + expected);
  }
  if constexpr (std::is_floating_point_v<Number>) {
    if (!std::isfinite(value))
      fail(command, std::string(option) + " '" + text + "': must be finite");
  }
  return value;
}

struct LoadedPart {
  std::string name;
  TriangleMesh mesh;
};

LoadedPart load_part(const std::string& command, const SimOptions& options) {
  if (!options.part.empty() && !options.mesh.empty())
    fail(command, "give either --part or --mesh, not both");
  if (!options.mesh.empty()) {
    if (options.size_mm.empty())
      fail(command, "--mesh needs --size-mm (the part's largest extent)");
    const double size_mm =
        parse_number<double>(command, "--size-mm", options.size_mm, "a number (mm)");
    return {fs::path(options.mesh).stem().string(), load_mesh(options.mesh, size_mm)};
  }
  if (options.part.empty()) fail(command, "missing --part NAME or --mesh PATH --size-mm S");
  if (!options.size_mm.empty())
    fail(command, "--size-mm goes with --mesh; a catalog part has its own size");
  const PartCatalog catalog = read_part_catalog(find_part_catalog(options.catalog));
  const PartEntry& entry = catalog.at(options.part);
  return {entry.name, load_mesh(entry.mesh_path, entry.size_mm)};
}

// The scanner and the conditioning of a cell (--config, else the defaults): range images lose
// the belt at the cell's threshold, as its model views and live scans do.
struct SimScanSetup {
  ScannerParameters scanner;
  ConditioningParameters conditioning;
};

SimScanSetup scan_setup(const std::string& command, const SimOptions& options, std::uint64_t seed) {
  SimScanSetup setup;
  if (!options.config.empty()) {
    const CellConfig config = load_cell_config(options.config);
    setup.scanner = config.scanner;
    setup.conditioning = config.conditioning;
  }
  ScannerParameters& parameters = setup.scanner;
  parameters.seed = seed;
  if (!options.noise_mm.empty()) {
    parameters.z_noise_mm =
        parse_number<double>(command, "--noise-mm", options.noise_mm, "a number (mm)");
    if (parameters.z_noise_mm < 0.0)
      fail(command, "--noise-mm '" + options.noise_mm + "': must be >= 0");
  }
  try {
    check_scanner_parameters(parameters);
  } catch (const std::invalid_argument& error) {
    fail(command, error.what());
  }
  return setup;
}

void check_output_image(const std::string& command, const fs::path& out) {
  if (out.empty()) fail(command, "missing --out FILE (.tif, .tiff or .pfm)");
  const std::string extension = out.extension().string();
  if (extension != ".tif" && extension != ".tiff" && extension != ".pfm") {
    fail(command, out.string() + ": unknown range image extension '" + extension +
                      "' (expected .tif, .tiff or .pfm)");
  }
  const fs::path parent = out.has_parent_path() ? out.parent_path() : fs::path(".");
  std::error_code error;
  if (!fs::is_directory(parent, error))
    fail(command, out.string() + ": no directory " + parent.string());
}

Eigen::Matrix3d part_rotation(const SimOptions& options, const TriangleMesh& mesh,
                              std::uint64_t seed) {
  const int modes = (options.rotation_deg.empty() ? 0 : 1) + (options.random_pose ? 1 : 0) +
                    (options.resting ? 1 : 0);
  if (modes > 1) fail("scan", "give one of --rotation-deg, --random-pose, --resting");
  const std::uint64_t pose_seed = mix_seed(seed, 0x9053);
  if (options.random_pose) return random_rotation(pose_seed);
  if (options.resting) return resting_rotation(mesh, pose_seed);
  if (options.rotation_deg.empty()) return Eigen::Matrix3d::Identity();
  if (options.rotation_deg.size() != 3)
    fail("scan", "--rotation-deg takes three angles: rx ry rz (degrees)");
  double angle[3];
  for (int k = 0; k < 3; ++k) {
    angle[k] = parse_number<double>("scan", "--rotation-deg",
                                    options.rotation_deg[static_cast<std::size_t>(k)],
                                    "a number (degrees)");
  }
  return rotation_from_xyz_deg(angle[0], angle[1], angle[2]);
}

void run_scan(const SimOptions& options) {
  check_output_image("scan", options.out);
  if (options.mode != "profile" && options.mode != "camera") {
    fail("scan", "--mode '" + options.mode + "': expected profile or camera");
  }
  const ScanMode mode = options.mode == "camera" ? ScanMode::kCamera : ScanMode::kProfile;
  if (!options.frames.empty() && mode != ScanMode::kCamera)
    fail("scan", "--frames needs --mode camera");
  const auto seed =
      parse_number<std::uint64_t>("scan", "--seed", options.seed, "a non-negative integer");
  const SimScanSetup setup = scan_setup("scan", options, seed);
  const ScannerParameters& parameters = setup.scanner;
  const LoadedPart part = load_part("scan", options);
  const Eigen::Matrix3d R_belt_part = part_rotation(options, part.mesh, seed);

  std::unique_ptr<FrameDump> frames;
  if (!options.frames.empty()) {
    frames =
        std::make_unique<FrameDump>(options.frames, (1 << parameters.camera.bit_depth) - 1,
                                    scanner_triangulation_geometry(parameters).roi_row_offset_px);
  }
  ProfileObserver observer;
  if (frames) {
    observer = [&frames](std::int64_t, const Profile& profile, const SimulatedScanner& scanner) {
      frames->write(profile.seq, scanner.last_frame(), scanner.last_peaks());
    };
  }
  const RangeImage image = scan_single_part(part.mesh, part.name, R_belt_part, parameters,
                                            setup.conditioning, mode, observer);
  if (image.width() == 0) {
    fail("scan",
         "the scanner measured nothing of '" + part.name + "' (out of the measuring range?)");
  }
  write_range_image(image, options.out);
  std::printf("sim scan: %s, %s mode, %d x %d pixels (%zu with data) -> %s + %s\n",
              part.name.c_str(), options.mode.c_str(), image.width(), image.height(),
              image.count_valid(), options.out.c_str(), sidecar_path(options.out).string().c_str());
  if (frames)
    std::printf("sim scan: %d camera frames -> %s\n", frames->count(), options.frames.c_str());
}

void write_view_yaml(const fs::path& path, const ModelView& view, const std::string& part) {
  std::FILE* file = std::fopen(path.string().c_str(), "w");
  if (file == nullptr) fail("views", path.string() + ": cannot be written");
  const Eigen::Matrix3d& R = view.T_scanner_part.linear();
  const Eigen::Vector3d& t = view.T_scanner_part.translation();
  std::fprintf(file, "part: %s\nview_index: %d\ndirection_part: [%.17g, %.17g, %.17g]\n",
               part.c_str(), view.index, view.direction_part.x(), view.direction_part.y(),
               view.direction_part.z());
  std::fprintf(file, "rotation: [%.17g, %.17g, %.17g, %.17g, %.17g, %.17g, %.17g, %.17g, %.17g]\n",
               R(0, 0), R(0, 1), R(0, 2), R(1, 0), R(1, 1), R(1, 2), R(2, 0), R(2, 1), R(2, 2));
  std::fprintf(file, "translation_mm: [%.17g, %.17g, %.17g]\nmeasured_pixels: %zu\n", t.x(), t.y(),
               t.z(), view.image.width() > 0 ? view.image.count_valid() : std::size_t{0});
  if (std::fclose(file) != 0) fail("views", path.string() + ": cannot be written");
}

void run_views(const SimOptions& options) {
  if (options.out.empty()) fail("views", "missing --out DIR");
  const auto seed =
      parse_number<std::uint64_t>("views", "--seed", options.seed, "a non-negative integer");
  const int count = parse_number<int>("views", "--count", options.count, "an integer");
  if (count < 1 || count > 320)
    fail("views", "--count '" + options.count + "': must be in [1, 320]");
  const SimScanSetup setup = scan_setup("views", options, seed);
  const LoadedPart part = load_part("views", options);
  const fs::path out = options.out;
  std::error_code error;
  fs::create_directories(out, error);
  if (!fs::is_directory(out, error)) fail("views", out.string() + ": cannot create the directory");

  ModelViewRenderer renderer(part.mesh, part.name, setup.scanner, setup.conditioning);
  int empty = 0;
  for (int index = 0; index < count; ++index) {
    const ModelView view = renderer.scan_view(index);
    char stem[32];
    std::snprintf(stem, sizeof stem, "view_%03d", index);
    if (view.image.width() > 0) {
      write_range_image(view.image, out / (std::string(stem) + ".tiff"));
    } else {
      ++empty;
    }
    write_view_yaml(out / (std::string(stem) + ".view.yaml"), view, part.name);
  }
  std::printf("sim views: %s, %d views (%d measured nothing) -> %s\n", part.name.c_str(), count,
              empty, out.string().c_str());
}

void add_part_options(CLI::App* command, SimOptions& options) {
  command->add_option("--part", options.part, "catalog part name")->type_name("NAME");
  command
      ->add_option("--catalog", options.catalog, "part catalog YAML (default: config/parts.yaml)")
      ->type_name("FILE");
  command->add_option("--seed", options.seed, "seed of pose and noise")
      ->type_name("UINT")
      ->capture_default_str();
  command
      ->add_option("--config", options.config,
                   "cell config whose scanner: and conditioning: sections override the defaults")
      ->type_name("FILE");
}

void install(CLI::App& root) {
  CLI::App* sim = root.add_subcommand("sim", "The simulated laser-line scanner and conveyor");
  sim->require_subcommand(1);

  auto scan_options = std::make_shared<SimOptions>();
  CLI::App* scan =
      sim->add_subcommand("scan", "Scan one part on the belt into a range image with ground truth");
  add_part_options(scan, *scan_options);
  scan->add_option("--mesh", scan_options->mesh,
                   "mesh file (.off, .ply, .stl, .obj) instead of --part")
      ->type_name("PATH");
  // No part larger than the highest camera mount (scanner.camera_height_mm's bound) passes
  // beneath the scanner; 1e9 mm asked the scan for an unbounded range image.
  scan->add_option("--size-mm", scan_options->size_mm, "largest extent of the --mesh part")
      ->type_name("MM")
      ->check(within_range<double>(Range::above(0, 5000)));
  scan->add_option("--rotation-deg", scan_options->rotation_deg,
                   "rotation Rz·Ry·Rx of the part (degrees)")
      ->expected(1, 3)
      ->type_name("RX RY RZ");
  scan->add_flag("--random-pose", scan_options->random_pose,
                 "uniformly random rotation from the seed");
  scan->add_flag("--resting", scan_options->resting,
                 "a stable resting pose on the convex hull, from the seed");
  scan->add_option("--noise-mm", scan_options->noise_mm,
                   "z noise sigma of profile mode (default: config)")
      ->type_name("MM")
      ->check(declared_range<ScannerParameters, double>(
          "scanner", [](ScannerParameters& p, double mm) { p.z_noise_mm = mm; }));
  scan->add_option("--mode", scan_options->mode, "profile (geometry) or camera (rendered frames)")
      ->capture_default_str();
  scan->add_option("--frames", scan_options->frames,
                   "camera mode: save frames with the found stripe as PNG")
      ->type_name("DIR");
  scan->add_option("--out", scan_options->out,
                   "output range image: .tif/.tiff or .pfm (+ <stem>.yaml)")
      ->type_name("FILE");
  scan->callback([scan_options] { run_scan(*scan_options); });

  auto views_options = std::make_shared<SimOptions>();
  CLI::App* views =
      sim->add_subcommand("views", "Scan a part from the view-sphere directions (model views)");
  add_part_options(views, *views_options);
  views->add_option("--count", views_options->count, "number of view directions, the first of 320")
      ->capture_default_str();
  views
      ->add_option("--out", views_options->out,
                   "output directory for view_NNN.tiff (+ .yaml, .view.yaml)")
      ->type_name("DIR");
  views->callback([views_options] { run_views(*views_options); });
}

const CommandRegistration registration("sim", install);

}  // namespace
}  // namespace cosmos::cli
