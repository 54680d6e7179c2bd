#include "core/io/parameter_table.hpp"

namespace cosmos {
namespace {

// A table cell: pipes would end it.
std::string cell(const std::string& text) {
  std::string escaped;
  for (char c : text) {
    if (c == '|') escaped += '\\';
    escaped += c;
  }
  return escaped;
}

std::string code(const std::string& text) { return text.empty() ? "" : "`" + text + "`"; }

}  // namespace

std::string parameter_value_text(double value) { return parameter_number_text(value); }

std::string parameter_value_text(const std::string& value) { return "\"" + value + "\""; }

std::string parameter_value_text(const std::filesystem::path& value) {
  return parameter_value_text(value.string());
}

std::string parameter_value_text(const std::vector<std::string>& value) {
  std::string list = "[";
  for (std::size_t i = 0; i < value.size(); ++i) list += (i > 0 ? ", " : "") + value[i];
  return list + "]";
}

std::string parameter_value_text(const RigidTransform& value) {
  if (value.rotation.isIdentity(0.0) && value.translation_mm.isZero(0.0)) return "identity";
  return "(a calibrated pose)";
}

std::string ParameterTable::markdown() const {
  std::string text = "| key | default | description | range |\n|---|---|---|---|\n";
  for (const ParameterRow& row : rows_) {
    text.append("| ").append(code(row.key)).append(" | ").append(code(cell(row.default_value)));
    text.append(" | ").append(cell(row.description)).append(" | ").append(cell(row.valid));
    text.append(" |\n");
  }
  for (const RetiredParameter& old : retired_) {
    text.append("\nRetired: ").append(code(old.key)).append(", replaced by ");
    text.append(old.replacement).append(".\n");
  }
  return text;
}

}  // namespace cosmos
