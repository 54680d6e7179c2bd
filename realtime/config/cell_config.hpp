#pragma once
// The cell configuration (config/cell.yaml), read once into the settings structs the cell's
// parts take as they are. Every field has its default, so a missing key (or section) keeps it;
// each struct's visit() lists its keys with their ranges (docs/parameters.md is generated from
// them). Sections:
//   scanner:      ScannerParameters (scanner/scanner_model.hpp)
//   cell:         catalog, model base, the scanner's pose in the cell
//   conditioning: ConditioningParameters (scanner/conditioning_parameters.hpp)
//   tracking:     PartTrackerParameters (realtime/loop/part_tracker.hpp) and the longest part
//   lcm:          where and on which channels the cell publishes
//   realtime:     the acquisition thread's scheduling and the queue sizes
//   sim_source:   SimulatedSourceSettings (realtime/config/sim_source_settings.hpp)
//   web:          the live web view (realtime/config/web_view_settings.hpp)
//   stream_check: StreamCheckSettings (realtime/sources/stream_checked_source.hpp)
//   faults:       FaultInjectionSettings (realtime/sources/fault_injection_settings.hpp)
// The cell's COSMOS parameters are not here: it takes those its model base was built with.
// An unknown section or key, a retired key, a value of the wrong type or out of its range
// throws InputError `file:LINE: section.key: reason`; a missing file or a YAML syntax error one
// line naming the file.
#include <filesystem>
#include <string>

#include "core/modelbase/model_surface.hpp"
#include "core/parameter_visitor.hpp"
#include "core/rigid_transform.hpp"
#include "realtime/cell/cell_runner.hpp"
#include "realtime/config/sim_source_settings.hpp"
#include "realtime/config/web_view_settings.hpp"
#include "realtime/lcm/lcm_channels.hpp"
#include "realtime/loop/part_tracker.hpp"
#include "realtime/loop/scan_loop.hpp"
#include "realtime/rt/realtime_settings.hpp"
#include "realtime/sources/fault_injection_settings.hpp"
#include "realtime/sources/stream_checked_source.hpp"
#include "scanner/conditioning_parameters.hpp"
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
  // The parts lie on the belt (not propped on each other): recognition refuses a pose that
  // would float above the belt or sink into it; and in their stable poses (fed one by one, not
  // tumbled): nor one that leans off every stable face
  // (core/recognition/resting_pose_search.hpp). Both need the belt plane conditioning removes
  // to be the real one (docs/calibration.md).
  bool parts_touch_belt = true;
  bool parts_rest = false;

  template <class Visitor>
  void visit(Visitor& v) {
    v("catalog", catalog, "the part catalog; relative: to the config file's directory");
    v("model_base", model_base, "the model base file; empty: built once and cached");
    v("model_views", model_views, "view-sphere directions per part (§4.5: 320)", Range{1, 320});
    v("T_cell_scanner", T_cell_scanner,
      "scanner frame in the cell frame: rotation_deg [rx, ry, rz] (R = Rz Ry Rx), "
      "translation_mm [x, y, z]");
    v("parts_touch_belt", parts_touch_belt,
      "parts lie on the belt: a pose floating above it or sunk into it is refused");
    v("parts_rest", parts_rest,
      "and in their stable poses: a pose leaning off every stable face is refused");
  }
};

struct TrackingSettings {
  PartTrackerParameters tracker = cell_part_tracking();
  // Longer parts are cut (their extra rows dropped and counted): sets IncrementalCosmos's
  // max_rows, see CellConfig::max_part_rows().
  double max_part_length_mm = 300.0;

  template <class Visitor>
  void visit(Visitor& v) {
    v.fields(tracker);
    v("max_part_length_mm", max_part_length_mm,
      "longer blobs are cut (their rest reported as ERROR); parts touching end to end are one "
      "blob, mm",
      Range::above(0, 1e4));
  }
};

struct LcmSettings {
  std::string url = kDefaultLcmUrl;
  std::string pose_channel = kPoseChannel;
  std::string status_channel = kStatusChannel;
  std::string profile_channel = kProfileChannel;
  CellPublishSettings publishing;  // profiles and status besides the poses (CellRunSettings)

  LcmChannelNames channels() const { return {pose_channel, status_channel, profile_channel}; }

  template <class Visitor>
  void visit(Visitor& v) {
    v("url", url, "LCM network; ttl=0 keeps the traffic on this host");
    v("pose_channel", pose_channel, "part_pose_t, one per part");
    v("status_channel", status_channel, "cell_status_t, every status_period_s");
    v("profile_channel", profile_channel, "range_profile_t, for record and replay");
    v.fields(publishing);
  }
};

// The structs the cell's threads take as they are: the acquisition thread and the rings
// between threads (CellRunSettings::threads), the scan loop's builders and its queue to the
// recognizer (ScanLoopSettings::parts).
struct RealtimeQueueSettings {
  CellThreadSettings threads;
  PartQueueSettings parts;
  // The recognizer thread's bound on unpacked model surfaces
  // (RecognitionParameters::surfaces).
  ModelSurfaceCacheParameters recognizer_surfaces;

  template <class Visitor>
  void visit(Visitor& v) {
    v.fields(threads);
    v.fields(parts);
    v.fields(recognizer_surfaces);
  }
};

struct CellConfig {
  std::filesystem::path file;  // the file this was read from (empty: all defaults)
  ScannerParameters scanner;
  CellSettings cell;
  ConditioningParameters conditioning;
  TrackingSettings tracking;
  LcmSettings lcm;
  RealtimeQueueSettings realtime;
  SimulatedSourceSettings sim_source;
  WebViewSettings web;
  StreamCheckSettings stream_check;
  FaultInjectionSettings faults;

  // Rows (profiles) of the longest part: max_part_length_mm over the belt step per profile.
  int max_part_rows() const;

  template <class Visitor>
  void visit(Visitor& v) {
    v("scanner", scanner, "the scanner and conveyor (scanner/scanner_model.hpp)");
    v("cell", cell, "the catalog, the model base and the scanner's pose in the cell");
    v("conditioning", conditioning,
      "profiles onto the COSMOS grid (realtime/loop/profile_conditioner.hpp)");
    v("tracking", tracking, "parts on the belt (realtime/loop/part_tracker.hpp)");
    v("lcm", lcm, "where the cell publishes");
    v("realtime", realtime, "the acquisition thread and the queues between threads");
    v("sim_source", sim_source, "the simulated source (sim/source/simulated_source.hpp)");
    v("web", web, "the live web view (realtime/web/web_view.hpp)");
    v("stream_check", stream_check,
      "what a source's stream may do before it counts as a fault "
      "(realtime/sources/stream_checked_source.hpp)");
    v("faults", faults, "faults the simulated cell injects into itself (all off by default)");
  }
};

CellConfig load_cell_config(const std::filesystem::path& yaml_path);

}  // namespace cosmos
