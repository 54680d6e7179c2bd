#pragma once
// Reads one map section of a YAML config (a `tracking:` or `lcm:` block of config/cell.yaml)
// key by key into typed fields: a key that is absent keeps the field's default; a key with
// the wrong type or out of its range, a key given twice, a retired key (naming its
// replacement) and a key that no read asked for throw InputError `file:LINE: section.key:
// reason` (YamlInputErrors).
//
// read_yaml_parameters() reads a whole section from its struct's visit() list
// (core/parameter_visitor.hpp), nested structs as nested maps.
#include <yaml-cpp/yaml.h>

#include <cstdint>
#include <filesystem>
#include <set>
#include <string>
#include <type_traits>
#include <vector>

#include "core/io/yaml_input_errors.hpp"
#include "core/parameter_visitor.hpp"
#include "core/rigid_transform.hpp"

namespace cosmos {

// The former name of Range, for readers written before the visitor.
using NumberRange = Range;

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

// The visitor behind read_yaml_parameters: each visited field read from its key.
class YamlParameterReader {
 public:
  explicit YamlParameterReader(YamlSectionReader& section) : section_(section) {}

  template <class T>
  void operator()(const char* key, T& field, const char* = "", const Range& range = {});
  template <class T>
  void fields(T& nested) {
    visit_parameters(*this, nested);
  }
  void retired(const char* key, const char* replacement) {
    section_.refuse_retired(key, replacement);
  }

 private:
  YamlSectionReader& section_;
};

// Every field `parameters` visits, from its key in `section`; then the first key no field
// has is refused. Cross-field rules are the caller's, after this.
template <VisitableParameters T>
void read_yaml_parameters(YamlSectionReader& section, T& parameters) {
  YamlParameterReader reader(section);
  visit_parameters(reader, parameters);
  section.reject_unknown_keys();
}

template <class T>
void YamlParameterReader::operator()(const char* key, T& field, const char*, const Range& range) {
  if constexpr (VisitableParameters<T>) {
    YamlSectionReader nested(section_.errors(), section_.value(key), section_.dotted(key));
    read_yaml_parameters(nested, field);
  } else if constexpr (std::is_same_v<T, double> || std::is_same_v<T, int> ||
                       std::is_same_v<T, std::int64_t>) {
    section_.read(key, field, range);
  } else {
    section_.read(key, field);
  }
}

}  // namespace cosmos
