#pragma once
// Reads one map section of a YAML config (a `tracking:` or `lcm:` block of config/cell.yaml)
// key by key into typed fields: a key that is absent keeps the field's default; a key with
// the wrong type or out of its range, a key given twice, and a key that no read asked for
// throw InputError `file:LINE: section.key: reason` (YamlInputErrors).
#include <yaml-cpp/yaml.h>

#include <cstdint>
#include <set>
#include <string>

#include "core/io/yaml_input_errors.hpp"

namespace cosmos {

// A closed or open interval for messages like "must be in (0, 100], got 0".
struct NumberRange {
  double low;
  double high;
  bool low_open = false;
  bool high_open = false;

  bool contains(double value) const;
  std::string text() const;
};

class YamlSectionReader {
 public:
  // `node` undefined or null: the section is absent and every field keeps its default.
  // `name` is the dotted prefix of its keys in messages ("tracking", "cell.T_cell_scanner").
  YamlSectionReader(const YamlInputErrors& errors, const YAML::Node& node, std::string name);

  // The key's value (undefined when absent); marks the key as known.
  YAML::Node value(const std::string& key);
  bool has(const std::string& key) { return value(key).IsDefined(); }
  std::string dotted(const std::string& key) const { return name_ + "." + key; }

  void read(const std::string& key, int& field, int low, int high);
  void read(const std::string& key, std::int64_t& field, std::int64_t low, std::int64_t high);
  void read(const std::string& key, std::uint64_t& field);
  void read(const std::string& key, double& field, const NumberRange& range);
  void read(const std::string& key, bool& field);
  // A non-empty scalar.
  void read(const std::string& key, std::string& field);

  // Fails at the key's line (the section's when the key is absent).
  [[noreturn]] void fail(const std::string& key, const std::string& reason);

  // After every read: the first key (in file order) no read asked for is an error that lists
  // the known keys.
  void reject_unknown_keys() const;

 private:
  const YamlInputErrors& errors_;
  const YAML::Node node_;
  // A map was given. Checked instead of node_.IsMap(): yaml-cpp's absent keys are "zombie"
  // nodes on which every query but IsDefined() throws.
  bool is_map_ = false;
  std::string name_;
  std::set<std::string> known_;
};

// Reads `node` as a number in `range`, failing with `key` in the message.
double read_yaml_number(const YamlInputErrors& errors, const YAML::Node& node,
                        const std::string& key, const NumberRange& range);

}  // namespace cosmos
