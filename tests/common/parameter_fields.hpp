#pragma once
// Test visitors over parameter structs (core/parameter_visitor.hpp), so a test can go through
// every field a struct declares without naming them:
//   ParameterLeaves   every field as "key = value" (values printed exactly), to compare structs;
//   FieldChanger      changes one field (by its index in visit order) or all of them to another
//                     valid value near the old one, writing what it set as YAML as it goes.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>
#include <type_traits>
#include <vector>

#include "core/parameter_visitor.hpp"
#include "core/rigid_transform.hpp"

namespace cosmos::testing {

inline std::string exact_text(double value) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.17g", value);
  return buffer;
}

class ParameterLeaves {
 public:
  explicit ParameterLeaves(std::string prefix = "") : prefix_(std::move(prefix)) {}

  template <class T>
  void operator()(const char* key, const T& field, const char* = "", const Range& = {}) {
    const std::string dotted = prefix_.empty() ? std::string(key) : prefix_ + "." + key;
    if constexpr (VisitableParameters<T>) {
      ParameterLeaves nested(dotted);
      visit_parameters(nested, field);
      leaves.insert(leaves.end(), nested.leaves.begin(), nested.leaves.end());
    } else {
      leaves.push_back(dotted + " = " + text(field));
    }
  }
  template <class T>
  void fields(const T& nested) {
    visit_parameters(*this, nested);
  }
  void retired(const char*, const char*) {}

  std::vector<std::string> leaves;

 private:
  template <class T>
  static std::string text(const T& field) {
    if constexpr (std::is_same_v<T, bool>) {
      return field ? "true" : "false";
    } else if constexpr (std::is_integral_v<T>) {
      return std::to_string(field);
    } else if constexpr (std::is_floating_point_v<T>) {
      return exact_text(field);
    } else if constexpr (std::is_enum_v<T>) {
      return std::string(choice_name(field));
    } else if constexpr (std::is_same_v<T, std::filesystem::path>) {
      return field.string();
    } else if constexpr (std::is_same_v<T, std::vector<std::string>>) {
      std::string list;
      for (const std::string& name : field) list += name + ";";
      return list;
    } else if constexpr (std::is_same_v<T, RigidTransform>) {
      std::string entries;
      for (int k = 0; k < 9; ++k) entries += exact_text(field.rotation(k / 3, k % 3)) + " ";
      for (int k = 0; k < 3; ++k) entries += exact_text(field.translation_mm(k)) + " ";
      return entries;
    } else {
      return field;
    }
  }

  std::string prefix_;
};

template <class T>
std::vector<std::string> parameter_leaves(const T& parameters) {
  ParameterLeaves visitor;
  visit_parameters(visitor, parameters);
  return visitor.leaves;
}

// Changes field number `target` (in visit order, nested structs' fields in place; kAll: every
// field, kNone: none, only counted) to a valid value near its old one: numbers by an eighth of
// themselves (or a step) or integers by 2 (bit depths stay even), flags flipped, choices to the
// next one, texts extended, lists grown, poses turned. `yaml` is what it set, as a YAML map.
class FieldChanger {
 public:
  static constexpr int kAll = -1;
  static constexpr int kNone = -2;

  explicit FieldChanger(int target, std::string prefix = "", int indent = 0)
      : target_(target), prefix_(std::move(prefix)), indent_(indent) {}

  template <class T>
  void operator()(const char* key, T& field, const char* = "", const Range& range = {}) {
    const std::string dotted = prefix_.empty() ? std::string(key) : prefix_ + "." + key;
    if constexpr (VisitableParameters<T>) {
      const int nested_target =
          target_ < 0 ? target_ : (target_ >= count ? target_ - count : kNone);
      FieldChanger nested(nested_target, dotted, indent_ + 2);
      visit_parameters(nested, field);
      count += nested.count;
      if (!nested.changed_key.empty()) changed_key = nested.changed_key;
      if (!nested.yaml.empty()) yaml += pad() + key + ":\n" + nested.yaml;
    } else {
      if (target_ == kAll || target_ == count) {
        yaml += pad() + key + ": " + change(field, range) + "\n";
        changed_key = dotted;
      }
      ++count;
    }
  }
  template <class T>
  void fields(T& nested) {
    visit_parameters(*this, nested);
  }
  void retired(const char*, const char*) {}

  int count = 0;            // fields visited
  std::string changed_key;  // dotted, the last field changed
  std::string yaml;

 private:
  // Built by appends: GCC 12 warns (-Wrestrict) about some chained string concatenations.
  static std::string quoted(const std::string& text) {
    std::string yaml = "'";
    return yaml.append(text).append("'");
  }
  std::string pad() const { return std::string(static_cast<std::size_t>(indent_), ' '); }

  template <class T>
  static std::string change(T& field, const Range& range) {
    if constexpr (std::is_same_v<T, bool>) {
      field = !field;
      return field ? "true" : "false";
    } else if constexpr (std::is_integral_v<T>) {
      const T up = static_cast<T>(field + 2);
      field = range.contains(static_cast<double>(up)) ? up : static_cast<T>(field - 2);
      return std::to_string(field);
    } else if constexpr (std::is_floating_point_v<T>) {
      const double step =
          field != 0 ? std::abs(field) / 8 : (range.bounded() ? (range.high - range.low) / 8 : 1);
      const double up = field + (std::isfinite(step) ? step : 1.0);
      field = range.contains(up) ? up : field - (up - field);
      return exact_text(field);
    } else if constexpr (std::is_enum_v<T>) {
      const auto choices = parameter_choices(field);
      for (std::size_t i = 0; i < choices.size(); ++i) {
        if (choices[i].value == field) {
          field = choices[(i + 1) % choices.size()].value;
          break;
        }
      }
      return std::string(choice_name(field));
    } else if constexpr (std::is_same_v<T, std::filesystem::path>) {
      std::string text = field.string();
      text.append("x");
      field = text;
      return quoted(text);
    } else if constexpr (std::is_same_v<T, std::vector<std::string>>) {
      field.push_back("extra");
      std::string list = "[";
      for (std::size_t i = 0; i < field.size(); ++i) list += (i ? ", " : "") + field[i];
      return list + "]";
    } else if constexpr (std::is_same_v<T, RigidTransform>) {
      field.rotation = rotation_from_xyz_angles_deg(10, 20, 30);
      field.translation_mm = Eigen::Vector3d(1, 2, 3);
      return "{rotation_deg: [10, 20, 30], translation_mm: [1, 2, 3]}";
    } else {
      field.append("x");
      return quoted(field);
    }
  }

  int target_;
  std::string prefix_;
  int indent_;
};

// How many fields `parameters` visits, nested ones included.
template <class T>
int parameter_field_count(T parameters) {
  FieldChanger counter(FieldChanger::kNone);
  visit_parameters(counter, parameters);
  return counter.count;
}

// `parameters` with field `index` changed; `key` is set to its dotted name.
template <class T>
T with_field_changed(T parameters, int index, std::string& key) {
  FieldChanger changer(index);
  visit_parameters(changer, parameters);
  key = changer.changed_key;
  return parameters;
}

}  // namespace cosmos::testing
