#pragma once
// The declared ranges (core/parameter_visitor.hpp) checked on parameters set in code, e.g.
// after a command-line override: the same ranges a config file is read with.
#include <optional>
#include <string>
#include <type_traits>

#include "core/parameter_visitor.hpp"

namespace cosmos {

class ParameterRangeCheck {
 public:
  explicit ParameterRangeCheck(std::string prefix) : prefix_(std::move(prefix)) {}

  template <class T>
  void operator()(const char* key, T& field, const char* = "", const Range& range = {}) {
    if (problem_) return;
    if constexpr (VisitableParameters<T>) {
      ParameterRangeCheck nested(dotted(key));
      visit_parameters(nested, field);
      problem_ = nested.problem_;
    } else if constexpr (std::is_arithmetic_v<T> && !std::is_same_v<T, bool>) {
      if (!range.contains(static_cast<double>(field))) {
        std::string value;
        if constexpr (std::is_integral_v<T>) {
          value = std::to_string(field);
        } else {
          value = parameter_number_text(field);
        }
        problem_ = dotted(key) + ": must be in " + range.text() + ", got " + value;
      }
    }
  }
  template <class T>
  void fields(T& nested) {
    visit_parameters(*this, nested);
  }
  void retired(const char*, const char*) {}

  const std::optional<std::string>& problem() const { return problem_; }

 private:
  std::string dotted(const char* key) const {
    return prefix_.empty() ? std::string(key) : prefix_ + "." + key;
  }

  std::string prefix_;
  std::optional<std::string> problem_;
};

// The first field out of its range, "prefix.key: must be in [a, b], got x"; nullopt when
// every field is in range.
template <class T>
std::optional<std::string> first_out_of_range(const T& parameters, const std::string& prefix) {
  ParameterRangeCheck check(prefix);
  visit_parameters(check, parameters);
  return check.problem();
}

}  // namespace cosmos
