#pragma once
// Command-line numbers checked against the ranges the parameters declare (their visit(),
// core/parameter_visitor.hpp), before the command runs: the option that sets a parameter is
// held to the same range as the config key it overrides, and the refusal names both
// ("--smoothing-iterations: cosmos.smoothing.iterations must be in [0, 1000], got 5000").
// Options that set no parameter are checked against a Range of their own.
#include <charconv>
#include <functional>
#include <string>
#include <system_error>
#include <type_traits>

#include "core/parameter_range_check.hpp"
#include "core/parameter_visitor.hpp"

namespace cosmos::cli {

// `text` as a T, the whole of it; false for anything else (or a non-finite float).
template <class T>
bool parse_whole_number(const std::string& text, T& value) {
  const char* const end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, value);
  if (text.empty() || error != std::errc{} || stop != end) return false;
  if constexpr (std::is_floating_point_v<T>) return std::isfinite(value);
  return true;
}

// A CLI11 check: the option's text parsed as T and set by `set` into default Parameters,
// which must then be in their declared ranges under `prefix`.
template <class Parameters, class T>
std::function<std::string(const std::string&)> declared_range(
    std::string prefix, std::function<void(Parameters&, T)> set) {
  return [prefix = std::move(prefix), set = std::move(set)](const std::string& text) {
    T value{};
    if (!parse_whole_number(text, value))
      return "'" + text + "' is not " + (std::is_integral_v<T> ? "a whole number" : "a number");
    Parameters parameters{};
    set(parameters, value);
    const std::optional<std::string> problem = first_out_of_range(parameters, prefix);
    if (!problem) return std::string();
    std::string reason = *problem;
    const std::size_t colon = reason.find(": ");
    if (colon != std::string::npos) reason.erase(colon, 1);  // "a.b must be in ..., got x"
    return reason;
  };
}

// A CLI11 check for an option that sets no parameter: a T within `range`.
template <class T>
std::function<std::string(const std::string&)> within_range(Range range) {
  return [range](const std::string& text) {
    T value{};
    if (!parse_whole_number(text, value))
      return "'" + text + "' is not " + (std::is_integral_v<T> ? "a whole number" : "a number");
    if (range.contains(static_cast<double>(value))) return std::string();
    return "must be in " + range.text() + ", got " + text;
  };
}

}  // namespace cosmos::cli
