#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>

#include "apps/cell_replay_source.hpp"
#include "apps/cell_world.hpp"
#include "apps/model_base_progress.hpp"
#include "core/input_error.hpp"
#include "core/io/model_base_file.hpp"
#include "core/io/xxh64.hpp"
#include "realtime/config/hardware_config.hpp"
#include "realtime/sources/hardware_source.hpp"
#include "realtime/sources/repeating_source.hpp"
#include "realtime/sources/stream_checked_source.hpp"
#include "scanner/simulated_mounting.hpp"
#include "sim/conveyor_scene.hpp"
#include "sim/evaluation/add_s_distance.hpp"
#include "sim/mesh.hpp"
#include "sim/mesh_surface_distance.hpp"
#include "sim/model_base_build/catalog_content_hash.hpp"
#include "sim/model_base_build/model_base_builder.hpp"
#include "sim/model_base_build/model_base_parameters.hpp"
#include "sim/part_catalog.hpp"
#include "sim/source/simulated_source.hpp"
#include "sim/twins/hardware_twin_source.hpp"

namespace cosmos::cli {
namespace {

SimulatedSourceSettings source_settings(const CellSourceChoice& choice, const CellConfig& config) {
  SimulatedSourceSettings settings = config.sim_source;
  if (choice.parts > 0) settings.parts = choice.parts;
  return settings;
}

ModelBaseBuildSettings build_settings(const CellConfig& config) {
  ModelBaseBuildSettings settings;
  settings.view_count = config.cell.model_views;
  settings.conditioning = config.conditioning;
  return settings;
}

// The cache holds one base per catalog content, parameter set and file format: a changed
// catalog, scanner or belt threshold, or a build whose model bases differ (their format
// version), builds a new base instead of loading a stale one.
std::filesystem::path cached_model_base_path(const CellConfig& config, const PartCatalog& catalog) {
  const ModelBaseBuildSettings settings = build_settings(config);
  const std::string key = catalog_content_hash(catalog) +
                          model_base_parameters_text(config.scanner, settings) + "format " +
                          std::to_string(ModelBase::kFormatVersion);
  char name[64];
  std::snprintf(name, sizeof name, "cell-%d-views-%016llx.cmb", settings.view_count,
                static_cast<unsigned long long>(xxh64(key)));
  return default_mesh_cache_dir().parent_path() / "modelbases" / name;
}

}  // namespace

struct CellWorld::State {
  const CellConfig& config;
  PartCatalog catalog;
  std::unique_ptr<StreamCheckedSource> source;
  const SimulatedConveyor* conveyor = nullptr;  // the source's, when it has one
  HardwareSource* hardware = nullptr;           // the source's, when it is one
  std::int64_t repeat_profiles = 0;             // --repeat: profiles per pass of the belt
  // Per catalog part, its mesh's vertices for ADD-S, loaded on first use.
  mutable std::map<std::string, std::unique_ptr<AddSDistance>> add_s;
};

CellWorld::CellWorld(const CellConfig& config)
    : state_(new State{
          config, read_part_catalog(config.cell.catalog), nullptr, nullptr, nullptr, 0, {}}) {}

CellWorld::~CellWorld() = default;

ScannerSource& CellWorld::open_source(const CellSourceChoice& choice) {
  const CellConfig& config = state_->config;
  std::unique_ptr<ScannerSource> opened;
  if (!choice.replay.empty()) {
    opened = make_cell_replay_source(choice.replay, config);
  } else if (choice.source == "hardware") {
    if (choice.hardware.empty()) {
      throw InputError(
          "cell: --source hardware needs --hardware FILE (see config/hardware-example.yaml, or "
          "config/hardware-sim.yaml for the simulated twins)");
    }
    const HardwareConfig hardware = read_hardware_config(choice.hardware);
    if (!hardware.camera_simulated()) {
      auto source = std::make_unique<HardwareSource>(hardware, config.scanner);
      state_->hardware = source.get();
      opened = std::move(source);
    } else {
      // The belt runs and the camera renders by the true geometry (sim_source.truth); the
      // hardware source steps and triangulates with what the cell is told.
      const SimulatedMounting& truth = config.sim_source.truth;
      auto twins = std::make_unique<HardwareTwinSource>(
          hardware,
          std::make_unique<SimulatedConveyor>(state_->catalog,
                                              true_scanner_parameters(config.scanner, truth),
                                              source_settings(choice, config)),
          config.scanner, truth, SimulatedGpioSettings{}, config.faults);
      state_->conveyor = &twins->conveyor();
      state_->hardware = &twins->hardware();
      opened = std::move(twins);
    }
  } else {
    auto simulated = std::make_unique<SimulatedSource>(
        state_->catalog, config.scanner, source_settings(choice, config), config.faults);
    state_->conveyor = &simulated->conveyor();
    opened = std::move(simulated);
  }
  if (choice.repeat && state_->conveyor) {
    state_->repeat_profiles = state_->conveyor->last_profile() + 1;
    opened = std::make_unique<RepeatingSource>(
        std::move(opened), config.scanner.encoder_ticks_per_profile,
        config.scanner.time_us_of_profile(1) - config.scanner.time_us_of_profile(0));
  }
  state_->source = std::make_unique<StreamCheckedSource>(
      std::move(opened), config.scanner.encoder_ticks_per_profile, config.stream_check);
  return *state_->source;
}

const StreamFaultLog* CellWorld::stream_faults() const {
  return state_->source ? &state_->source->faults() : nullptr;
}

CellModelBase CellWorld::load_model_base() const {
  const CellConfig& config = state_->config;
  if (!config.cell.model_base.empty()) return read_cell_model_base(config.cell.model_base, config);
  const std::filesystem::path path = cached_model_base_path(config, state_->catalog);
  if (std::filesystem::exists(path)) return read_cell_model_base(path, config);
  std::fprintf(stderr, "cell: building the model base (first run; cached as %s)\n",
               path.string().c_str());
  std::error_code error;
  std::filesystem::create_directories(path.parent_path(), error);
  if (error)
    throw InputError(path.parent_path().string() + ": cannot create (" + error.message() + ")");
  const ModelBase base = build_model_base(state_->catalog, config.scanner, build_settings(config),
                                          progress_printer(state_->catalog));
  write_model_base(base, path);
  return read_cell_model_base(path, config);
}

std::vector<int> CellWorld::catalog_indices(const ModelBase& base) const {
  std::vector<int> indices;
  for (const ModelPart& part : base.parts) {
    const PartEntry* entry = state_->catalog.find(part.name);
    indices.push_back(entry ? static_cast<int>(entry - state_->catalog.parts.data()) : -1);
  }
  return indices;
}

bool CellWorld::has_ground_truth() const { return state_->conveyor != nullptr; }

std::string CellWorld::simulated_part_in(std::int64_t first_profile,
                                         std::int64_t last_profile) const {
  if (!state_->conveyor) return "";
  if (state_->repeat_profiles > 0) {  // the pass's own profile indices
    const std::int64_t pass_start = first_profile - first_profile % state_->repeat_profiles;
    first_profile -= pass_start;
    last_profile -= pass_start;
  }
  const PlacedSimPart* placed =
      state_->conveyor->placed_part_scanned_in(first_profile, last_profile);
  return placed ? placed->name : "";
}

CellWorld::SimulatedTruth CellWorld::simulated_truth_of(const PartRecognition& recognition,
                                                        const RigidTransform& T_cell_scanner,
                                                        double mm_per_tick) const {
  SimulatedTruth truth;
  if (!state_->conveyor) return truth;
  const PartPose& pose = recognition.pose;
  RigidTransform T_belt_part = belt_pose_of(pose, T_cell_scanner, mm_per_tick);
  std::int64_t first_profile = recognition.first_profile;
  std::int64_t last_profile = recognition.last_profile;
  std::int64_t pass = 0;
  if (state_->repeat_profiles > 0) {
    // --repeat: the pass's own profiles, and the belt position its parts had in the first
    // pass (the encoder counts on, so each pass lies pass_start profiles further along).
    pass = std::max<std::int64_t>(first_profile, 0) / state_->repeat_profiles;
    const std::int64_t pass_start = pass * state_->repeat_profiles;
    first_profile -= pass_start;
    last_profile -= pass_start;
    T_belt_part.translation_mm.y() += static_cast<double>(pass_start) *
                                      state_->config.scanner.encoder_ticks_per_profile *
                                      mm_per_tick;
  }
  const PlacedSimPart* placed =
      state_->conveyor->placed_part_at(T_belt_part.translation_mm, first_profile, last_profile);
  if (!placed) return truth;
  const std::vector<PlacedSimPart>& all = state_->conveyor->placed_parts();
  truth.placed_index =
      static_cast<int>(pass * static_cast<std::int64_t>(all.size()) + (placed - all.data()));
  truth.name = placed->name;
  if (pose.status != PoseStatus::kOk || pose.part_name != placed->name) return truth;
  std::unique_ptr<AddSDistance>& add_s = state_->add_s[placed->name];
  if (!add_s) {
    // The scanner's own mesh and hierarchy: a second copy of each was tens of MB of the
    // cell's peak memory.
    const ConveyorScene& scene = state_->conveyor->scene();
    std::vector<Eigen::Vector3d> points_mm;
    for (const Eigen::Vector3f& vertex : scene.mesh(placed->scene_mesh).vertices)
      points_mm.push_back(vertex.cast<double>());
    add_s = std::make_unique<AddSDistance>(
        points_mm, std::make_unique<const MeshSurfaceDistance>(scene.embree(), placed->scene_mesh));
  }
  const RigidPose true_pose{placed->T_belt_part.rotation(), placed->T_belt_part.translation()};
  truth.add_s_mm = add_s->add_s_mm(true_pose, {T_belt_part.rotation, T_belt_part.translation_mm});
  return truth;
}

std::int64_t CellWorld::simulated_parts_placed() const {
  return state_->conveyor ? static_cast<std::int64_t>(state_->conveyor->placed_parts().size()) : 0;
}

std::string CellWorld::describe_placed_part(std::int64_t index) const {
  if (!state_->conveyor || index < 0) return "";
  const std::vector<PlacedSimPart>& all = state_->conveyor->placed_parts();
  if (all.empty()) return "";
  const auto count = static_cast<std::int64_t>(all.size());
  // --repeat: pass p's parts are the first pass's, p passes of profiles further along.
  const std::int64_t pass_start = (index / count) * state_->repeat_profiles;
  const PlacedSimPart& placed = all[static_cast<std::size_t>(index % count)];
  return placed.name + ", profiles " + std::to_string(pass_start + placed.first_profile) + "-" +
         std::to_string(pass_start + placed.last_profile);
}

HardwareSource* CellWorld::hardware_source() const { return state_->hardware; }

void CellWorld::announce_pose_published() {
  if (state_->hardware) state_->hardware->announce_result();
}

}  // namespace cosmos::cli
