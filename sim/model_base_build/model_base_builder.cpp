#include "sim/model_base_build/model_base_builder.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <thread>

#include "core/modelbase/part_surface_summary.hpp"
#include "core/modelbase/view_extent.hpp"
#include "core/modelbase/view_signature.hpp"
#include "core/recognition/confusable_parts.hpp"
#include "core/representation/cosmos_pipeline.hpp"
#include "core/task_runner.hpp"
#include "sim/convex_hull.hpp"
#include "sim/mesh.hpp"
#include "sim/model_base_build/catalog_content_hash.hpp"
#include "sim/model_base_build/model_base_parameters.hpp"
#include "sim/model_views.hpp"

namespace cosmos {
namespace {

// Largest distance between two vertices (the ADD-S normalizer): the farthest pair lies on the
// convex hull, so only its corners are compared.
double mesh_diameter_mm(const TriangleMesh& mesh) {
  std::vector<Eigen::Vector3d> points;
  try {
    for (const HullFace& face : convex_hull(mesh.vertices).faces)
      points.insert(points.end(), face.corners.begin(), face.corners.end());
  } catch (const std::invalid_argument&) {  // flat: no hull, every vertex is a candidate
    for (const Eigen::Vector3f& v : mesh.vertices) points.push_back(v.cast<double>());
  }
  const auto less = [](const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
  };
  std::sort(points.begin(), points.end(), less);
  points.erase(std::unique(points.begin(), points.end()), points.end());
  double largest_mm2 = 0;
  for (std::size_t i = 0; i < points.size(); ++i)
    for (std::size_t j = i + 1; j < points.size(); ++j)
      largest_mm2 = std::max(largest_mm2, (points[i] - points[j]).squaredNorm());
  return std::sqrt(largest_mm2);
}

struct ViewResult {
  bool measured = false;
  ModelBaseView view;
};

// What the workers share. Each job writes only its own result slot.
struct BuildJobs {
  BuildJobs(const PartCatalog& catalog_, const std::vector<TriangleMesh>& meshes_,
            const ScannerParameters& scanner_, const ModelBaseBuildSettings& settings_)
      : catalog(catalog_),
        meshes(meshes_),
        scanner(scanner_),
        settings(settings_),
        view_indices(spread_view_subset(settings_.view_count)),
        results(catalog_.parts.size() * view_indices.size()),
        done_per_part(std::make_unique<std::atomic<int>[]>(catalog_.parts.size())) {}

  const PartCatalog& catalog;
  const std::vector<TriangleMesh>& meshes;
  const ScannerParameters& scanner;
  const ModelBaseBuildSettings& settings;
  std::vector<int> view_indices;
  std::vector<ViewResult> results;
  std::atomic<std::size_t> next_job{0};
  std::unique_ptr<std::atomic<int>[]> done_per_part;
  std::atomic<bool> failed{false};
  std::mutex mutex;
  std::condition_variable progressed;
  std::exception_ptr error;

  std::size_t views_per_part() const { return view_indices.size(); }
};

void analyze_job(const ModelBaseBuildSettings& settings, ModelViewRenderer& renderer,
                 ViewAnalysisWorkspace& workspace, int part, int view_index, ViewResult& result) {
  const ModelView scanned = renderer.scan_view(view_index);
  if (scanned.image.width() == 0 || scanned.image.count_valid() == 0) return;
  ViewAnalysis analysis = analyze_view(scanned.image, settings.cosmos, workspace);
  ModelBaseView& view = result.view;
  view.part_index = part;
  view.view_index = view_index;
  view.direction_part = scanned.direction_part;
  view.T_scanner_part = {scanned.T_scanner_part.linear(), scanned.T_scanner_part.translation()};
  view.moments = analysis.moments;
  // With the view's Darboux frames, control-point normals come from the smoothed bicubic fit,
  // more accurate on curved surfaces than the window plane's
  // (core/registration/registration_points.hpp).
  const RegistrationPointsResult registration =
      build_registration_points(scanned.image, settings.registration, &analysis.frames);
  view.registration_packed = pack_registration_points(registration.points);
  view.cosmos = std::move(analysis.view);
  result.measured = true;
}

void run_worker(BuildJobs& jobs) {
  std::unique_ptr<ModelViewRenderer> renderer;  // one Embree scene per part and worker
  int renderer_part = -1;
  ViewAnalysisWorkspace workspace;  // the worker's views, one after another
  const std::size_t total = jobs.results.size();
  try {
    for (std::size_t job = jobs.next_job++; job < total && !jobs.failed; job = jobs.next_job++) {
      const int part = static_cast<int>(job / jobs.views_per_part());
      const int view_index = jobs.view_indices[job % jobs.views_per_part()];
      if (part != renderer_part) {
        renderer.reset();
        renderer = std::make_unique<ModelViewRenderer>(
            jobs.meshes[static_cast<std::size_t>(part)],
            jobs.catalog.parts[static_cast<std::size_t>(part)].name, jobs.scanner,
            jobs.settings.conditioning, kViewSphereSubdivisions);
        renderer_part = part;
      }
      analyze_job(jobs.settings, *renderer, workspace, part, view_index, jobs.results[job]);
      ++jobs.done_per_part[static_cast<std::size_t>(part)];
      jobs.progressed.notify_one();
    }
  } catch (...) {
    const std::lock_guard lock(jobs.mutex);
    if (!jobs.error) jobs.error = std::current_exception();
    jobs.failed = true;
    jobs.progressed.notify_one();
  }
}

ModelBaseBuildProgress snapshot(const BuildJobs& jobs) {
  ModelBaseBuildProgress progress;
  progress.parts_total = static_cast<int>(jobs.catalog.parts.size());
  progress.views_total = static_cast<int>(jobs.results.size());
  bool complete_so_far = true;
  for (int part = 0; part < progress.parts_total; ++part) {
    const int done = jobs.done_per_part[static_cast<std::size_t>(part)];
    progress.views_done += done;
    complete_so_far = complete_so_far && done == static_cast<int>(jobs.views_per_part());
    if (complete_so_far) progress.parts_done = part + 1;
  }
  return progress;
}

void run_jobs(BuildJobs& jobs, int threads, const ModelBaseProgress& progress) {
  std::vector<std::thread> workers;
  for (int t = 0; t < threads; ++t) workers.emplace_back(run_worker, std::ref(jobs));
  int reported_parts = -1;
  auto last_report = std::chrono::steady_clock::now();
  for (;;) {
    {
      std::unique_lock lock(jobs.mutex);
      jobs.progressed.wait_for(lock, std::chrono::milliseconds(100));
    }
    const ModelBaseBuildProgress now = snapshot(jobs);
    const bool finished = now.views_done == now.views_total || jobs.failed;
    const auto time = std::chrono::steady_clock::now();
    if (progress && (finished || now.parts_done != reported_parts ||
                     time - last_report >= std::chrono::milliseconds(100))) {
      progress(now);
      reported_parts = now.parts_done;
      last_report = time;
    }
    if (finished) break;
  }
  for (std::thread& worker : workers) worker.join();
  if (jobs.error) std::rethrow_exception(jobs.error);
}

// The build's independent steps after the views (the parts' summaries, the fits of their
// views) on `threads` threads, the calling one among them, each task taken from a counter.
class BuildThreads final : public TaskRunner {
 public:
  explicit BuildThreads(int threads) : threads_(threads) {}
  void run(int count, const std::function<void(int task)>& task) const override {
    std::atomic<int> next{0};
    const auto work = [&] {
      for (int k = next++; k < count; k = next++) task(k);
    };
    std::vector<std::thread> workers;
    for (int t = 1; t < threads_; ++t) workers.emplace_back(work);
    work();
    for (std::thread& worker : workers) worker.join();
  }
  int threads() const override { return threads_; }

