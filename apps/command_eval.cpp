// `cosmos eval --modelbase FILE --catalog FILE --tests N --seed S [--pose random|resting]
// [--noise-mm S] [--unknown PART,...] [--only TEST,...] [--threads N] [--helpers N] --out DIR`:
// N seeded scans (random poses, or the parts' stable resting poses on the belt)
// of the base's parts and scans of parts it does not hold, each recognized; metrics.json and
// report.html (sim/evaluation/evaluation_report.hpp) in DIR, and confusions.json: which part
// was taken for which, and why known parts were rejected (evaluation_confusions.hpp). --only
// re-runs chosen tests of the same plan (by the numbers the report shows), e.g. the failures of a
// long run.
#include <CLI/CLI.hpp>
#include <atomic>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "apps/command_registry.hpp"
#include "apps/model_base_progress.hpp"
#include "apps/option_range.hpp"
#include "core/input_error.hpp"
#include "core/io/model_base_file.hpp"
#include "core/io/recorded_parameters.hpp"
#include "realtime/rt/helper_threads.hpp"
#include "scanner/scanner_config.hpp"
#include "sim/evaluation/add_s_distance.hpp"
#include "sim/evaluation/evaluation_confusions.hpp"
#include "sim/evaluation/evaluation_report.hpp"
#include "sim/evaluation/evaluation_scans.hpp"
#include "sim/model_base_build/model_base_parameters.hpp"

