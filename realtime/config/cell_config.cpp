#include "realtime/config/cell_config.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <set>

#include "core/input_error.hpp"
#include "core/io/yaml_input_errors.hpp"
#include "core/io/yaml_section_reader.hpp"
#include "scanner/scanner_config.hpp"

namespace cosmos {
namespace {

namespace fs = std::filesystem;

// `scanner` is parsed by sim/scanner_config.
constexpr std::array<const char*, 7> kSections = {"scanner", "cell",     "conditioning", "tracking",
                                                  "lcm",     "realtime", "sim_source"};

// Profiles wider than this are a typo (65,536 columns of 0.4 mm are 26 m of belt).
constexpr double kMaxGridColumns = 65536.0;

void check_sections(const YAML::Node& root, const YamlInputErrors& errors) {
  std::set<std::string> seen;
  for (const auto& item : root) {
    const std::string name = item.first.IsScalar() ? item.first.Scalar() : "";
    bool known = false;
    for (const char* section : kSections) known = known || name == section;
    if (!known) {
      std::string list;
      for (const char* section : kSections)
        list += (list.empty() ? "" : ", ") + std::string(section);
      errors.fail(item.first, name.empty() ? describe_yaml_node(item.first) : name,
                  "unknown section (known: " + list + ")");
    }
    if (!seen.insert(name).second) errors.fail(item.first, name, "section given twice");
  }
}

fs::path resolve(const fs::path& path, const fs::path& config_file) {
  return path.empty() || path.is_absolute() ? path : config_file.parent_path() / path;
}

// A flow or block list of exactly three numbers, each in `range`.
std::array<double, 3> read_triple(YamlSectionReader& section, const YamlInputErrors& errors,
                                  const std::string& key, const NumberRange& range) {
  const YAML::Node node = section.value(key);
  if (!node.IsSequence() || node.size() != 3) {
    const std::string got =
        node.IsSequence() ? "a list of " + std::to_string(node.size()) : describe_yaml_node(node);
    section.fail(key, "expected a list of 3 numbers, got " + got);
  }
  std::array<double, 3> values{};
  for (std::size_t k = 0; k < 3; ++k) {
    values[k] = read_yaml_number(errors, node[k], section.dotted(key), range);
  }
  return values;
}

void read_transform(YamlSectionReader& cell, const YamlInputErrors& errors, RigidTransform& T) {
  YamlSectionReader section(errors, cell.value("T_cell_scanner"), cell.dotted("T_cell_scanner"));
  if (section.has("rotation_deg")) {
    const auto angles = read_triple(section, errors, "rotation_deg", {-360.0, 360.0});
    T.rotation = rotation_from_xyz_angles_deg(angles[0], angles[1], angles[2]);
  }
  if (section.has("translation_mm")) {
    const auto t = read_triple(section, errors, "translation_mm", {-1e5, 1e5});
    T.translation_mm = Eigen::Vector3d(t[0], t[1], t[2]);
  }
  section.reject_unknown_keys();
}

void read_cell(const YAML::Node& node, const YamlInputErrors& errors, const fs::path& file,
               CellSettings& cell) {
  YamlSectionReader section(errors, node, "cell");
  std::string catalog = cell.catalog.string();
  section.read("catalog", catalog);
  cell.catalog = resolve(catalog, file);
  const YAML::Node model_base = section.value("model_base");
  if (model_base.IsDefined() && !model_base.IsNull()) {
    if (!model_base.IsScalar()) {
      section.fail("model_base", "expected a path, got " + describe_yaml_node(model_base));
    }
    cell.model_base = model_base.Scalar();
  }
  cell.model_base = resolve(cell.model_base, file);
  section.read("model_views", cell.model_views, 1, 320);
  read_transform(section, errors, cell.T_cell_scanner);
  section.reject_unknown_keys();
}

void read_conditioning(const YAML::Node& node, const YamlInputErrors& errors,
                       ConditioningParameters& p) {
  YamlSectionReader section(errors, node, "conditioning");
  section.read("grid_mm", p.grid_mm, {0.0, 100.0, true});
  section.read("x_min_mm", p.x_min_mm, {-1e5, 1e5});
  section.read("x_max_mm", p.x_max_mm, {-1e5, 1e5});
  section.read("belt_height_mm", p.belt_height_mm, {-1e4, 1e4});
  section.read("belt_slope_x", p.belt_slope_x, {-10.0, 10.0});
  section.read("height_threshold_mm", p.height_threshold_mm, {0.0, 1e4});
  section.read("depth_jump_mm", p.depth_jump_mm, {0.0, 1e4, true});
  section.reject_unknown_keys();
  // Cross-field rules, reported at a key the file gave (the section when it gave neither).
  if (p.x_max_mm <= p.x_min_mm) {
    section.fail(section.has("x_max_mm") ? "x_max_mm" : "x_min_mm",
                 "x_max_mm must exceed x_min_mm");
  }
  if ((p.x_max_mm - p.x_min_mm) / p.grid_mm > kMaxGridColumns) {
    section.fail("grid_mm", "gives more than 65536 columns across [x_min_mm, x_max_mm)");
  }
}

void read_tracking(const YAML::Node& node, const YamlInputErrors& errors, TrackingSettings& t) {
  YamlSectionReader section(errors, node, "tracking");
  section.read("max_open_parts", t.tracker.max_open_parts, 1, 4096);
  section.read("max_runs_per_row", t.tracker.max_runs_per_row, 1, 65536);
  section.read("link_gap_columns", t.tracker.link_gap_columns, 0, 65536);
  section.read("link_gap_rows", t.tracker.link_gap_rows, 0, 65536);
  section.read("min_pixels", t.tracker.min_pixels, 0, std::int64_t{1} << 40);
  section.read("max_part_length_mm", t.max_part_length_mm, {0.0, 1e4, true});
  section.reject_unknown_keys();
}

void read_lcm(const YAML::Node& node, const YamlInputErrors& errors, LcmSettings& lcm) {
  YamlSectionReader section(errors, node, "lcm");
  section.read("url", lcm.url);
  section.read("pose_channel", lcm.pose_channel);
  section.read("status_channel", lcm.status_channel);
  section.read("profile_channel", lcm.profile_channel);
  section.read("publish_profiles", lcm.publish_profiles);
  section.read("status_period_s", lcm.status_period_s, {0.0, 3600.0, true});
  section.reject_unknown_keys();
}

void read_realtime(const YAML::Node& node, const YamlInputErrors& errors,
                   RealtimeQueueSettings& rt) {
  YamlSectionReader section(errors, node, "realtime");
  section.read("sched_fifo_priority", rt.thread.sched_fifo_priority, 0, 99);
  section.read("cpu", rt.thread.cpu, -1, 1023);  // CPU_SETSIZE - 1
  section.read("lock_memory", rt.thread.lock_memory);
  section.read("profile_ring_slots", rt.profile_ring_slots, 1, 1 << 20);
  section.read("part_builders", rt.part_builders, 1, 64);
  section.read("part_queue_slots", rt.part_queue_slots, 1, 1024);
  section.read("pose_queue_slots", rt.pose_queue_slots, 1, 4096);
  section.reject_unknown_keys();
}

void read_sim_source(const YAML::Node& node, const YamlInputErrors& errors,
                     SimSourceSettings& sim) {
  YamlSectionReader section(errors, node, "sim_source");
  section.read("parts", sim.parts, 0, 1000000);
  section.read("seed", sim.seed);
  section.read("part_gap_mm", sim.part_gap_mm, {0.0, 1e4});
  const YAML::Node pose = section.value("pose");
  if (pose.IsDefined()) {
    const std::string text = pose.IsScalar() ? pose.Scalar() : "";
    if (text == "random") {
      sim.pose = SimPoseMode::kRandom;
    } else if (text == "resting") {
      sim.pose = SimPoseMode::kResting;
    } else {
      section.fail("pose", "expected random or resting, got " + describe_yaml_node(pose));
    }
  }
  const YAML::Node names = section.value("part_names");
  if (names.IsDefined() && !names.IsNull()) {
    if (!names.IsSequence()) {
      section.fail("part_names", "expected a list of part names, got " + describe_yaml_node(names));
    }
    sim.part_names.clear();
    for (const YAML::Node& name : names) {
      if (!name.IsScalar() || name.Scalar().empty()) {
        errors.fail(name, "sim_source.part_names",
                    "expected a part name, got " + describe_yaml_node(name));
      }
      for (const std::string& earlier : sim.part_names) {
        if (earlier == name.Scalar())
          errors.fail(name, "sim_source.part_names", earlier + " given twice");
      }
      sim.part_names.push_back(name.Scalar());
    }
  }
  section.reject_unknown_keys();
}

}  // namespace

int CellConfig::max_part_rows() const {
  return std::max(
      1, static_cast<int>(std::ceil(tracking.max_part_length_mm / scanner.profile_step_mm())));
}

CellConfig load_cell_config(const fs::path& yaml_path) {
  const YamlInputErrors errors(yaml_path);
  const YAML::Node root = errors.load_file("config file");
  CellConfig config;
  config.file = yaml_path;
  if (!root.IsNull() && !root.IsMap()) {
    errors.fail_line(root.Mark().line, "config",
                     "expected a map of sections, got " + describe_yaml_node(root));
  }
  if (root.IsMap()) check_sections(root, errors);
  config.scanner = read_scanner_config(yaml_path);
  // A null root (an empty file) reads every section as absent: all defaults.
  const auto section = [&root](const char* name) {
    return root.IsMap() ? root[name] : YAML::Node(YAML::NodeType::Undefined);
  };
  read_cell(section("cell"), errors, yaml_path, config.cell);
  read_conditioning(section("conditioning"), errors, config.conditioning);
  read_tracking(section("tracking"), errors, config.tracking);
  read_lcm(section("lcm"), errors, config.lcm);
  read_realtime(section("realtime"), errors, config.realtime);
  read_sim_source(section("sim_source"), errors, config.sim_source);
  return config;
}

}  // namespace cosmos
