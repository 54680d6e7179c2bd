#pragma once
// The canonical text of a set of parameters (what the model base records it was built with):
// one JSON object nested by the dots of the keys ("cosmos.fit.window_size" is
// {"cosmos": {"fit": {"window_size": 5}}}), keys sorted, two-space indent, numbers in the
// shortest form that reads back to the same double. Two runs with the same parameters give
// the same bytes, and two texts are compared key by key, so a refusal can name the one
// parameter that differs.
//
// Whole parameter structs are written and read back through their visit()
// (core/parameter_visitor.hpp): every field a struct lists is in the text.
#include <cstdint>
#include <initializer_list>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>

#include "core/parameter_visitor.hpp"

namespace cosmos {

class ParameterText {
 public:
  // Keys are dotted identifiers; setting a key again replaces its value.
  void set_number(std::string_view key, double value);
  void set_integer(std::string_view key, std::int64_t value);
  void set_unsigned(std::string_view key, std::uint64_t value);  // seeds use all 64 bits
  void set_flag(std::string_view key, bool value);
  void set_text(std::string_view key, std::string_view value);

  // Every field `parameters` visits, under "prefix.", except the keys (or whole nested
  // sections) named in `left_out` relative to the prefix ("line_rate_hz", "camera").
  template <VisitableParameters T>
  void set_parameters(std::string_view prefix, const T& parameters,
                      std::initializer_list<std::string_view> left_out = {});

  std::string text() const;

 private:
  std::map<std::string, std::string> values_;  // key -> value as compact JSON
};

struct ParameterDifference {
  std::string key;       // dotted, e.g. "scanner.z_noise_mm"
  std::string expected;  // compact JSON, or "(absent)"
  std::string actual;
};

// The first key, in sorted order, whose value differs between the two texts or that only one
// of them has; nullopt when they hold the same parameters. A text that is not a JSON object
// differs at the key "(text)".
std::optional<ParameterDifference> first_parameter_difference(std::string_view expected_text,
                                                              std::string_view actual_text);

// A parameters text's values by dotted key, to read parameters back.
class ParameterValues {
 public:
  // nullopt when the text is not a JSON object.
  static std::optional<ParameterValues> parse(std::string_view text);

  // Each nullopt when the key is absent or holds another kind of value.
  std::optional<double> number(const std::string& key) const;
  std::optional<std::int64_t> integer(const std::string& key) const;
  std::optional<std::uint64_t> unsigned_integer(const std::string& key) const;
  std::optional<bool> flag(const std::string& key) const;
  std::optional<std::string> text(const std::string& key) const;

 private:
  std::map<std::string, std::string> leaves_;  // key -> value as compact JSON
};

// Reads every field `parameters` visits from the keys under "prefix."; returns the first key
// that is absent or holds no value of the field's kind (the field then keeps its value),
// nullopt when every field was read.
template <VisitableParameters T>
std::optional<std::string> read_parameter_values(const ParameterValues& values,
                                                 const std::string& prefix, T& parameters);

// ---- the visitors behind set_parameters and read_parameter_values

class ParameterTextWriter {
 public:
  ParameterTextWriter(ParameterText& text, std::string prefix,
                      std::initializer_list<std::string_view> left_out)
      : text_(text), prefix_(std::move(prefix)), left_out_(left_out) {}

  template <class T>
  void operator()(const char* key, const T& field, const char* = "", const Range& = {}) {
    for (std::string_view skipped : left_out_)
      if (skipped == key) return;
    const std::string dotted = prefix_ + "." + key;
    if constexpr (VisitableParameters<T>) {
      // left_out names keys directly under the prefix only.
      std::initializer_list<std::string_view> none = {};
      ParameterTextWriter nested(text_, dotted, none);
      visit_parameters(nested, field);
    } else if constexpr (std::is_same_v<T, bool>) {
      text_.set_flag(dotted, field);
    } else if constexpr (std::is_same_v<T, std::uint64_t>) {
      text_.set_unsigned(dotted, field);
    } else if constexpr (std::is_integral_v<T>) {
      text_.set_integer(dotted, field);
    } else if constexpr (std::is_floating_point_v<T>) {
      text_.set_number(dotted, field);
    } else if constexpr (std::is_enum_v<T>) {
      text_.set_text(dotted, choice_name(field));
    } else {
      text_.set_text(dotted, field);
    }
  }
  template <class T>
  void fields(const T& nested) {
    visit_parameters(*this, nested);
  }
  void retired(const char*, const char*) {}

 private:
  ParameterText& text_;
  std::string prefix_;
  std::initializer_list<std::string_view> left_out_;
};

class ParameterValuesReader {
 public:
  ParameterValuesReader(const ParameterValues& values, std::string prefix)
      : values_(values), prefix_(std::move(prefix)) {}

  template <class T>
  void operator()(const char* key, T& field, const char* = "", const Range& = {}) {
    if (missing_) return;
    const std::string dotted = prefix_ + "." + key;
    bool read = true;
    if constexpr (VisitableParameters<T>) {
      ParameterValuesReader nested(values_, dotted);
      visit_parameters(nested, field);
      missing_ = nested.missing_;
      return;
    } else if constexpr (std::is_same_v<T, bool>) {
      read = assign(values_.flag(dotted), field);
    } else if constexpr (std::is_same_v<T, std::uint64_t>) {
      read = assign(values_.unsigned_integer(dotted), field);
    } else if constexpr (std::is_integral_v<T>) {
      read = assign(values_.integer(dotted), field);
    } else if constexpr (std::is_floating_point_v<T>) {
      read = assign(values_.number(dotted), field);
    } else if constexpr (std::is_enum_v<T>) {
      const std::optional<std::string> name = values_.text(dotted);
      read = name && parse_choice(*name, field);
    } else {
      read = assign(values_.text(dotted), field);
    }
    if (!read) missing_ = dotted;
  }
  template <class T>
  void fields(T& nested) {
    visit_parameters(*this, nested);
  }
  void retired(const char*, const char*) {}

  const std::optional<std::string>& missing() const { return missing_; }

 private:
  template <class Value, class Field>
  static bool assign(const std::optional<Value>& value, Field& field) {
    if (!value) return false;
    field = static_cast<Field>(*value);
    return true;
  }

  const ParameterValues& values_;
  std::string prefix_;
  std::optional<std::string> missing_;
};

template <VisitableParameters T>
void ParameterText::set_parameters(std::string_view prefix, const T& parameters,
                                   std::initializer_list<std::string_view> left_out) {
  ParameterTextWriter writer(*this, std::string(prefix), left_out);
  visit_parameters(writer, parameters);
}

template <VisitableParameters T>
std::optional<std::string> read_parameter_values(const ParameterValues& values,
                                                 const std::string& prefix, T& parameters) {
  ParameterValuesReader reader(values, prefix);
  visit_parameters(reader, parameters);
  return reader.missing();
}

}  // namespace cosmos
