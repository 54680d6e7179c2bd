// `cosmos cell --config config/cell.yaml [--source sim|hardware] [--hardware FILE] [--parts N]
// [--duration-s S] [--unpaced] [--replay FILE] [--http HOST:PORT]`: the work cell. Profiles from
// the scanner source run through the real-time loop (realtime/cell/cell_runner.hpp); each part's
// pose goes out on COSMOS_POSE while a live table shows it; a summary ends the run. With --http
// (or web.http_address) a live web view serves the belt, the poses and the status counters
// (realtime/web/web_view.hpp) from before the model base loads until the run ends.
#include <sys/resource.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <numbers>
#include <optional>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include "apps/cell_world.hpp"
#include "apps/command_registry.hpp"
#include "core/input_error.hpp"
#include "core/parameter_range_check.hpp"
#include "core/recognition/recognizer.hpp"
#include "realtime/cell/cell_runner.hpp"
#include "realtime/config/cell_config.hpp"
#include "realtime/rt/helper_threads.hpp"
#include "realtime/rt/latency_histogram.hpp"
#include "realtime/web/web_view.hpp"

namespace cosmos::cli {
namespace {

struct CellOptions {
  std::string config = "config/cell.yaml";
  std::string source = "sim";
  std::string hardware;
  int parts = -1;
  double duration_s = 0;
  bool unpaced = false;
  bool repeat = false;
  std::string replay;
  std::string http;  // replaces web.http_address
};

// The process's peak resident memory so far, MB (getrusage's ru_maxrss is in kB on Linux).
double peak_resident_mb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;
}

// Every loss and fault total of the run's last COSMOS_STATUS, zeros too: an operator sees
// that each was counted, not only that nothing was printed.
void print_losses(const CellStatus& status) {
  std::string line = "cell: losses and faults:";
  const char* separator = " ";
  CellStatus::visit_totals(status, [&](const char* name, std::int64_t total, const char*) {
    const std::string_view key(name);
    if (key == "profiles_acquired" || key == "parts_seen" || key == "parts_recognized" ||
        key == "parts_rejected")
      return;
    line += separator + std::string(name) + ' ' + std::to_string(total);
    separator = ", ";
  });
  std::printf("%s\n", line.c_str());
}

// The web view, when an address is given, started before anything slow.
std::unique_ptr<WebView> start_web_view(const CellOptions& options, const CellConfig& config) {
  const std::string& text = options.http.empty() ? config.web.http_address : options.http;
  if (text.empty()) return nullptr;
  // Bad input names where the address came from.
  const std::string source =
      options.http.empty() ? options.config + ": web.http_address" : std::string("--http");
  std::string reason;
  const std::optional<HttpAddress> address = parse_http_address(text, reason);
  if (!address) throw InputError(source + ": " + reason);
  auto web = std::make_unique<WebView>(config.web, *address, source);
  std::printf("cell: web view at %s\n", web->url().c_str());
  std::fflush(stdout);
  web->show_state("loading the model base");
  return web;
}

// The run against the simulated ground truth, a pose or rejection at a time: each is paired
// with the placed part it stands for (by position, so that each of a blob's parts has its own).
struct GroundTruthTally {
  std::vector<int> reported;  // per placed part: poses and rejections that stand for it
  int identified = 0, wrong_part = 0, poor_pose = 0, rejected = 0, unpaired = 0;

  void add(const PartPose& pose, const CellWorld::SimulatedTruth& truth,
           const std::map<std::string, double>& diameter_mm) {
    if (truth.placed_index < 0) {
      ++unpaired;
    } else {
      // --repeat: each pass's parts are placed again, after the first pass's.
      const auto index = static_cast<std::size_t>(truth.placed_index);
      if (index >= reported.size()) reported.resize(index + 1, 0);
      ++reported[index];
    }
    if (pose.status != PoseStatus::kOk) {
      ++rejected;
    } else if (pose.part_name != truth.name) {
      ++wrong_part;
    } else {
      const auto diameter = diameter_mm.find(pose.part_name);
      const bool close = diameter != diameter_mm.end() && truth.add_s_mm >= 0 &&
                         truth.add_s_mm < 0.1 * diameter->second;
      ++(close ? identified : poor_pose);
    }
  }

