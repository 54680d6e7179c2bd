#include "core/io/yaml_input_errors.hpp"

#include "core/input_error.hpp"

namespace cosmos {

void YamlInputErrors::fail(const YAML::Node& at, const std::string& key,
                           const std::string& reason) const {
  fail_line(at.IsDefined() ? at.Mark().line : -1, key, reason);
}

void YamlInputErrors::fail_line(int line0, const std::string& key,
                                const std::string& reason) const {
  // Built by appends: GCC 12 warns (-Wrestrict) about some chained string concatenations.
  std::string message = file_.string();
  if (line0 >= 0) message.append(":").append(std::to_string(line0 + 1));
  message.append(": ").append(key).append(": ").append(reason);
  throw InputError(message);
}

YAML::Node YamlInputErrors::load_file(const std::string& what) const {
  std::error_code error;
  if (!std::filesystem::is_regular_file(file_, error))
    throw InputError(file_.string() + ": " + what + " not found");
  try {
    return YAML::LoadFile(file_.string());
  } catch (const YAML::ParserException& parse) {
    fail_line(parse.mark.line, "yaml", parse.msg);
  } catch (const YAML::Exception& other) {
    throw InputError(file_.string() + ": cannot read " + what + ": " + other.msg);
  }
}

std::string describe_yaml_node(const YAML::Node& node) {
  if (node.IsNull()) return "nothing";
  if (node.IsSequence()) return "a list";
  if (node.IsMap()) return "a map";
  std::string quoted = "'";
  return quoted.append(node.Scalar()).append("'");
}

}  // namespace cosmos
