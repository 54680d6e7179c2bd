#include "core/io/parameters_text.hpp"

#include <cstdint>
#include <nlohmann/json.hpp>

namespace cosmos {
namespace {

using nlohmann::json;

std::string pointer_of(std::string_view dotted_key) {
  std::string pointer = "/";
  for (char c : dotted_key) pointer += c == '.' ? '/' : c;
  return pointer;
}

std::string dotted_of(const std::string& pointer) {
  std::string key = pointer.substr(pointer.empty() ? 0 : 1);
  for (char& c : key)
    if (c == '/') c = '.';
  return key;
}

// Leaves of the text as dotted key -> compact JSON; nullopt when it is not a JSON object.
std::optional<std::map<std::string, std::string>> leaves_of(std::string_view text) {
  const json parsed = json::parse(text.begin(), text.end(), nullptr, false);
  if (parsed.is_discarded() || !parsed.is_object()) return std::nullopt;
  std::map<std::string, std::string> leaves;
  const json flat = parsed.flatten();
  for (const auto& [pointer, value] : flat.items()) leaves[dotted_of(pointer)] = value.dump();
  return leaves;
}

}  // namespace

void ParameterText::set_number(std::string_view key, double value) {
  values_[std::string(key)] = json(value).dump();
}
void ParameterText::set_integer(std::string_view key, std::int64_t value) {
  values_[std::string(key)] = json(value).dump();
}
void ParameterText::set_unsigned(std::string_view key, std::uint64_t value) {
  values_[std::string(key)] = json(value).dump();
}
void ParameterText::set_flag(std::string_view key, bool value) {
  values_[std::string(key)] = json(value).dump();
}
void ParameterText::set_text(std::string_view key, std::string_view value) {
  values_[std::string(key)] = json(std::string(value)).dump();
}

std::string ParameterText::text() const {
  json flat = json::object();
  for (const auto& [key, value] : values_) flat[pointer_of(key)] = json::parse(value);
  // nlohmann's objects are std::maps: the keys come out sorted at every level.
  return flat.empty() ? "{}\n" : flat.unflatten().dump(2) + "\n";
}

std::optional<ParameterDifference> first_parameter_difference(std::string_view expected_text,
                                                              std::string_view actual_text) {
  const auto expected = leaves_of(expected_text);
  const auto actual = leaves_of(actual_text);
  if (!expected || !actual) {
    if (expected_text == actual_text) return std::nullopt;
    return ParameterDifference{"(text)", expected ? "a JSON object" : "not a JSON object",
                               actual ? "a JSON object" : "not a JSON object"};
  }
  auto e = expected->begin();
  auto a = actual->begin();
  const std::string absent = "(absent)";
  while (e != expected->end() || a != actual->end()) {
    if (a == actual->end() || (e != expected->end() && e->first < a->first))
      return ParameterDifference{e->first, e->second, absent};
    if (e == expected->end() || a->first < e->first)
      return ParameterDifference{a->first, absent, a->second};
    if (e->second != a->second) return ParameterDifference{e->first, e->second, a->second};
    ++e;
    ++a;
  }
  return std::nullopt;
}

std::optional<ParameterValues> ParameterValues::parse(std::string_view text) {
  auto leaves = leaves_of(text);
  if (!leaves) return std::nullopt;
  ParameterValues values;
  values.leaves_ = std::move(*leaves);
  return values;
}

namespace {

std::optional<json> leaf(const std::map<std::string, std::string>& leaves, const std::string& key) {
  const auto found = leaves.find(key);
  if (found == leaves.end()) return std::nullopt;
  return json::parse(found->second);
}

}  // namespace

std::optional<double> ParameterValues::number(const std::string& key) const {
  const auto value = leaf(leaves_, key);
  if (!value || !value->is_number()) return std::nullopt;
  return value->get<double>();
}

std::optional<std::int64_t> ParameterValues::integer(const std::string& key) const {
  const auto value = leaf(leaves_, key);
  if (!value || !value->is_number_integer()) return std::nullopt;
  if (value->is_number_unsigned() &&
      value->get<std::uint64_t>() > static_cast<std::uint64_t>(INT64_MAX))
    return std::nullopt;
  return value->get<std::int64_t>();
}

std::optional<std::uint64_t> ParameterValues::unsigned_integer(const std::string& key) const {
  const auto value = leaf(leaves_, key);
  if (!value || !value->is_number_unsigned()) return std::nullopt;
  return value->get<std::uint64_t>();
}

std::optional<bool> ParameterValues::flag(const std::string& key) const {
  const auto value = leaf(leaves_, key);
  if (!value || !value->is_boolean()) return std::nullopt;
  return value->get<bool>();
}

std::optional<std::string> ParameterValues::text(const std::string& key) const {
  const auto value = leaf(leaves_, key);
  if (!value || !value->is_string()) return std::nullopt;
  return value->get<std::string>();
}

}  // namespace cosmos
