#pragma once
// Reads one map section of a YAML config (a `tracking:` or `lcm:` block of config/cell.yaml)
// key by key into typed fields: a key that is absent keeps the field's default; a key with
// the wrong type or out of its range, a key given twice, a retired key (naming its
// replacement) and a key that no read asked for throw InputError `file:LINE: section.key:
// reason` (YamlInputErrors). yaml_parameter_reader.hpp drives it from a struct's visit() list.
#include <yaml-cpp/yaml.h>

#include <cstdint>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "core/io/yaml_input_errors.hpp"
#include "core/parameter_visitor.hpp"
#include "core/rigid_transform.hpp"

namespace cosmos {

class YamlSectionReader {
 public:
  // `node` undefined or null: the section is absent and every field keeps its default.
  // `name` is the dotted prefix of its keys in messages ("tracking", "cell.T_cell_scanner");
  // empty for a file's root, whose keys are sections.
  YamlSectionReader(const YamlInputErrors& errors, const YAML::Node& node, std::string name);

  // The key's value (undefined when absent); marks the key as known.
  YAML::Node value(const std::string& key);
  bool has(const std::string& key) { return value(key).IsDefined(); }
  std::string dotted(const std::string& key) const {
    return name_.empty() ? key : name_ + "." + key;
  }
  const YamlInputErrors& errors() const { return errors_; }

  void read(const std::string& key, int& field, int low, int high);
  void read(const std::string& key, std::int64_t& field, std::int64_t low, std::int64_t high);
  void read(const std::string& key, std::uint64_t& field);
  void read(const std::string& key, double& field, const Range& range);
  // Integers checked against a range given as numbers.
  void read(const std::string& key, int& field, const Range& range);
  void read(const std::string& key, std::int64_t& field, const Range& range);
  void read(const std::string& key, bool& field);
  // A non-empty scalar.
  void read(const std::string& key, std::string& field);
  // A scalar, possibly empty; null keeps the default.
  void read(const std::string& key, std::filesystem::path& field);
  // A list of distinct non-empty scalars; null keeps the default.
  void read(const std::string& key, std::vector<std::string>& field);
  // A map {rotation_deg: [rx, ry, rz], translation_mm: [x, y, z]}, either key optional:
  // R = Rz Ry Rx (Eq. 6.2).
  void read(const std::string& key, RigidTransform& field);
  // One of the enum's names (parameter_choices).
  template <ChoiceParameter E>
  void read(const std::string& key, E& field) {
    const YAML::Node node = value(key);
    if (node.IsDefined() && (!node.IsScalar() || !parse_choice(node.Scalar(), field)))
      fail(key, "expected " + choice_list<E>() + ", got " + describe_yaml_node(node));
  }

  // A key the section no longer takes: an error naming its replacement when given.
  void refuse_retired(const std::string& key, const std::string& replacement);

  // Fails at the key's line (the section's when the key is absent).
  [[noreturn]] void fail(const std::string& key, const std::string& reason);

  // After every read: the first key (in file order) no read asked for is an error that lists
  // the known keys.
  void reject_unknown_keys() const;

 private:
  const char* kind() const { return name_.empty() ? "section" : "key"; }

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
                        const std::string& key, const Range& range);

}  // namespace cosmos