  void print() const {
    const auto none = std::count(reported.begin(), reported.end(), 0);
    const auto twice = std::count_if(reported.begin(), reported.end(), [](int n) { return n > 1; });
    std::printf(
        "cell: of %zu parts placed: %d identified (ADD-S < 10 %% of the diameter), %d wrong part, "
        "%d poor pose, %d rejected with a reason; parts with no pose nor rejection %lld, with "
        "several %lld, reports matching no part %d (simulated ground truth)\n",
        reported.size(), identified, wrong_part, poor_pose, rejected, static_cast<long long>(none),
        static_cast<long long>(twice), unpaired);
  }

  // The parts with no pose nor rejection, by name and place on the belt (the first few).
  void print_unreported(const CellWorld& world) const {
    constexpr int kListed = 10;
    std::string listed;
    int count = 0;
    for (std::size_t index = 0; index < reported.size(); ++index) {
      if (reported[index] != 0) continue;
      if (++count <= kListed)
        listed += (listed.empty() ? "" : "; ") + std::string("#") + std::to_string(index) + " " +
                  world.describe_placed_part(static_cast<std::int64_t>(index));
    }
    if (count > 0)
      std::printf("cell: no pose nor rejection for %s%s\n", listed.c_str(),
                  count > kListed ? "; ..." : "");
  }
};

void run(const CellOptions& options) {
  const CellConfig config = load_cell_config(options.config);
  const std::unique_ptr<WebView> web = start_web_view(options, config);
  CellWorld world(config);
  ScannerSource& source = world.open_source(
      {options.source, options.hardware, options.replay, options.parts, options.repeat});
  if (std::abs(source.mm_per_profile() - config.conditioning.grid_mm) > 1e-9)
    throw InputError(options.config +
                     ": conditioning.grid_mm must equal the belt travel per profile (" +
                     std::to_string(source.mm_per_profile()) + " mm)");
  // The COSMOS parameters the base was built with, the one set every analysis of a scan
  // uses: the recognizer, the scan loop's incremental COSMOS and the part views.
  const CellModelBase loaded = world.load_model_base();
  const double model_base_loaded_mb = peak_resident_mb();
  const ModelBase& base = loaded.base;
  const CosmosParameters& cosmos = loaded.cosmos;
  RecognitionParameters recognition;
  recognition.surfaces = config.realtime.recognizer_surfaces;
  recognition.resting.parts_touch_belt = config.cell.parts_touch_belt;
  recognition.resting.parts_rest = config.cell.parts_rest;
  recognition.surface_seen.sight = scanner_sight(config.scanner);
  const HelperThreads recognition_helpers(config.realtime.threads.recognition_helpers);
  const Recognizer recognizer(base, cosmos, recognition, &recognition_helpers);
  LcmPublisher lcm_publisher(config.lcm.url, config.lcm.channels());
  Publisher& publisher = web ? web->publisher(lcm_publisher) : lcm_publisher;

  const bool unpaced = options.unpaced || !options.replay.empty();
  ScanLoopSettings loop_settings{
      .conditioning = config.conditioning,
      .tracking = config.tracking.tracker,
      .cosmos = cosmos,
      .max_part_rows = config.max_part_rows(),
      .shadow_length_per_height =
          std::tan(config.scanner.triangulation_angle_deg * std::numbers::pi / 180),
      .parts = config.realtime.parts,
      .wait_for_recognizer = unpaced};
  ScanLoop loop(loop_settings);

  PartRecognitionContext context;
  context.recognizer = &recognizer;
  context.model_base = &base;
  context.cosmos = cosmos;
  context.catalog_index_of_base_part = world.catalog_indices(base);
  context.T_cell_scanner = config.cell.T_cell_scanner;
  context.mm_per_tick = config.scanner.encoder_mm_per_tick;
  context.grid_mm = config.conditioning.grid_mm;
  context.x0_loop_mm = loop.x0_loop_mm();
  context.keep_part_image = web != nullptr;
  if (web) {
    web->set_belt(config.conditioning.grid_mm, loop.width(), loop.x0_loop_mm());
    web->show_state("starting");
  }
  context.stream_faults = world.stream_faults();

  // The source starts last: a camera streams and an encoder counts from start(), and a slow
  // model base load or recognizer set-up before the loop polls them would be lost frames,
  // camera timeouts and encoder events.
  if (source.start() != SourceStatus::kOk) throw InputError(std::string(source.last_error()));

  CellRunSettings settings;
  settings.line_rate_hz = config.scanner.line_rate_hz;
  settings.paced = !unpaced;
  settings.deterministic_output = !options.replay.empty();
  settings.threads = config.realtime.threads;
  settings.publishing = config.lcm.publishing;
  settings.duration_s = options.duration_s;
  settings.recognizer_delay_ms = config.faults.recognizer_delay_ms;

  // A histogram, not a list of every latency: a cell runs for months (the soak's RSS).
  LatencyHistogram latencies;
  std::map<std::string, double> diameter_mm;
  for (const ModelPart& part : base.parts) diameter_mm[part.name] = part.diameter_mm;
  GroundTruthTally tally;
  tally.reported.assign(static_cast<std::size_t>(world.simulated_parts_placed()), 0);
  std::printf("%5s  %-18s %-9s %9s %9s %9s  %6s %8s %10s\n", "part", "name", "status", "x_mm",
              "y_mm", "z_mm", "score", "rms_mm", "latency_ms");
  const CellRunSummary summary =
      run_cell(source, loop, context, publisher, settings, [&](const PartRecognition& recognition) {
        const PartPose& pose = recognition.pose;
        latencies.record_ns(static_cast<std::int64_t>(pose.latency_ms * 1e6));
        world.announce_pose_published();
        if (web) web->observe(recognition);
        const CellWorld::SimulatedTruth found = world.simulated_truth_of(
            recognition, config.cell.T_cell_scanner, config.scanner.encoder_mm_per_tick);
        const std::string& truth = found.name;
        if (world.has_ground_truth()) tally.add(pose, found, diameter_mm);
        const Eigen::Vector3d& t = pose.translation_cell_part_mm;
        // A rejection or error says why, as its part_pose_t does.
        const bool ok = pose.status == PoseStatus::kOk;
        std::printf("%5lld  %-18s %-9s %9.2f %9.2f %9.2f  %6.3f %8.4f %10.1f%s%s%s%s\n",
                    static_cast<long long>(pose.part_seq), ok ? pose.part_name.c_str() : "-",
                    to_string(pose.status), t.x(), t.y(), t.z(), pose.score,
                    pose.registration_rms_mm, pose.latency_ms,
                    truth.empty() ? "" : "  truth: ", truth.c_str(),
                    ok ? "" : "  reason: ", ok ? "" : pose.reason.c_str());
        std::fflush(stdout);
      });
  if (!summary.source_error.empty()) throw InputError(summary.source_error);
  std::printf(
      "\ncell: %lld profiles (%lld dropped, %lld deadline overruns), %lld parts seen "
      "(%lld dropped), %lld poses published\n",
      static_cast<long long>(summary.profiles), static_cast<long long>(summary.profiles_dropped),
      static_cast<long long>(summary.deadline_overruns), static_cast<long long>(summary.parts_seen),
      static_cast<long long>(summary.parts_dropped),
      static_cast<long long>(summary.poses_published));
  // The belt's time, from the profiles and the line rate: what the cell kept up with,
  // whatever the wall clock did while it ran.
  const double belt_s = static_cast<double>(summary.profiles) / settings.line_rate_hz;
  std::printf("cell: %.1f parts/s over %.1f s of belt (%lld parts seen)\n",
              belt_s > 0 ? static_cast<double>(summary.parts_seen) / belt_s : 0.0, belt_s,
              static_cast<long long>(summary.parts_seen));
  if (world.has_ground_truth()) {
    tally.print();
    tally.print_unreported(world);
  }
  std::printf(
      "cell: latency end of part -> pose published: median %.1f ms, p99 %.1f ms, max %.1f ms; "
      "%lld blobs recognized ahead of their completion, %lld at it; %lld groups of pieces a "
      "part's shadow cut apart recognized as one; %lld recognized blobs waited for the part "
      "behind them (a soft successor: its shadow may have cut one part in two)\n",
      latencies.p50_ns() / 1e6, latencies.p99_ns() / 1e6, latencies.max_ns() / 1e6,
      static_cast<long long>(summary.blobs_recognized_ahead),
      static_cast<long long>(summary.blobs_recognized_at_completion),
      static_cast<long long>(summary.blob_groups_recognized),
      static_cast<long long>(summary.blobs_held_for_successor));
  const RowBlockPool& row_pool = loop.row_pool();
  const double block_mb = static_cast<double>(row_pool.block_bytes()) / (1024.0 * 1024.0);
  std::printf(
      "cell: peak memory %.0f MB (max RSS; %.0f MB once the model base was loaded); part rows "
      "peak %d of %d blocks (%.1f of %.1f MB, realtime.row_blocks), %lld parts dropped for "
      "want of one\n",
      peak_resident_mb(), model_base_loaded_mb, row_pool.peak_blocks_in_use(),
      row_pool.block_count(), row_pool.peak_blocks_in_use() * block_mb,
      row_pool.block_count() * block_mb,
      static_cast<long long>(loop.counters().parts_out_of_rows.load()));
  std::printf(
      "cell: per-profile processing p50 %.0f us, p99 %.0f us, max %.0f us; start jitter "
      "p50 %.0f us, p99 %.0f us\n",
      summary.profile_time_p50_us, summary.profile_time_p99_us, summary.profile_time_max_us,
      summary.start_jitter_p50_us, summary.start_jitter_p99_us);
  print_losses(summary.last_status);
  std::printf("cell: %s\n", summary.realtime_report.c_str());
  if (web && config.web.linger_s > 0) {
    std::printf("cell: web view stays up for %g s (web.linger_s)\n", config.web.linger_s);
    std::fflush(stdout);
    std::this_thread::sleep_for(std::chrono::duration<double>(config.web.linger_s));
  }
}

// --parts sets sim_source.parts: the range its visit() declares, before any config is read.
std::string check_part_count(const std::string& text) {
  SimulatedSourceSettings settings;
  const char* const end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, settings.parts);
  if (error != std::errc{} || stop != end) return "'" + text + "' is not a whole number";
  const std::optional<std::string> problem = first_out_of_range(settings, "sim_source");
  if (!problem) return {};
  std::string reason = *problem;
  const std::size_t colon = reason.find(": ");
  if (colon != std::string::npos) reason.erase(colon, 1);  // "sim_source.parts must be in ..."
  return reason;
}

