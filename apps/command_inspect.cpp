// cosmos inspect RANGE --out DIR: the COSMOS representation of one range image (chapter 3),
// written as cosmos.json and five pictures for a person to look at.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <system_error>

#include "apps/command_registry.hpp"
#include "apps/option_range.hpp"
#include "core/input_error.hpp"
#include "core/io/cosmos_json.hpp"
#include "core/io/range_image_file.hpp"
#include "core/render/view_pictures.hpp"
#include "core/representation/cosmos_pipeline.hpp"

namespace cosmos::cli {
namespace {

struct InspectOptions {
  std::filesystem::path range_path;
  std::filesystem::path out_dir;
  CosmosParameters cosmos;  // the defaults, with the options' overrides
};

std::size_t fitted_pixels(const ViewAnalysis& analysis) {
  std::size_t count = 0;
  for (SurfaceLabel label : analysis.field.label.values())
    count += label != SurfaceLabel::kInvalid ? 1 : 0;
  return count;
}

void run_inspect(const InspectOptions& options) {
  const auto start = std::chrono::steady_clock::now();

  const RangeImage image = read_range_image(options.range_path);
  const std::size_t data_pixels = image.count_valid();
  if (data_pixels == 0)
    throw InputError(options.range_path.string() + ": no pixel has data (all NaN)");

  const CosmosParameters& parameters = options.cosmos;
  const ViewAnalysis analysis = analyze_view(image, parameters);
  if (fitted_pixels(analysis) == 0) {
    throw InputError(options.range_path.string() +
                     ": no local surface fit succeeded on any of the " +
                     std::to_string(data_pixels) + " pixels with data (too sparse for a " +
                     std::to_string(parameters.fit.window_size) + "x" +
                     std::to_string(parameters.fit.window_size) + " window?)");
  }

  std::error_code error;
  std::filesystem::create_directories(options.out_dir, error);
  if (error)
    throw InputError("--out " + options.out_dir.string() + ": cannot create directory (" +
                     error.message() + ")");
  write_cosmos_json(analysis, options.out_dir / "cosmos.json");
  write_view_pictures(image, analysis, options.out_dir);

  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("inspect: %zu valid pixels, %zu patches, %.2f s -> %s\n", analysis.valid_pixels,
              analysis.view.patches.size(), seconds, options.out_dir.string().c_str());
}

void install_inspect(CLI::App& root) {
  auto options = std::make_shared<InspectOptions>();
  CLI::App* command = root.add_subcommand(
      "inspect", "Compute the COSMOS of one range image; write cosmos.json and pictures");
  command
      ->add_option("RANGE", options->range_path,
                   "range image (float32 TIFF or PFM, mm) with its <stem>.yaml")
      ->type_name("FILE")
      ->required();
  command->add_option("--out", options->out_dir, "output directory (created if missing)")
      ->type_name("DIR")
      ->required();
  command
      ->add_option("--smoothing-iterations", options->cosmos.smoothing.iterations,
                   "curvature-consistency iterations (cosmos.smoothing.iterations)")
      ->type_name("N")
      ->check(declared_range<CosmosParameters, int>(
          "cosmos", [](CosmosParameters& p, int n) { p.smoothing.iterations = n; }))
      ->capture_default_str();
  command
      ->add_option("--max-patches", options->cosmos.segmentation.max_patches,
                   "adaptive CSMP budget, §5.4.3 (0 = fixed shape-diameter limit)")
      ->type_name("N")
      ->check(declared_range<CosmosParameters, int>(
          "cosmos", [](CosmosParameters& p, int n) { p.segmentation.max_patches = n; }))
      ->capture_default_str();
  command->callback([options] { run_inspect(*options); });
}

const CommandRegistration registration{"inspect", install_inspect};

}  // namespace
}  // namespace cosmos::cli