 private:
  int threads_;
};

// Each part's confusable parts, from every part's search model (its distance field).
void list_confusable_parts(ModelBase& base, const ConfusablePartParameters& confusion,
                           const TaskRunner& tasks) {
  if (!confusion.enabled) return;
  std::vector<PartSearchModel> models(base.parts.size());
  tasks.run(static_cast<int>(models.size()), [&](int part) {
    models[static_cast<std::size_t>(part)] = build_part_search_model(base, part);
  });
  std::vector<std::vector<int>> confusable = find_confusable_parts(base, models, confusion, tasks);
  for (std::size_t part = 0; part < base.parts.size(); ++part)
    base.parts[part].confusable_parts = std::move(confusable[part]);
}

}  // namespace

RegistrationPointParameters model_surface_registration_parameters() {
  RegistrationPointParameters parameters;
  parameters.stride_px = 3;
  return parameters;
}

ModelBase build_model_base(const PartCatalog& catalog, const ScannerParameters& scanner,
                           const ModelBaseBuildSettings& settings,
                           const ModelBaseProgress& progress) {
  ModelBase base;
  base.catalog_hash = catalog_content_hash(catalog);
  base.parameters_text = model_base_parameters_text(scanner, settings);
  std::vector<TriangleMesh> meshes;
  for (const PartEntry& entry : catalog.parts) {
    meshes.push_back(load_mesh(entry.mesh_path, entry.size_mm));
    ModelPart& part = base.parts.emplace_back();
    part = {entry.name,
            entry.mesh_path.filename().string(),
            entry.size_mm,
            mesh_diameter_mm(meshes.back()),
            entry.symmetric,
            {},
            {},
            {},
            {},
            {}};
    for (const StableRestingPose& pose : stable_resting_poses(meshes.back(), settings.resting))
      part.resting_poses.push_back({pose.R_belt_part, pose.height_mm, pose.probability});
    part.hull_vertices_mm = hull_vertices(meshes.back());
  }

  BuildJobs jobs(catalog, meshes, scanner, settings);
  const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  const int threads = std::clamp(settings.threads > 0 ? settings.threads : cores, 1,
                                 std::max(1, static_cast<int>(jobs.results.size())));
  run_jobs(jobs, threads, progress);

  for (ViewResult& result : jobs.results)
    if (result.measured) base.views.push_back(std::move(result.view));
  ViewGroupingResult grouping = group_model_views(base, settings.grouping);
  if (grouping.status != ClusteringStatus::kOk)
    throw std::logic_error("view grouping failed for part '" +
                           base.parts[static_cast<std::size_t>(grouping.failed_part)].name +
                           "' (non-finite moments?)");
  base.clusters = std::move(grouping.clusters);
  const BuildThreads tasks(threads);
  // Each part's summaries read and write only that part and its views.
  tasks.run(static_cast<int>(base.parts.size()), [&](int part) {
    summarize_part_surface(base, part, settings.field);
    summarize_view_extents(base, part);
    summarize_view_signatures(base, part);
  });
  list_confusable_parts(base, settings.confusion, tasks);
  return base;
}

}  // namespace cosmos
