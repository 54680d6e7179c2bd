#pragma once
// One-line errors for YAML inputs (catalogs, cell configs): `file:LINE: key: reason`, the
// line 1-based (yaml-cpp marks are 0-based, -1 when unknown), thrown as InputError.
#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <string>

namespace cosmos {

class YamlInputErrors {
 public:
  explicit YamlInputErrors(std::filesystem::path file) : file_(std::move(file)) {}
  [[noreturn]] void fail(const YAML::Node& at, const std::string& key,
                         const std::string& reason) const;
  [[noreturn]] void fail_line(int line0, const std::string& key, const std::string& reason) const;
  // The file's root node. `what` names the file in the two errors that have no line:
  // "<file>: <what> not found" and "<file>: cannot read <what>: <reason>"; a parse error is
  // "<file>:LINE: yaml: <reason>".
  YAML::Node load_file(const std::string& what) const;

 private:
  std::filesystem::path file_;
};

// "nothing", "a list", "a map" or the quoted scalar: what a wrong value was, for messages.
std::string describe_yaml_node(const YAML::Node& node);

}  // namespace cosmos
