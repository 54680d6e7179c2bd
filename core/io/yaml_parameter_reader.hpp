#pragma once
// read_yaml_parameters(): a whole YAML section read from its struct's visit() list
// (core/parameter_visitor.hpp), every declared key with its range, nested structs as nested
// maps, retired keys refused naming their replacement, then any key no field has refused
// (through YamlSectionReader, so every error is one line `file:LINE: section.key: reason`).
#include <cstdint>
#include <type_traits>

#include "core/io/yaml_section_reader.hpp"
#include "core/parameter_visitor.hpp"

namespace cosmos {

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
