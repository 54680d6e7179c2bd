#include "core/io/yaml_section_reader.hpp"

#include <array>
#include <climits>
#include <cstdint>
#include <utility>

namespace cosmos {

double read_yaml_number(const YamlInputErrors& errors, const YAML::Node& node,
                        const std::string& key, const Range& range) {
  double number = 0.0;
  if (!node.IsScalar() || !YAML::convert<double>::decode(node, number)) {
    errors.fail(node, key, "expected a number, got " + describe_yaml_node(node));
  }
  if (!range.contains(number)) {
    errors.fail(node, key, "must be in " + range.text() + ", got " + node.Scalar());
  }
  return number;
}

YamlSectionReader::YamlSectionReader(const YamlInputErrors& errors, const YAML::Node& node,
                                     std::string name)
    : errors_(errors), node_(node), name_(std::move(name)) {
  if (!node_.IsDefined() || node_.IsNull()) return;
  if (!node_.IsMap()) {
    errors_.fail(node_, name_, "expected a map, got " + describe_yaml_node(node_));
  }
  is_map_ = true;
  // yaml-cpp keeps both entries of a repeated key; the second would silently lose.
  std::set<std::string> seen;
  for (const auto& item : node_) {
    if (!item.first.IsScalar()) {
      errors_.fail(item.first, name_, "expected a key, got " + describe_yaml_node(item.first));
    }
    if (!seen.insert(item.first.Scalar()).second) {
      errors_.fail(item.first, dotted(item.first.Scalar()), std::string(kind()) + " given twice");
    }
  }
}

YAML::Node YamlSectionReader::value(const std::string& key) {
  known_.insert(key);
  if (!is_map_) return YAML::Node(YAML::NodeType::Undefined);
  return node_[key];
}

void YamlSectionReader::read(const std::string& key, int& field, int low, int high) {
  std::int64_t wide = field;
  read(key, wide, low, high);
  field = static_cast<int>(wide);
}

void YamlSectionReader::read(const std::string& key, std::int64_t& field, std::int64_t low,
                             std::int64_t high) {
  const YAML::Node node = value(key);
  if (!node.IsDefined()) return;
  std::int64_t number = 0;
  if (!node.IsScalar() || !YAML::convert<std::int64_t>::decode(node, number)) {
    errors_.fail(node, dotted(key), "expected an integer, got " + describe_yaml_node(node));
  }
  if (number < low || number > high) {
    errors_.fail(node, dotted(key),
                 "must be in [" + std::to_string(low) + ", " + std::to_string(high) + "], got " +
                     node.Scalar());
  }
  field = number;
}

void YamlSectionReader::read(const std::string& key, std::uint64_t& field) {
  const YAML::Node node = value(key);
  if (!node.IsDefined()) return;
  std::uint64_t number = 0;
  // yaml-cpp's unsigned conversion wraps "-1" around; a leading minus is rejected first.
  if (!node.IsScalar() || node.Scalar().starts_with('-') ||
      !YAML::convert<std::uint64_t>::decode(node, number)) {
    errors_.fail(node, dotted(key),
                 "expected a non-negative integer, got " + describe_yaml_node(node));
  }
  field = number;
}

void YamlSectionReader::read(const std::string& key, double& field, const Range& range) {
  const YAML::Node node = value(key);
  if (node.IsDefined()) field = read_yaml_number(errors_, node, dotted(key), range);
}

void YamlSectionReader::read(const std::string& key, int& field, const Range& range) {
  std::int64_t wide = field;
  // Without a declared range: every int.
  read(key, wide, range.bounded() ? range : Range{INT_MIN, INT_MAX});
  field = static_cast<int>(wide);
}

void YamlSectionReader::read(const std::string& key, std::int64_t& field, const Range& range) {
  const YAML::Node node = value(key);
  if (!node.IsDefined()) return;
  std::int64_t number = 0;
  if (!node.IsScalar() || !YAML::convert<std::int64_t>::decode(node, number)) {
    errors_.fail(node, dotted(key), "expected an integer, got " + describe_yaml_node(node));
  }
  if (range.bounded() && !range.contains(static_cast<double>(number))) {
    errors_.fail(node, dotted(key), "must be in " + range.text() + ", got " + node.Scalar());
  }
  field = number;
}

void YamlSectionReader::read(const std::string& key, bool& field) {
  const YAML::Node node = value(key);
  if (!node.IsDefined()) return;
  bool flag = false;
  if (!node.IsScalar() || !YAML::convert<bool>::decode(node, flag)) {
    errors_.fail(node, dotted(key), "expected true or false, got " + describe_yaml_node(node));
  }
  field = flag;
}

void YamlSectionReader::read(const std::string& key, std::string& field) {
  const YAML::Node node = value(key);
  if (!node.IsDefined()) return;
  if (!node.IsScalar() || node.Scalar().empty()) {
    errors_.fail(node, dotted(key), "expected a non-empty string, got " + describe_yaml_node(node));
  }
  field = node.Scalar();
}

void YamlSectionReader::read(const std::string& key, std::filesystem::path& field) {
  const YAML::Node node = value(key);
  if (!node.IsDefined() || node.IsNull()) return;
  if (!node.IsScalar()) {
    errors_.fail(node, dotted(key), "expected a path, got " + describe_yaml_node(node));
  }
  field = node.Scalar();
}

void YamlSectionReader::read(const std::string& key, std::vector<std::string>& field) {
  const YAML::Node node = value(key);
  if (!node.IsDefined() || node.IsNull()) return;
  if (!node.IsSequence()) {
    errors_.fail(node, dotted(key), "expected a list of names, got " + describe_yaml_node(node));
  }
  std::vector<std::string> names;
  for (const YAML::Node& name : node) {
    if (!name.IsScalar() || name.Scalar().empty()) {
      errors_.fail(name, dotted(key), "expected a name, got " + describe_yaml_node(name));
    }
    for (const std::string& earlier : names) {
      if (earlier == name.Scalar()) errors_.fail(name, dotted(key), earlier + " given twice");
    }
    names.push_back(name.Scalar());
  }
  field = std::move(names);
}

namespace {

// A flow or block list of exactly three numbers, each in `range`.
std::array<double, 3> read_triple(YamlSectionReader& section, const std::string& key,
                                  const Range& range) {
  const YAML::Node node = section.value(key);
  if (!node.IsSequence() || node.size() != 3) {
    const std::string got =
        node.IsSequence() ? "a list of " + std::to_string(node.size()) : describe_yaml_node(node);
    section.fail(key, "expected a list of 3 numbers, got " + got);
  }
  std::array<double, 3> values{};
  for (std::size_t k = 0; k < 3; ++k) {
    values[k] = read_yaml_number(section.errors(), node[k], section.dotted(key), range);
  }
  return values;
}

}  // namespace

void YamlSectionReader::read(const std::string& key, RigidTransform& field) {
  YamlSectionReader section(errors_, value(key), dotted(key));
  if (section.has("rotation_deg")) {
    const auto angles = read_triple(section, "rotation_deg", Range{-360, 360});
    field.rotation = rotation_from_xyz_angles_deg(angles[0], angles[1], angles[2]);
  }
  if (section.has("translation_mm")) {
    const auto t = read_triple(section, "translation_mm", Range{-1e5, 1e5});
    field.translation_mm = Eigen::Vector3d(t[0], t[1], t[2]);
  }
  section.reject_unknown_keys();
}

void YamlSectionReader::refuse_retired(const std::string& key, const std::string& replacement) {
  if (!is_map_) return;
  const YAML::Node node = node_[key];
  if (node.IsDefined()) errors_.fail(node, dotted(key), "replaced by " + replacement);
}

void YamlSectionReader::fail(const std::string& key, const std::string& reason) {
  const YAML::Node node = value(key);
  errors_.fail(node.IsDefined() ? node : node_, dotted(key), reason);
}

void YamlSectionReader::reject_unknown_keys() const {
  if (!is_map_) return;
  for (const auto& item : node_) {
    if (known_.count(item.first.Scalar()) > 0) continue;
    std::string list;
    for (const std::string& key : known_) list += (list.empty() ? "" : ", ") + key;
    errors_.fail(item.first, dotted(item.first.Scalar()),
                 "unknown " + std::string(kind()) + " (known: " + list + ")");
  }
}

}  // namespace cosmos
