#include "apps/cell_replay_source.hpp"
#include "apps/cell_world.hpp"
#include "core/input_error.hpp"
#include "realtime/config/hardware_config.hpp"
#include "realtime/sources/hardware_source.hpp"
#include "realtime/sources/stream_checked_source.hpp"

namespace cosmos::cli {

// Without the simulator there is no part catalog to read (its meshes are the simulator's):
// a base part's catalog index is its index in the base, which the model-base build takes in
// catalog order.
struct CellWorld::State {
  const CellConfig& config;
  std::unique_ptr<StreamCheckedSource> source;
  HardwareSource* hardware = nullptr;
};

CellWorld::CellWorld(const CellConfig& config) : state_(new State{config, nullptr}) {}

CellWorld::~CellWorld() = default;

ScannerSource& CellWorld::open_source(const CellSourceChoice& choice) {
  const CellConfig& config = state_->config;
  if (!choice.replay.empty()) {
    state_->source = std::make_unique<StreamCheckedSource>(
        make_cell_replay_source(choice.replay, config), config.scanner.encoder_ticks_per_profile,
        config.stream_check);
    return *state_->source;
  }
  if (choice.source != "hardware")
    throw InputError("cell: --source " + choice.source +
                     ": this cosmos was built without the simulator (COSMOS_SIMULATOR=OFF); use "
                     "--source hardware --hardware FILE or --replay FILE");
  if (choice.hardware.empty())
    throw InputError(
        "cell: --source hardware needs --hardware FILE (see config/hardware-example.yaml)");
  const HardwareConfig hardware = read_hardware_config(choice.hardware);
  if (hardware.camera_simulated())
    throw InputError(choice.hardware +
                     ": names the simulated devices, but this cosmos was built without the "
                     "simulator (COSMOS_SIMULATOR=OFF)");
  auto source = std::make_unique<HardwareSource>(hardware, config.scanner);
  // The devices are tried once here, so that a cell without them stops at once in one line
  // naming the device, before its model base is read; the source itself starts only after
  // that load (command_cell.cpp), since a camera streams and an encoder counts from start().
  if (source->start() != SourceStatus::kOk) throw InputError(std::string(source->last_error()));
  source->stop();
  state_->hardware = source.get();
  state_->source = std::make_unique<StreamCheckedSource>(
      std::move(source), config.scanner.encoder_ticks_per_profile, config.stream_check);
  return *state_->source;
}

const StreamFaultLog* CellWorld::stream_faults() const {
  return state_->source ? &state_->source->faults() : nullptr;
}

CellModelBase CellWorld::load_model_base() const {
  const CellConfig& config = state_->config;
  if (config.cell.model_base.empty())
    throw InputError(config.file.string() +
                     ": cell.model_base: required in a build without the simulator, which "
                     "cannot build one (build it with `cosmos modelbase build` elsewhere)");
  return read_cell_model_base(config.cell.model_base, config);
}

std::vector<int> CellWorld::catalog_indices(const ModelBase& base) const {
  std::vector<int> indices;
  for (std::size_t part = 0; part < base.parts.size(); ++part)
    indices.push_back(static_cast<int>(part));
  return indices;
}

bool CellWorld::has_ground_truth() const { return false; }

std::string CellWorld::simulated_part_in(std::int64_t, std::int64_t) const { return ""; }

CellWorld::SimulatedTruth CellWorld::simulated_truth_of(const PartRecognition&,
                                                        const RigidTransform&, double) const {
  return {};
}

std::int64_t CellWorld::simulated_parts_placed() const { return 0; }

std::string CellWorld::describe_placed_part(std::int64_t) const { return ""; }

HardwareSource* CellWorld::hardware_source() const { return state_->hardware; }

void CellWorld::announce_pose_published() {
  if (state_->hardware) state_->hardware->announce_result();
}

}  // namespace cosmos::cli
