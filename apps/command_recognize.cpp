// `cosmos recognize --modelbase FILE RANGE [--json]`: one range image against the model base
// (ch. 5 selection and verification, ch. 6 registration): which part, in which pose, or
// rejected as unknown.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <memory>
#include <string>

#include "apps/command_registry.hpp"
#include "apps/recognition_json.hpp"
#include "core/input_error.hpp"
#include "core/io/model_base_file.hpp"
#include "core/io/range_image_file.hpp"
#include "core/io/recorded_parameters.hpp"
#include "core/recognition/recognizer.hpp"
#include "scanner/scanner_model.hpp"

namespace cosmos::cli {
namespace {

struct RecognizeOptions {
  std::string model_base;
  std::string range_image;
  bool json = false;
  std::string estimator = "mve";
  std::string distance = "euclidean";
};

RecognitionParameters recognition_parameters(const RecognizeOptions& options) {
  RecognitionParameters parameters;
  parameters.registration.estimator = options.estimator == "cm"
                                          ? RegistrationEstimator::kChenMedioni
                                          : RegistrationEstimator::kMinimumVariance;
  parameters.selection.distance = options.distance == "mahalanobis" ? SpectralDistance::kMahalanobis
                                                                    : SpectralDistance::kEuclidean;
  // A range image file does not say which scanner took it: the simulated scanner's, by which
  // `cosmos sim scan` writes them and the default base is built.
  parameters.surface_seen.sight = scanner_sight(ScannerParameters{});
  return parameters;
}

void print_summary(const RecognitionResult& result, const ModelBase& base) {
  if (result.status != RecognitionStatus::kOk) {
    std::printf("rejected: %s\n", result.reason.c_str());
    return;
  }
  const Eigen::Vector3d& t = result.T_scanner_part.translation_mm;
  std::printf(
      "%s (view %d): score %.3f, rms %.3f mm, inliers %.0f %%, t = [%.2f %.2f %.2f] mm, %.1f ms\n",
      base.parts[static_cast<std::size_t>(result.part)].name.c_str(),
      base.views[static_cast<std::size_t>(result.view)].view_index, result.score,
      result.registration_rms_mm, 100 * result.inlier_fraction, t.x(), t.y(), t.z(),
      result.timings.total_ms);
}

void run(const RecognizeOptions& options) {
  if (options.model_base.empty()) throw InputError("recognize: missing --modelbase FILE");
  if (options.range_image.empty()) throw InputError("recognize: missing RANGE image");
  const ModelBase base = read_model_base(options.model_base);
  // A scene is analysed exactly as the base's views were.
  const CosmosParameters cosmos = model_base_cosmos_parameters(base, options.model_base);
  const RangeImage scene = read_range_image(options.range_image);
  const Recognizer recognizer(base, cosmos, recognition_parameters(options));
  const RecognitionResult result = recognizer.recognize(scene);
  if (options.json) {
    std::printf("%s\n", recognition_json(result, base).dump(2).c_str());
  } else {
    print_summary(result, base);
  }
}

void install(CLI::App& root) {
  auto options = std::make_shared<RecognizeOptions>();
  CLI::App* command =
      root.add_subcommand("recognize", "Identify a part and its pose in a range image");
  command->add_option("--modelbase", options->model_base, "model-base file")->type_name("FILE");
  command->add_option("RANGE", options->range_image, "range image (TIFF or PFM with sidecar)")
      ->type_name("FILE");
  command->add_flag("--json", options->json, "print the result as JSON");
  command
      ->add_option("--estimator", options->estimator,
                   "registration: mve (ch. 6.6) or cm (Chen-Medioni)")
      ->check(CLI::IsMember({"mve", "cm"}))
      ->capture_default_str();
  command
      ->add_option("--distance", options->distance, "spectral distance: euclidean or mahalanobis")
      ->check(CLI::IsMember({"euclidean", "mahalanobis"}))
      ->capture_default_str();
  command->callback([options] { run(*options); });
}

const CommandRegistration registration("recognize", install);

}  // namespace
}  // namespace cosmos::cli
