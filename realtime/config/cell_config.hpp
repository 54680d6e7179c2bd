#pragma once
// The cell configuration (config/cell.yaml): one struct per section, every field with its
// default, so a missing key (or section) keeps it. Sections:
//   scanner:      ScannerParameters, parsed by scanner/scanner_config.hpp (read_scanner_config)
//   cell:         catalog, model base, the scanner's pose in the cell
//   conditioning: ConditioningParameters (realtime/loop/profile_conditioner.hpp)
//   tracking:     PartTrackerParameters (realtime/loop/part_tracker.hpp) and the longest part
//   lcm:          where and on which channels the cell publishes
//   realtime:     the acquisition thread's scheduling and the queue sizes
//   sim_source:   the parts the simulated source sends down the belt
// An unknown section or key, a value of the wrong type or out of its range throws InputError
// `file:LINE: section.key: reason`; a missing file or a YAML syntax error one line naming the
// file.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "core/rigid_transform.hpp"
#include "realtime/lcm/lcm_channels.hpp"
#include "realtime/loop/part_tracker.hpp"
#include "realtime/loop/profile_conditioner.hpp"
#include "realtime/rt/realtime_settings.hpp"
#include "scanner/scanner_model.hpp"

namespace cosmos {

struct CellSettings {
  // The part catalog. Relative paths (also this default) are resolved against the directory
  // of the config file, so the shipped config finds config/parts.yaml from anywhere.
  std::filesystem::path catalog = "parts.yaml";
  // The model base file; empty: the app picks its cache path. Relative: as catalog.
  std::filesystem::path model_base;
  int model_views = 320;  // view-sphere directions per part (thesis §4.5), 1..320
  // The scanner frame (scanner/scanner_model.hpp: x across the belt, y along travel, z up, origin
  // on the belt in the laser sheet) in the cell (robot) frame: x_cell = R x_scanner + t. In
  // YAML, rotation_deg [rx, ry, rz] gives R = Rz Ry Rx (Eq. 6.2 order) and translation_mm t.
  // Default identity: the cell frame is the scanner frame until the cell is calibrated.
  RigidTransform T_cell_scanner;
};

struct TrackingSettings {
  PartTrackerParameters tracker = cell_part_tracking();
  // Longer parts are cut (their extra rows dropped and counted): sets IncrementalCosmos's
  // max_rows, see CellConfig::max_part_rows().
  double max_part_length_mm = 300.0;
};

struct LcmSettings {
  std::string url = kDefaultLcmUrl;
  std::string pose_channel = kPoseChannel;
  std::string status_channel = kStatusChannel;
  std::string profile_channel = kProfileChannel;
  bool publish_profiles = false;  // every profile on profile_channel, for record/replay
  double status_period_s = 1.0;   // cell_status_t period

  LcmChannelNames channels() const { return {pose_channel, status_channel, profile_channel}; }
};

struct RealtimeQueueSettings {
  RealtimeSettings thread;        // the acquisition thread: SCHED_FIFO, cpu, mlockall
  int profile_ring_slots = 4096;  // loop -> publisher recorded profiles (1.6 s at 2,500/s)
  int part_builders = 8;          // parts in flight (ScanLoopSettings::builders)
  int part_queue_slots = 8;       // loop -> recognizer completed parts
  int pose_queue_slots = 32;      // recognizer -> publisher poses
};

enum class SimPoseMode : std::uint8_t {
  kRandom,   // uniformly random orientation (sim/part_pose.hpp random_rotation)
  kResting,  // settled on a face of the convex hull (resting_rotation)
};

struct SimSourceSettings {
  int parts = 20;             // parts sent down the belt, then the source ends
  std::uint64_t seed = 7;     // the order, poses and placement of the parts
  double part_gap_mm = 40.0;  // belt between consecutive parts' bounding boxes
  SimPoseMode pose = SimPoseMode::kRandom;
  // Catalog part names the source picks from; empty: every catalog part. The names are
  // checked against the catalog by whoever loads it.
  std::vector<std::string> part_names;
};

struct CellConfig {
  std::filesystem::path file;  // the file this was read from (empty: all defaults)
  ScannerParameters scanner;
  CellSettings cell;
  ConditioningParameters conditioning;
  TrackingSettings tracking;
  LcmSettings lcm;
  RealtimeQueueSettings realtime;
  SimSourceSettings sim_source;

  // Rows (profiles) of the longest part: max_part_length_mm over the belt step per profile.
  int max_part_rows() const;
};

CellConfig load_cell_config(const std::filesystem::path& yaml_path);

}  // namespace cosmos