namespace cosmos::cli {
namespace {

namespace fs = std::filesystem;

// A million scans is days of evaluation; a thread per core of the largest machine is plenty
// (each std::thread reserves its stack: a billion of them end in std::system_error).
constexpr double kMaxTests = 1e6;
constexpr double kMaxThreads = 1024;

struct EvalOptions {
  std::string model_base;
  std::string catalog;
  std::string config;
  int tests = 100;
  std::uint64_t seed = 1;
  std::string pose = "random";
  double noise_mm = -1;
  std::vector<std::string> unknown;
  std::vector<int> only;
  int threads = 1;
  int helpers = 0;
  std::string out;
};

// Tests run on `threads` workers; each record lands in its own slot, so the records (and all
// but the timing metrics) do not depend on the thread count.
std::vector<EvaluationRecord> run_tests(const std::vector<EvaluationTest>& plan,
                                        const std::vector<EvaluationPart>& parts,
                                        const ScannerParameters& scanner,
                                        const ConditioningParameters& conditioning,
                                        const Recognizer& recognizer, const ModelBase& base,
                                        int threads) {
  std::vector<EvaluationRecord> records(plan.size());
  std::atomic<std::size_t> next{0}, done{0};
  std::exception_ptr error;
  std::mutex error_mutex;
  ProgressReporter progress("eval", "scans", [](int done, int total) {
    return std::to_string(done) + "/" + std::to_string(total) + " scans recognized";
  });
  std::mutex progress_mutex;
  const auto work = [&] {
    ViewAnalysisWorkspace workspace;
    try {
      for (std::size_t i = next++; i < plan.size(); i = next++) {
        records[i] =
            run_evaluation_test(plan[i], parts, scanner, conditioning, recognizer, base, workspace);
        const std::lock_guard lock(progress_mutex);
        const int finished = static_cast<int>(++done);
        const int total = static_cast<int>(plan.size());
        progress.update(static_cast<double>(finished) / total, finished, total, "", 10);
      }
    } catch (...) {
      const std::lock_guard lock(error_mutex);
      if (!error) error = std::current_exception();
      next = plan.size();
    }
  };
  std::vector<std::thread> workers;
  for (int t = 1; t < threads; ++t) workers.emplace_back(work);
  work();
  for (std::thread& worker : workers) worker.join();
  if (error) std::rethrow_exception(error);
  return records;
}

std::vector<EvaluationTest> chosen_tests(const std::vector<EvaluationTest>& plan,
                                         const std::vector<int>& only) {
  std::vector<EvaluationTest> chosen;
  for (int index : only) {
    if (index < 0 || index >= static_cast<int>(plan.size()))
      throw InputError("eval: --only " + std::to_string(index) + " is not a test of this plan (0-" +
                       std::to_string(plan.size() - 1) + ")");
    chosen.push_back(plan[static_cast<std::size_t>(index)]);
  }
  return chosen;
}

void run(const EvalOptions& options) {
  if (options.model_base.empty()) throw InputError("eval: missing --modelbase FILE");
  if (options.out.empty()) throw InputError("eval: missing --out DIR");
  if (options.tests < 1) throw InputError("eval: --tests must be at least 1");
  if (options.threads < 1) throw InputError("eval: --threads must be at least 1");
  if (options.helpers < 0) throw InputError("eval: --helpers must be at least 0");
  std::error_code error;
  fs::create_directories(options.out, error);
  if (error) throw InputError(options.out + ": cannot create directory (" + error.message() + ")");

  const ModelBase base = read_model_base(options.model_base);
  const CosmosParameters cosmos = model_base_cosmos_parameters(base, options.model_base);
  const PartCatalog catalog = read_part_catalog(find_part_catalog(options.catalog));
  ScannerParameters scanner =
      options.config.empty() ? ScannerParameters{} : read_scanner_config(options.config);
  if (options.noise_mm >= 0) scanner.z_noise_mm = options.noise_mm;
  // The test scans are conditioned as the base's views were: they lose the belt at its
  // recorded threshold.
  ConditioningParameters conditioning;
  conditioning.height_threshold_mm =
      model_base_view_conditioning(base, options.model_base).height_threshold_mm;

  const std::vector<EvaluationPart> parts = evaluation_parts(base, catalog, options.unknown);
  std::vector<EvaluationTest> plan = evaluation_plan(
      parts, options.tests, options.seed,
      options.pose == "resting" ? EvaluationPoseMode::kResting : EvaluationPoseMode::kRandom);
  if (!options.only.empty()) plan = chosen_tests(plan, options.only);
  // Every test part lies on the belt (its lowest point on it), in resting poses in its
  // stable poses, as in a cell; the recognizer is told so (resting_pose_search.hpp).
  RecognitionParameters recognition;
  recognition.resting.parts_touch_belt = true;
  recognition.resting.parts_rest = options.pose == "resting";
  recognition.surface_seen.sight = scanner_sight(scanner);
  const HelperThreads helpers(options.helpers);
  const Recognizer recognizer(base, cosmos, recognition, &helpers);
  const std::vector<EvaluationRecord> records =
      run_tests(plan, parts, scanner, conditioning, recognizer, base, options.threads);

  std::vector<std::unique_ptr<AddSDistance>> add_s_by_catalog(catalog.parts.size());
  for (const EvaluationPart& part : parts)
    add_s_by_catalog[static_cast<std::size_t>(part.catalog_index)] =
        std::make_unique<AddSDistance>(part.model_points_mm, part.mesh);
  const EvaluationMetrics metrics = compute_metrics(records, [&](int part) -> const AddSDistance* {
    if (part < 0 || part >= static_cast<int>(add_s_by_catalog.size())) return nullptr;
    return add_s_by_catalog[static_cast<std::size_t>(part)].get();
  });
  std::vector<std::string> names;
  for (const PartEntry& entry : catalog.parts) names.push_back(entry.name);
  write_evaluation_report(options.out, records, metrics, names);
  const EvaluationConfusions confusions = count_confusions(records);
  const fs::path confusions_path = fs::path(options.out) / "confusions.json";
  std::ofstream confusions_file(confusions_path, std::ios::binary);
  confusions_file << confusions_json(confusions).dump(2) << "\n";
  confusions_file.close();
  if (!confusions_file) throw InputError("cannot write " + confusions_path.string());
  std::printf("%s\n", metrics_json(metrics).dump(2).c_str());
  std::printf("%s", confusions_text(confusions).c_str());
  std::printf("eval: report in %s\n", (fs::path(options.out) / "report.html").string().c_str());
}

void install(CLI::App& root) {
  auto options = std::make_shared<EvalOptions>();
  CLI::App* command =
      root.add_subcommand("eval", "Recognize seeded simulated scans and report the metrics");
  command->add_option("--modelbase", options->model_base, "model-base file")->type_name("FILE");
  command
      ->add_option("--catalog", options->catalog, "part catalog YAML (default: config/parts.yaml)")
      ->type_name("FILE");
  command
      ->add_option("--config", options->config,
                   "cell config whose scanner: section overrides the defaults")
      ->type_name("FILE");
  command->add_option("--tests", options->tests, "scans of known parts")
      ->check(within_range<int>(Range{1, kMaxTests}))
      ->capture_default_str();
  command->add_option("--seed", options->seed, "seed of the test plan, poses and noise")
      ->capture_default_str();
  command
      ->add_option(
          "--pose", options->pose,
          "random: uniform over all rotations; resting: the part's stable poses on the belt, "
          "and the recognizer told the parts rest")
      ->check(CLI::IsMember({"random", "resting"}))
      ->type_name("random|resting")
      ->capture_default_str();
  command->add_option("--noise-mm", options->noise_mm, "z noise sigma (default: the scanner's)")
      ->type_name("MM")
      ->check(declared_range<ScannerParameters, double>(
          "scanner", [](ScannerParameters& p, double mm) { p.z_noise_mm = mm; }));
  command
      ->add_option("--unknown", options->unknown, "catalog parts not in the base, to be rejected")
      ->delimiter(',')
      ->type_name("PART,...");
  command
      ->add_option("--only", options->only, "re-run only these tests of the plan (report numbers)")
      ->delimiter(',')
      ->type_name("TEST,...");
  command->add_option("--threads", options->threads, "worker threads (timings are per thread)")
      ->check(within_range<int>(Range{1, kMaxThreads}))
      ->capture_default_str();
  command
      ->add_option("--helpers", options->helpers,
                   "threads sharing each recognition's independent work, as in the cell "
                   "(0: none, the recognition on one core; the results are the same)")
      ->check(within_range<int>(Range{0, kMaxThreads}))
      ->capture_default_str();
  command->add_option("--out", options->out, "output directory")->type_name("DIR");
  command->callback([options] { run(*options); });
}

const CommandRegistration registration("eval", install);

}  // namespace
}  // namespace cosmos::cli
