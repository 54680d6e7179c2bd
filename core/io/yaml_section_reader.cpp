#include "core/io/yaml_section_reader.hpp"

#include <cmath>
#include <sstream>
#include <utility>

namespace cosmos {

bool NumberRange::contains(double value) const {
  return std::isfinite(value) && (low_open ? value > low : value >= low) &&
         (high_open ? value < high : value <= high);
}

std::string NumberRange::text() const {
  std::ostringstream out;
  out << (low_open ? "(" : "[") << low << ", " << high << (high_open ? ")" : "]");
  return out.str();
}

double read_yaml_number(const YamlInputErrors& errors, const YAML::Node& node,
                        const std::string& key, const NumberRange& range) {
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
      errors_.fail(item.first, dotted(item.first.Scalar()), "key given twice");
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

void YamlSectionReader::read(const std::string& key, double& field, const NumberRange& range) {
  const YAML::Node node = value(key);
  if (node.IsDefined()) field = read_yaml_number(errors_, node, dotted(key), range);
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
    errors_.fail(item.first, dotted(item.first.Scalar()), "unknown key (known: " + list + ")");
  }
}

}  // namespace cosmos
