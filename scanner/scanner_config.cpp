#include "scanner/scanner_config.hpp"

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/input_error.hpp"
#include "core/io/yaml_input_errors.hpp"

namespace cosmos {
namespace {

namespace fs = std::filesystem;

struct Range {
  double low;
  double high;
  bool low_open;
  bool high_open;

  bool contains(double value) const {
    return (low_open ? value > low : value >= low) && (high_open ? value < high : value <= high);
  }
  std::string text() const {
    std::ostringstream out;
    out << (low_open ? "(" : "[") << low << ", " << high << (high_open ? ")" : "]");
    return out.str();
  }
};

// One numeric key of the section: its dotted name, range and field.
struct NumericKey {
  const char* name;
  Range range;
  double& (*real)(ScannerParameters&);
  int& (*integer)(ScannerParameters&);
};

#define COSMOS_REAL(key, field, low, high, low_open, high_open)          \
  NumericKey {                                                           \
    key, {low, high, low_open, high_open},                               \
        [](ScannerParameters& p) -> double& { return p.field; }, nullptr \
  }
#define COSMOS_INTEGER(key, field, low, high)                                                     \
  NumericKey {                                                                                    \
    key, {low, high, false, false}, nullptr, [](ScannerParameters& p) -> int& { return p.field; } \
  }

const std::vector<NumericKey>& numeric_keys() {
  static const std::vector<NumericKey> keys = {
      COSMOS_REAL("encoder_mm_per_tick", encoder_mm_per_tick, 0.0, 100.0, true, false),
      COSMOS_INTEGER("encoder_ticks_per_profile", encoder_ticks_per_profile, 1, 100000),
      COSMOS_REAL("line_rate_hz", line_rate_hz, 0.0, 1e6, true, false),
      COSMOS_REAL("triangulation_angle_deg", triangulation_angle_deg, 5.0, 75.0, false, false),
      COSMOS_REAL("camera_height_mm", camera_height_mm, 50.0, 5000.0, false, false),
      COSMOS_REAL("laser_height_mm", laser_height_mm, 50.0, 5000.0, false, false),
      COSMOS_REAL("field_of_view_mm", field_of_view_mm, 10.0, 5000.0, false, false),
      COSMOS_INTEGER("points_per_profile", points_per_profile, 16, 8192),
      COSMOS_INTEGER("sensor_width_px", sensor_width_px, 64, 8192),
      COSMOS_INTEGER("sensor_height_px", sensor_height_px, 16, 8192),
      COSMOS_INTEGER("roi_height_px", roi_height_px, 16, 8192),
      COSMOS_REAL("belt_row_fraction_of_roi", belt_row_fraction_of_roi, 0.0, 1.0, true, true),
      COSMOS_REAL("max_incidence_deg", max_incidence_deg, 0.0, 90.0, true, true),
      COSMOS_REAL("min_reflected_intensity", min_reflected_intensity, 0.0, 1.0, false, false),
      COSMOS_REAL("reflectivity", reflectivity, 0.0, 1.0, true, false),
      COSMOS_REAL("z_noise_mm", z_noise_mm, 0.0, 10.0, false, false),
      COSMOS_REAL("background_height_mm", background_height_mm, 0.0, 1000.0, false, false),
      COSMOS_INTEGER("camera.bit_depth", camera.bit_depth, 8, 16),
      COSMOS_REAL("camera.stripe_sigma_px", camera.stripe_sigma_px, 0.3, 20.0, false, false),
      COSMOS_REAL("camera.stripe_peak_level", camera.stripe_peak_level, 0.0, 1.0, true, false),
      COSMOS_REAL("camera.ambient_level", camera.ambient_level, 0.0, 1.0, false, true),
      COSMOS_REAL("camera.read_noise_level", camera.read_noise_level, 0.0, 0.5, false, false),
      COSMOS_REAL("camera.speckle_contrast", camera.speckle_contrast, 0.0, 1.0, false, false),
      COSMOS_REAL("camera.full_well_electrons", camera.full_well_electrons, 100.0, 1e7, false,
                  false),
      COSMOS_REAL("camera.threshold_level", camera.threshold_level, 0.0, 1.0, true, true),
      COSMOS_INTEGER("camera.background_frames", camera.background_frames, 1, 64),
  };
  return keys;
}

#undef COSMOS_REAL
#undef COSMOS_INTEGER

// The reason a value is out of range, or "" when it is acceptable. Cross-field rules live
// here too, reported at the key that breaks them.
std::string range_problem(const NumericKey& key, double value,
                          const ScannerParameters& parameters) {
  if (!std::isfinite(value) || !key.range.contains(value)) return "must be in " + key.range.text();
  const std::string name = key.name;
  if (name == "camera.bit_depth" && value != 8 && value != 10 && value != 12 && value != 16) {
    return "must be 8, 10, 12 or 16";
  }
  if (name == "roi_height_px" && value > parameters.sensor_height_px) {
    return "must not exceed sensor_height_px (" + std::to_string(parameters.sensor_height_px) + ")";
  }
  return {};
}

const NumericKey* find_key(const std::string& name) {
  for (const NumericKey& key : numeric_keys()) {
    if (name == key.name) return &key;
  }
  return nullptr;
}

void read_value(const YamlInputErrors& errors, const std::string& name, const YAML::Node& value,
                ScannerParameters& parameters,
                std::vector<std::pair<const NumericKey*, YAML::Node>>& numbers) {
  const std::string key = "scanner." + name;
  if (name == "laser_model") {
    const std::string text = value.IsScalar() ? value.Scalar() : "";
    if (text == "fan") {
      parameters.laser_model = LaserModel::kFan;
    } else if (text == "parallel") {
      parameters.laser_model = LaserModel::kParallel;
    } else {
      errors.fail(value, key, "expected fan or parallel, got " + describe_yaml_node(value));
    }
    return;
  }
  if (name == "seed") {
    std::uint64_t seed = 0;
    if (!value.IsScalar() || !YAML::convert<std::uint64_t>::decode(value, seed)) {
      errors.fail(value, key, "expected a non-negative integer, got " + describe_yaml_node(value));
    }
    parameters.seed = seed;
    return;
  }
  const NumericKey* numeric = find_key(name);
  if (numeric == nullptr) {
    std::string known = "laser_model, seed, camera";
    for (const NumericKey& k : numeric_keys()) {
      if (std::string(k.name).find('.') == std::string::npos) known += std::string(", ") + k.name;
    }
    errors.fail(value, key, "unknown key (known: " + known + ")");
  }
  if (numeric->integer != nullptr) {
    int number = 0;
    if (!value.IsScalar() || !YAML::convert<int>::decode(value, number)) {
      errors.fail(value, key, "expected an integer, got " + describe_yaml_node(value));
    }
    numeric->integer(parameters) = number;
  } else {
    double number = 0.0;
    if (!value.IsScalar() || !YAML::convert<double>::decode(value, number)) {
      errors.fail(value, key, "expected a number, got " + describe_yaml_node(value));
    }
    numeric->real(parameters) = number;
  }
  numbers.emplace_back(numeric, value);
}

void read_map(const YamlInputErrors& errors, const YAML::Node& map, const std::string& prefix,
              ScannerParameters& parameters,
              std::vector<std::pair<const NumericKey*, YAML::Node>>& numbers) {
  std::set<std::string> seen;
  for (const auto& item : map) {
    const std::string name =
        prefix + (item.first.IsScalar() ? item.first.Scalar() : describe_yaml_node(item.first));
    if (!seen.insert(name).second) errors.fail(item.first, "scanner." + name, "key given twice");
    if (prefix.empty() && name == "camera") {
      if (!item.second.IsMap())
        errors.fail(item.second, "scanner.camera",
                    "expected a map, got " + describe_yaml_node(item.second));
      read_map(errors, item.second, "camera.", parameters, numbers);
      continue;
    }
    read_value(errors, name, item.second, parameters, numbers);
  }
}

}  // namespace

ScannerParameters read_scanner_config(const fs::path& yaml_path,
                                      const ScannerParameters& defaults) {
  const YamlInputErrors errors(yaml_path);
  const YAML::Node root = errors.load_file("config file");
  ScannerParameters parameters = defaults;
  if (root.IsNull()) return parameters;
  if (!root.IsMap())
    errors.fail_line(root.Mark().line, "scanner", "the config must be a map of sections");
  const YAML::Node section = root["scanner"];
  if (!section.IsDefined() || section.IsNull()) return parameters;
  if (!section.IsMap())
    errors.fail(section, "scanner",
                "expected a map of settings, got " + describe_yaml_node(section));
  std::vector<std::pair<const NumericKey*, YAML::Node>> numbers;
  read_map(errors, section, "", parameters, numbers);
  // Ranges are checked once every key is read: cross-field rules see the final values.
  for (const auto& [key, node] : numbers) {
    ScannerParameters copy = parameters;
    const double value = key->integer != nullptr ? key->integer(copy) : key->real(copy);
    const std::string problem = range_problem(*key, value, parameters);
    if (!problem.empty())
      errors.fail(node, std::string("scanner.") + key->name, problem + ", got " + node.Scalar());
  }
  return parameters;
}

void check_scanner_parameters(const ScannerParameters& parameters) {
  for (const NumericKey& key : numeric_keys()) {
    ScannerParameters copy = parameters;
    const double value = key.integer != nullptr ? key.integer(copy) : key.real(copy);
    const std::string problem = range_problem(key, value, parameters);
    if (!problem.empty()) {
      std::ostringstream text;
      text << "scanner." << key.name << ": " << problem << ", got " << value;
      throw std::invalid_argument(text.str());
    }
  }
}

}  // namespace cosmos
