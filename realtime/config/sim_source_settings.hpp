#pragma once
// The settings of the simulated cell's conveyor and source (sim/source/), declared here
// so that the cell config's `sim_source:` section reads into the very struct the source takes
// (realtime/ does not see sim/; sim/source sees realtime/).
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "core/parameter_visitor.hpp"
#include "scanner/scanner_model.hpp"
#include "scanner/simulated_mounting.hpp"

namespace cosmos {

enum class PoseMode : std::uint8_t {
  kRandom,   // uniform over SO(3) (sim/part_pose.hpp random_rotation)
  kResting,  // settled on a face of its convex hull (resting_rotation)
};

inline std::span<const ParameterChoice<PoseMode>> parameter_choices(PoseMode) {
  static constexpr ParameterChoice<PoseMode> kChoices[] = {{PoseMode::kRandom, "random"},
                                                           {PoseMode::kResting, "resting"}};
  return kChoices;
}

// The conveyor's parts (sim/source/simulated_conveyor.hpp): what goes down the belt, for the
// simulated source and the hardware twins alike.
struct SimulatedConveyorSettings {
  int parts = 20;             // parts in the stream, >= 1
  std::uint64_t seed = 7;     // part sequence, poses and offsets
  double part_gap_mm = 40.0;  // empty belt between bounding boxes, and before and after
  // Layout (sim/source/part_layout.hpp): above part_gap_mm, each gap is drawn uniformly from
  // [part_gap_mm, part_gap_max_mm]; side_by_side puts the parts in pairs across the belt,
  // across_gap_mm apart (0: touching).
  double part_gap_max_mm = 0.0;
  int group_size = 1;  // parts per group touching end to end; groups part_gap_mm apart
  bool side_by_side = false;
  double across_gap_mm = 0.0;
  PoseMode pose = PoseMode::kRandom;
  // false: every part centred across the belt (x = 0); true: a seeded x offset that keeps
  // its bounding box at least edge_margin_mm inside the field of view at belt height.
  bool random_x_offset = false;
  double edge_margin_mm = 8.0;
  // The parts to draw from, uniformly; empty = all. The names are checked against the
  // catalog by whoever loads it.
  std::vector<std::string> part_names;

  template <class Visitor>
  void visit(Visitor& v) {
    v("parts", parts, "parts sent down the belt, then the source ends", Range{1, 1000000});
    v("seed", seed, "the order, poses and placement of the parts");
    v("part_gap_mm", part_gap_mm,
      "belt between consecutive parts' bounding boxes, mm (0: touching)", Range{0, 1e4});
    v("part_gap_max_mm", part_gap_max_mm,
      "above part_gap_mm: each gap seeded from [part_gap_mm, part_gap_max_mm], mm", Range{0, 1e4});
    v("group_size", group_size, "parts per group touching end to end, groups part_gap_mm apart",
      Range{1, 1000});
    v("side_by_side", side_by_side, "parts in pairs across the belt");
    v("across_gap_mm", across_gap_mm, "between a pair's bounding boxes across the belt, mm",
      Range{0, 1e3});
    v("pose", pose, "random: any orientation; resting: settled on a face of its hull");
    v("random_x_offset", random_x_offset, "false: parts centred across the belt");
    v("edge_margin_mm", edge_margin_mm, "random offsets keep the part this far inside, mm",
      Range{0, 1e4});
    v("part_names", part_names, "catalog parts to draw from; empty: all");
  }
};

// The `sim_source:` section: the conveyor, how the simulated source scans it, and the true
// geometry the hardware twins render through (scanner/simulated_mounting.hpp; the source's
// own modes deliver the design's profiles and ignore it).
struct SimulatedSourceSettings : SimulatedConveyorSettings {
  ScanMode mode = ScanMode::kProfile;
  SimulatedMounting truth;

  template <class Visitor>
  void visit(Visitor& v) {
    SimulatedConveyorSettings::visit(v);
    v("mode", mode, "profile: calibrated profiles; camera: sensor frames and stripe extraction");
    v("truth", truth, "the simulated cell's true geometry, where it departs from the design");
  }
};

}  // namespace cosmos
