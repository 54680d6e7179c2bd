#pragma once
// Writing what a calibration measured into the YAML files the cell reads: a parameter struct
// becomes a YAML map through its visit() (core/parameter_visitor.hpp), so the keys written are
// exactly the keys the readers accept, and update_yaml_file() puts each map or value at its
// dotted key of an existing file (or a new one), leaving every other key as it was. The file
// is rewritten by yaml-cpp: its comments are not kept.
#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "core/parameter_visitor.hpp"
#include "core/rigid_transform.hpp"

namespace cosmos {

// rotation_deg [rx, ry, rz] (R = Rz Ry Rx, Eq. 6.2) and translation_mm, as the readers take it.
YAML::Node yaml_of_transform(const RigidTransform& T);

class YamlNodeWriter {
 public:
  explicit YamlNodeWriter(YAML::Node& map) : map_(map) {}

  template <class T>
  void operator()(const char* key, const T& field, const char*, const Range& = {}) {
    if constexpr (std::is_same_v<T, RigidTransform>) {
      map_[key] = yaml_of_transform(field);
    } else if constexpr (VisitableParameters<T>) {
      YAML::Node nested(YAML::NodeType::Map);
      YamlNodeWriter writer(nested);
      visit_parameters(writer, const_cast<T&>(field));
      map_[key] = nested;
    } else {
      map_[key] = field;
    }
  }
  template <class T>
  void fields(const T& nested) {
    visit_parameters(*this, const_cast<T&>(nested));
  }
  void retired(const char*, const char*) {}

 private:
  YAML::Node& map_;
};

template <VisitableParameters T>
YAML::Node yaml_of(const T& parameters) {
  YAML::Node map(YAML::NodeType::Map);
  YamlNodeWriter writer(map);
  visit_parameters(writer, const_cast<T&>(parameters));
  return map;
}

using YamlEntries = std::vector<std::pair<std::string, YAML::Node>>;

// InputError naming the file when it cannot be read or written.
void update_yaml_file(const std::filesystem::path& file, const YamlEntries& entries);

}  // namespace cosmos