void install(CLI::App& root) {
  auto options = std::make_shared<CellOptions>();
  CLI::App* command =
      root.add_subcommand("cell", "Run the work cell: scan, recognize, publish poses over LCM");
  command->add_option("--config", options->config, "cell configuration")->capture_default_str();
  command->add_option("--source", options->source, "scanner source")
      ->check(CLI::IsMember({"sim", "hardware"}))
      ->capture_default_str();
  command->add_option("--hardware", options->hardware, "hardware YAML for --source hardware")
      ->type_name("FILE");
  command->add_option("--parts", options->parts, "simulated parts (default: sim_source.parts)")
      ->check(check_part_count, "N");
  command->add_option("--duration-s", options->duration_s, "stop after this much scanning time")
      ->check(CLI::NonNegativeNumber);
  command->add_flag("--unpaced", options->unpaced, "do not pace the loop at the line rate");
  command->add_flag("--repeat", options->repeat,
                    "simulated parts: start the belt over at its end, until --duration-s");
  command->add_option("--replay", options->replay, "replay an lcm-logger log of COSMOS_PROFILE")
      ->type_name("FILE");
  command
      ->add_option("--http", options->http,
                   "serve the live web view at HOST:PORT (e.g. 127.0.0.1:8080; default: "
                   "web.http_address, empty = off)")
      ->type_name("HOST:PORT")
      ->check(
          [](const std::string& text) {
            std::string reason;
            return parse_http_address(text, reason) ? std::string() : reason;
          },
          "HOST:PORT");
  command->callback([options] { run(*options); });
}

const CommandRegistration registration("cell", install);

}  // namespace
}  // namespace cosmos::cli
