#pragma once
// What `cosmos cell` runs with beyond its config file: the scanner source its options choose,
// the model base, the catalog index of each base part, and the simulated ground truth where
// the source has one. One interface, one implementation per build:
//   cell_world_simulated.cpp  the full build: the simulated source, real hardware or the
//                             hardware twins (a hardware YAML naming the simulated devices,
//                             config/hardware-sim.yaml), replays; the model base the config
//                             names, or one built and cached on first run
//   cell_world_hardware.cpp   a build without the simulator (-DCOSMOS_SIMULATOR=OFF, which
//                             links no Embree or Qhull): real hardware and replays;
//                             the model base the config names
// Errors throw InputError (one line).
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "apps/cell_model_base.hpp"
#include "realtime/cell/part_recognition.hpp"
#include "realtime/config/cell_config.hpp"
#include "realtime/sources/hardware_source.hpp"
#include "realtime/sources/scanner_source.hpp"
#include "realtime/sources/stream_fault_log.hpp"

namespace cosmos::cli {

struct CellSourceChoice {
  std::string source = "sim";  // sim | hardware
  std::string hardware;        // the hardware YAML
  std::string replay;          // an LCM log; wins over `source`
  int parts = -1;              // simulated parts; <= 0: sim_source.parts
  bool repeat = false;         // the simulated parts again and again (RepeatingSource)
};

class CellWorld {
 public:
  // Reads what the build needs besides the config (the part catalog, with the simulator).
  explicit CellWorld(const CellConfig& config);
  ~CellWorld();
  CellWorld(const CellWorld&) = delete;
  CellWorld& operator=(const CellWorld&) = delete;

  // The source the options choose, owned by this world; call once. Every source's stream is
  // checked (realtime/sources/stream_checked_source.hpp).
  ScannerSource& open_source(const CellSourceChoice& choice);
  CellModelBase load_model_base() const;
  // The open source's stream faults, for the recognizer (PartRecognitionContext).
  const StreamFaultLog* stream_faults() const;
  // Per part of `base`, its index in the catalog (-1 when the catalog lacks it).
  std::vector<int> catalog_indices(const ModelBase& base) const;

  // Whether the open source has simulated ground truth, and the name of the part it scanned
  // in profiles [first, last] ("" for none).
  bool has_ground_truth() const;
  std::string simulated_part_in(std::int64_t first_profile, std::int64_t last_profile) const;
  // The placed part a pose (or a rejection) stands for, found by its position on the belt
  // among the parts its profiles cross (so each of a blob's parts finds its own truth), and
  // for a pose of that part its ADD-S error; placed_index -1 when none. With --repeat, pass p's
  // parts are indices p x simulated_parts_placed() on.
  struct SimulatedTruth {
    int placed_index = -1;
    std::string name;
    double add_s_mm = -1;  // -1: not an OK pose of the true part
  };
  SimulatedTruth simulated_truth_of(const PartRecognition& recognition,
                                    const RigidTransform& T_cell_scanner, double mm_per_tick) const;
  std::int64_t simulated_parts_placed() const;  // 0 without ground truth
  // Placed part `index` (as in SimulatedTruth) for the summary: its name and the profiles
  // whose sheet crosses it, e.g. "cow, profiles 1200-1530"; "" without ground truth.
  std::string describe_placed_part(std::int64_t index) const;
  // The open source's hardware source (real devices or the twins), null for others.
  HardwareSource* hardware_source() const;
  // A pose went out: a hardware source (real or on the twins) pulses result_ready for it.
  // Safe from the publisher thread (HardwareSource::announce_result).
  void announce_pose_published();

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace cosmos::cli
