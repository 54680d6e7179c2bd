#include "scanner/scanner_config.hpp"

#include <yaml-cpp/yaml.h>

#include <optional>
#include <stdexcept>
#include <string>

#include "core/io/yaml_input_errors.hpp"
#include "core/io/yaml_parameter_reader.hpp"
#include "core/parameter_range_check.hpp"

namespace cosmos {
namespace {

namespace fs = std::filesystem;

// The rules between fields, beyond each field's own range: the reason and the dotted key
// (below scanner.) that breaks one, nullopt when none does.
struct RuleBroken {
  std::string key;
  std::string reason;  // ending in the value, ", got 9"
};

std::optional<RuleBroken> broken_rule(const ScannerParameters& p) {
  const int bits = p.camera.bit_depth;
  if (bits != 8 && bits != 10 && bits != 12 && bits != 16)
    return RuleBroken{"camera.bit_depth", "must be 8, 10, 12 or 16, got " + std::to_string(bits)};
  if (p.roi_height_px > p.sensor_height_px) {
    return RuleBroken{"roi_height_px", "must not exceed sensor_height_px (" +
                                           std::to_string(p.sensor_height_px) + "), got " +
                                           std::to_string(p.roi_height_px)};
  }
  return std::nullopt;
}

}  // namespace

void read_scanner_section(YamlSectionReader& section, ScannerParameters& parameters) {
  read_yaml_parameters(section, parameters);
  // Rules between keys see the final values, and are reported at the key that breaks them
  // (at its section when the file left it at its default).
  if (const auto broken = broken_rule(parameters)) {
    const std::size_t dot = broken->key.find('.');
    if (dot == std::string::npos) section.fail(broken->key, broken->reason);
    YamlSectionReader nested(section.errors(), section.value(broken->key.substr(0, dot)),
                             section.dotted(broken->key.substr(0, dot)));
    nested.fail(broken->key.substr(dot + 1), broken->reason);
  }
}

ScannerParameters read_scanner_config(const fs::path& yaml_path,
                                      const ScannerParameters& defaults) {
  const YamlInputErrors errors(yaml_path);
  const YAML::Node root = errors.load_file("config file");
  ScannerParameters parameters = defaults;
  if (root.IsNull()) return parameters;
  if (!root.IsMap())
    errors.fail_line(root.Mark().line, "scanner", "the config must be a map of sections");
  YamlSectionReader section(errors, root["scanner"], "scanner");
  read_scanner_section(section, parameters);
  return parameters;
}

void check_scanner_parameters(const ScannerParameters& parameters) {
  if (const auto problem = first_out_of_range(parameters, "scanner"))
    throw std::invalid_argument(*problem);
  if (const auto broken = broken_rule(parameters))
    throw std::invalid_argument("scanner." + broken->key + ": " + broken->reason);
}

}  // namespace cosmos
