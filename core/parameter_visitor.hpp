#pragma once
// Each parameter declared once, as a name-value list (the pattern of Drake's
// Serialize(Archive*) with DRAKE_NVP): a parameter struct names its fields in one member
//
//   template <class Visitor>
//   void visit(Visitor& v) {
//     v("window_size", window_size, "fit window, pixels (odd)", Range{3, 15});
//     v("bicubic", bicubic, "bicubic z(x, y); false: biquadratic");
//     v("camera", camera, "camera-mode frame drawing");  // a visitable struct: a nested map
//     v.fields(thread);  // a visitable struct whose keys sit in this map
//     v.retired("background_height_mm", "conditioning.height_threshold_mm");
//   }
//
// and whatever needs the list is a visitor over it: the YAML section reader
// (core/io/yaml_section_reader.hpp), the model base's parameter text (core/io/parameters_text.hpp),
// the range check (core/parameter_range_check.hpp) and the table of docs/parameters.md
// (core/io/parameter_table.hpp). A field listed there is read, recorded, checked and documented
// with no further line anywhere.
//
// A visitor provides
//   template <class T>
//   void operator()(const char* key, T& field, const char* description, const Range& range = {});
//   template <class T> void fields(T& nested);
//   void retired(const char* key, const char* replacement);
// Field types: bool, int, std::int64_t, std::uint64_t, double, an enum with parameter_choices
// (below), std::string, a visitable struct, and for config files std::filesystem::path,
// std::vector<std::string> and RigidTransform. A range applies to numbers; an integer field is
// checked as the integer it is. A retired key is one a file may no longer give: readers refuse
// it naming its replacement, every other visitor ignores it.
#include <charconv>
#include <cmath>
#include <concepts>
#include <limits>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>

namespace cosmos {

// The valid values of a number: [low, high] unless an end is open. The default is every
// finite number.
struct Range {
  double low = -std::numeric_limits<double>::infinity();
  double high = std::numeric_limits<double>::infinity();
  bool low_open = false;
  bool high_open = false;

  static constexpr Range above(double low, double high) { return {low, high, true, false}; }
  static constexpr Range open(double low, double high) { return {low, high, true, true}; }
  static constexpr Range below(double low, double high) { return {low, high, false, true}; }

  bool bounded() const {
    return low != -std::numeric_limits<double>::infinity() ||
           high != std::numeric_limits<double>::infinity();
  }
  bool contains(double value) const {
    return std::isfinite(value) && (low_open ? value > low : value >= low) &&
           (high_open ? value < high : value <= high);
  }
  // "(0, 100]" for messages and documentation.
  std::string text() const;
};

// The shortest text that reads back to the same double ("0.4", "-127.8", "2.5e-05"); whole
// numbers in full ("100000").
inline std::string parameter_number_text(double value) {
  char buffer[64];
  const bool whole = std::isfinite(value) && std::abs(value) < 1e15 && value == std::trunc(value);
  const auto result =
      whole ? std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::fixed)
            : std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

inline std::string Range::text() const {
  // Built by appends: GCC 12 warns (-Wrestrict) about some chained string concatenations.
  std::string text = low_open ? "(" : "[";
  text.append(parameter_number_text(low)).append(", ").append(parameter_number_text(high));
  return text.append(high_open ? ")" : "]");
}

// The name an enum value has in files; an enum parameter's type declares, next to itself,
//   std::span<const ParameterChoice<E>> parameter_choices(E);
// found by argument-dependent lookup.
template <class Enum>
struct ParameterChoice {
  Enum value;
  const char* name;
};

// Accepts any field: only the form of the calls matters to the concepts below.
struct ParameterVisitorArchetype {
  template <class... Arguments>
  void operator()(Arguments&&...) {}
  template <class T>
  void fields(T&) {}
  void retired(const char*, const char*) {}
};

template <class T>
concept VisitableParameters = std::is_class_v<T> &&
    requires(T& parameters, ParameterVisitorArchetype& visitor) {
  parameters.visit(visitor);
};

template <class E>
concept ChoiceParameter = std::is_enum_v<E> && requires(E value) {
  { parameter_choices(value) } -> std::convertible_to<std::span<const ParameterChoice<E>>>;
};

// Visits `parameters`. A visitor given a const struct only reads its fields: the struct
// declares one visit(), for both.
template <class Visitor, VisitableParameters T>
void visit_parameters(Visitor& visitor, T& parameters) {
  parameters.visit(visitor);
}
template <class Visitor, VisitableParameters T>
void visit_parameters(Visitor& visitor, const T& parameters) {
  const_cast<T&>(parameters).visit(visitor);
}

template <ChoiceParameter E>
std::string_view choice_name(E value) {
  for (const ParameterChoice<E>& choice : parameter_choices(value))
    if (choice.value == value) return choice.name;
  return "?";
}

// "fan or parallel", "a, b or c".
template <ChoiceParameter E>
std::string choice_list() {
  const auto choices = parameter_choices(E{});
  std::string list;
  for (std::size_t i = 0; i < choices.size(); ++i) {
    if (i > 0) list += i + 1 == choices.size() ? " or " : ", ";
    list += choices[i].name;
  }
  return list;
}

// false (and `value` unchanged) when `name` is none of the choices.
template <ChoiceParameter E>
bool parse_choice(std::string_view name, E& value) {
  for (const ParameterChoice<E>& choice : parameter_choices(value)) {
    if (name == choice.name) {
      value = choice.value;
      return true;
    }
  }
  return false;
}

}  // namespace cosmos
