#pragma once
// The canonical text of a set of parameters (what the model base records it was built with):
// one JSON object nested by the dots of the keys ("cosmos.fit.window_size" is
// {"cosmos": {"fit": {"window_size": 5}}}), keys sorted, two-space indent, numbers in the
// shortest form that reads back to the same double. Two runs with the same parameters give
// the same bytes, and two texts are compared key by key, so a refusal can name the one
// parameter that differs.
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>

namespace cosmos {

class ParameterText {
 public:
  // Keys are dotted identifiers; setting a key again replaces its value.
  void set_number(std::string_view key, double value);
  void set_integer(std::string_view key, std::int64_t value);
  void set_unsigned(std::string_view key, std::uint64_t value);  // seeds use all 64 bits
  void set_flag(std::string_view key, bool value);
  void set_text(std::string_view key, std::string_view value);

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

}  // namespace cosmos
