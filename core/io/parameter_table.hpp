#pragma once
// The documentation of a parameter struct, from its visit() (core/parameter_visitor.hpp): one
// row per key with its default, description and valid range, and the retired keys with their
// replacements, as a Markdown table (docs/parameters.md is made of these).
#include <filesystem>
#include <string>
#include <type_traits>
#include <vector>

#include "core/parameter_visitor.hpp"
#include "core/rigid_transform.hpp"

namespace cosmos {

struct ParameterRow {
  std::string key;            // below the section, dotted: "camera.bit_depth"
  std::string default_value;  // as a file would give it
  std::string description;
  std::string valid;  // "[5, 75]", "fan or parallel"; empty when any value of the type is
};

struct RetiredParameter {
  std::string key;
  std::string replacement;
};

class ParameterTable {
 public:
  // The rows of `defaults` (a default-constructed struct: its defaults are the documented ones).
  template <VisitableParameters T>
  static ParameterTable of(const T& defaults);

  const std::vector<ParameterRow>& rows() const { return rows_; }
  const std::vector<RetiredParameter>& retired() const { return retired_; }

  // "| key | default | description | range |" and a row per key, then a line per retired key.
  std::string markdown() const;

  // The visitor behind of().
  class Writer;

 private:
  std::vector<ParameterRow> rows_;
  std::vector<RetiredParameter> retired_;
};

// A field's value as a config file gives it: 0.4, true, fan, "parts.yaml", [], identity.
std::string parameter_value_text(double value);
std::string parameter_value_text(const std::string& value);
std::string parameter_value_text(const std::filesystem::path& value);
std::string parameter_value_text(const std::vector<std::string>& value);
std::string parameter_value_text(const RigidTransform& value);

class ParameterTable::Writer {
 public:
  Writer(ParameterTable& table, std::string prefix) : table_(table), prefix_(std::move(prefix)) {}

  template <class T>
  void operator()(const char* key, const T& field, const char* description,
                  const Range& range = {}) {
    const std::string dotted = prefix_.empty() ? std::string(key) : prefix_ + "." + key;
    if constexpr (VisitableParameters<T>) {
      Writer nested(table_, dotted);
      visit_parameters(nested, field);
    } else {
      ParameterRow row{dotted, "", description, range.bounded() ? range.text() : ""};
      if constexpr (std::is_same_v<T, bool>) {
        row.default_value = field ? "true" : "false";
      } else if constexpr (std::is_integral_v<T>) {
        row.default_value = std::to_string(field);
      } else if constexpr (std::is_enum_v<T>) {
        row.default_value = std::string(choice_name(field));
        row.valid = choice_list<T>();
      } else {
        row.default_value = parameter_value_text(field);
      }
      table_.rows_.push_back(std::move(row));
    }
  }
  template <class T>
  void fields(const T& nested) {
    visit_parameters(*this, nested);
  }
  void retired(const char* key, const char* replacement) {
    table_.retired_.push_back({prefix_.empty() ? key : prefix_ + "." + key, replacement});
  }

 private:
  ParameterTable& table_;
  std::string prefix_;
};

template <VisitableParameters T>
ParameterTable ParameterTable::of(const T& defaults) {
  ParameterTable table;
  Writer writer(table, "");
  visit_parameters(writer, defaults);
  return table;
}

}  // namespace cosmos
