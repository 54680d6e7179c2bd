// cosmos synth SHAPE --out FILE: an analytic test surface (sim/analytic_surface.hpp) written
// as a range image with its sidecar, ground truth included.
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

#include "apps/command_registry.hpp"
#include "core/input_error.hpp"
#include "core/io/range_image_file.hpp"
#include "sim/analytic_surface.hpp"

namespace cosmos::cli {
namespace {

// Numbers are taken as text and converted here: a conversion failure inside CLI11 would print
// its own two-line report instead of the one-line reason the CLI contract asks for.
struct SynthOptions {
  std::string shape;
  std::string out;
  std::string radius_mm = "25";
  std::string pixel_mm = "0.5";
  std::string noise_mm = "0";
  std::string seed = "1";
  std::string rotate_deg = "0";
};

template <class Number>
Number parse_whole(const char* option, const std::string& text, const char* expected) {
  Number value{};
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, value);
  if (text.empty() || error != std::errc() || stop != end) {
    throw InputError(std::string("synth: ") + option + " '" + text + "': expected " + expected);
  }
  return value;
}

double parse_mm(const char* option, const std::string& text, bool zero_allowed) {
  const double value = parse_whole<double>(option, text, "a number");
  const bool in_range = std::isfinite(value) && (zero_allowed ? value >= 0.0 : value > 0.0);
  if (!in_range) {
    throw InputError(std::string("synth: ") + option + " '" + text + "': must be " +
                     (zero_allowed ? ">= 0" : "> 0") + " and finite");
  }
  return value;
}

void run_synth(const SynthOptions& options) {
  if (options.shape.empty()) {
    throw InputError("synth: missing SHAPE (one of " + analytic_shape_names() + ")");
  }
  if (options.out.empty()) throw InputError("synth: missing --out FILE (.tif, .tiff or .pfm)");
  AnalyticSurfaceSpec spec;
  spec.shape = parse_analytic_shape(options.shape);
  spec.radius_mm = parse_mm("--radius-mm", options.radius_mm, false);
  spec.pixel_size_mm = parse_mm("--pixel-mm", options.pixel_mm, false);
  spec.noise_mm = parse_mm("--noise-mm", options.noise_mm, true);
  spec.seed = parse_whole<std::uint64_t>("--seed", options.seed, "a non-negative integer");
  spec.rotate_deg = parse_whole<double>("--rotate-deg", options.rotate_deg, "a number");
  if (!std::isfinite(spec.rotate_deg)) {
    throw InputError("synth: --rotate-deg '" + options.rotate_deg + "': must be finite");
  }

  const AnalyticSurface surface = make_analytic_surface(spec);
  const std::filesystem::path out_path = options.out;
  write_range_image(surface.range, out_path);
  std::printf("synth: %s %d x %d pixels (%zu with data) -> %s + %s\n", options.shape.c_str(),
              surface.range.width(), surface.range.height(), surface.range.count_valid(),
              out_path.string().c_str(), sidecar_path(out_path).string().c_str());
}

void install_synth(CLI::App& root) {
  auto options = std::make_shared<SynthOptions>();
  CLI::App* command = root.add_subcommand(
      "synth", "Render an analytic test surface as a range image with exact ground truth");
  command->add_option("SHAPE", options->shape, "one of: " + analytic_shape_names());
  command
      ->add_option("--out", options->out, "output range image: .tif/.tiff or .pfm (+ <stem>.yaml)")
      ->type_name("FILE");
  command->add_option("--radius-mm", options->radius_mm, "radius R; the other sizes scale with it")
      ->type_name("MM")
      ->capture_default_str();
  command->add_option("--pixel-mm", options->pixel_mm, "pixel size (dx = dy)")
      ->type_name("MM")
      ->capture_default_str();
  command->add_option("--noise-mm", options->noise_mm, "standard deviation of Gaussian z noise")
      ->type_name("MM")
      ->capture_default_str();
  command->add_option("--seed", options->seed, "seed of the noise generator")
      ->type_name("UINT")
      ->capture_default_str();
  command
      ->add_option("--rotate-deg", options->rotate_deg,
                   "rotation of the part about the viewing axis")
      ->type_name("DEG")
      ->capture_default_str();
  command->callback([options] { run_synth(*options); });
}

const CommandRegistration registration{"synth", install_synth};

}  // namespace
}  // namespace cosmos::cli
