#include "sim/part_catalog.hpp"

#include <pwd.h>
#include <unistd.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <cstdlib>
#include <map>
#include <set>
#include <sstream>

#include "core/input_error.hpp"
#include "core/io/yaml_input_errors.hpp"

namespace cosmos {
namespace {

namespace fs = std::filesystem;

fs::path home_dir() {
  if (const char* home = std::getenv("HOME"); home != nullptr && *home != '\0') return home;
  if (const passwd* entry = getpwuid(getuid()); entry != nullptr && entry->pw_dir != nullptr) {
    return entry->pw_dir;
  }
  return fs::current_path();
}

bool starts_with_component(const std::string& text, const std::string& component) {
  return text == component || text.rfind(component + "/", 0) == 0;
}

// "~/x" is the home folder; other relative paths are relative to `base`.
fs::path expand(const std::string& text, const fs::path& base) {
  if (starts_with_component(text, "~")) {
    return text.size() <= 2 ? home_dir() : home_dir() / text.substr(2);
  }
  const fs::path path(text);
  return path.is_absolute() ? path : base / path;
}

fs::path resolve_mesh(const std::string& text, const fs::path& yaml_dir, const fs::path& mesh_dir) {
  const fs::path path(text);
  if (path.is_absolute() || starts_with_component(text, "~")) return expand(text, yaml_dir);
  if (starts_with_component(text, ".") || starts_with_component(text, "..")) return yaml_dir / path;
  std::error_code error;
  if (fs::exists(mesh_dir / path, error)) return mesh_dir / path;
  if (fs::exists(yaml_dir / path, error)) return yaml_dir / path;
  return mesh_dir / path;
}

std::string scalar_string(const YamlInputErrors& errors, const YAML::Node& value,
                          const std::string& key) {
  if (!value.IsScalar() || value.Scalar().empty()) {
    errors.fail(value, key, "expected a non-empty text, got " + describe_yaml_node(value));
  }
  return value.Scalar();
}

// Names become file names and CLI arguments, so they are kept to a portable set.
std::string part_name(const YamlInputErrors& errors, const YAML::Node& value) {
  const std::string name = scalar_string(errors, value, "name");
  for (const char c : name) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                    c == '.' || c == '_' || c == '-';
    if (!ok)
      errors.fail(value, "name", "'" + name + "' may only use letters, digits, '.', '_' or '-'");
  }
  return name;
}

double size_mm(const YamlInputErrors& errors, const YAML::Node& value) {
  double size = 0.0;
  if (!value.IsScalar() || !YAML::convert<double>::decode(value, size)) {
    errors.fail(value, "size_mm", "expected a number (mm), got " + describe_yaml_node(value));
  }
  if (!std::isfinite(size) || size <= 0.0) {
    std::ostringstream reason;
    reason << "must be a finite size > 0 mm, got " << value.Scalar();
    errors.fail(value, "size_mm", reason.str());
  }
  return size;
}

bool symmetric_flag(const YamlInputErrors& errors, const YAML::Node& value) {
  bool flag = false;
  if (!value.IsScalar() || !YAML::convert<bool>::decode(value, flag)) {
    errors.fail(value, "symmetric", "expected true or false, got " + describe_yaml_node(value));
  }
  return flag;
}

// Map entries by key, refusing keys outside `allowed` and keys given twice (yaml-cpp would
// silently keep the first).
std::map<std::string, YAML::Node> keyed_entries(const YamlInputErrors& errors,
                                                const YAML::Node& map,
                                                const std::set<std::string>& allowed,
                                                const std::string& allowed_text) {
  std::map<std::string, YAML::Node> entries;
  for (const auto& item : map) {
    const std::string key =
        item.first.IsScalar() ? item.first.Scalar() : describe_yaml_node(item.first);
    if (allowed.count(key) == 0)
      errors.fail(item.first, key, "unknown key (expected " + allowed_text + ")");
    if (!entries.emplace(key, item.second).second) errors.fail(item.first, key, "key given twice");
  }
  return entries;
}

PartEntry read_part(const YamlInputErrors& errors, const YAML::Node& node, const fs::path& yaml_dir,
                    const fs::path& mesh_dir) {
  if (!node.IsMap())
    errors.fail(node, "parts", "each part must be a map, got " + describe_yaml_node(node));
  const auto entries = keyed_entries(errors, node, {"name", "mesh", "size_mm", "symmetric"},
                                     "name, mesh, size_mm, symmetric");
  for (const char* required : {"name", "mesh", "size_mm"}) {
    if (entries.count(required) == 0) errors.fail(node, required, "missing key");
  }
  PartEntry part;
  part.name = part_name(errors, entries.at("name"));
  part.mesh_path =
      resolve_mesh(scalar_string(errors, entries.at("mesh"), "mesh"), yaml_dir, mesh_dir)
          .lexically_normal();
  part.size_mm = size_mm(errors, entries.at("size_mm"));
  if (const auto it = entries.find("symmetric"); it != entries.end()) {
    part.symmetric = symmetric_flag(errors, it->second);
  }
  return part;
}

}  // namespace

const PartEntry* PartCatalog::find(std::string_view name) const {
  for (const PartEntry& part : parts) {
    if (part.name == name) return &part;
  }
  return nullptr;
}

const PartEntry& PartCatalog::at(std::string_view name) const {
  if (const PartEntry* part = find(name)) return *part;
  std::string known;
  for (const PartEntry& part : parts) known += (known.empty() ? "" : ", ") + part.name;
  throw InputError("unknown part '" + std::string(name) + "' in " + file.string() +
                   " (known: " + known + ")");
}

PartCatalog read_part_catalog(const fs::path& yaml_path, const fs::path& mesh_cache_dir) {
  const YamlInputErrors errors(yaml_path);
  const YAML::Node root = errors.load_file("part catalog");
  if (!root.IsMap())
    errors.fail_line(root.Mark().line, "parts", "the catalog must be a map with a 'parts' list");
  const auto entries = keyed_entries(errors, root, {"mesh_dir", "parts"}, "mesh_dir, parts");

  const fs::path yaml_dir = fs::absolute(yaml_path).parent_path();
  fs::path mesh_dir = fs::absolute(mesh_cache_dir);
  if (const auto it = entries.find("mesh_dir"); it != entries.end()) {
    mesh_dir = expand(scalar_string(errors, it->second, "mesh_dir"), yaml_dir);
  }

  const auto parts = entries.find("parts");
  if (parts == entries.end()) errors.fail_line(root.Mark().line, "parts", "missing key");
  if (!parts->second.IsSequence() || parts->second.size() == 0) {
    errors.fail(parts->second, "parts",
                "expected a non-empty list of parts, got " + describe_yaml_node(parts->second));
  }

  PartCatalog catalog;
  catalog.file = fs::absolute(yaml_path).lexically_normal();
  std::map<std::string, int> first_line;
  for (const YAML::Node& node : parts->second) {
    PartEntry part = read_part(errors, node, yaml_dir, mesh_dir);
    const YAML::Node name_node = node["name"];
    const int line0 = name_node.Mark().line;
    if (const auto seen = first_line.find(part.name); seen != first_line.end()) {
      errors.fail(name_node, "name",
                  "duplicate part '" + part.name + "' (first at line " +
                      std::to_string(seen->second + 1) + ")");
    }
    first_line.emplace(part.name, line0);
    catalog.parts.push_back(std::move(part));
  }
  return catalog;
}

PartCatalog read_part_catalog(const fs::path& yaml_path) {
  return read_part_catalog(yaml_path, default_mesh_cache_dir());
}

fs::path default_mesh_cache_dir() {
  if (const char* cache = std::getenv("COSMOS_CACHE_DIR"); cache != nullptr && *cache != '\0') {
    return fs::path(cache) / "meshes";
  }
  return home_dir() / ".cache" / "cosmos-cell" / "meshes";
}

fs::path find_part_catalog(const fs::path& explicit_path) {
  if (!explicit_path.empty()) return explicit_path;
  std::error_code error;
  const fs::path in_current_dir = fs::current_path(error) / "config" / "parts.yaml";
  if (!error && fs::is_regular_file(in_current_dir, error)) return in_current_dir;
  std::string tried = in_current_dir.string();
  const fs::path executable = fs::read_symlink("/proc/self/exe", error);
  if (!error) {
    const fs::path beside_build =
        (executable.parent_path() / ".." / ".." / "config" / "parts.yaml").lexically_normal();
    if (fs::is_regular_file(beside_build, error)) return beside_build;
    if (beside_build != in_current_dir) tried += " and " + beside_build.string();
  }
  throw InputError("no part catalog found (looked for " + tried + "): pass --catalog FILE");
}

}  // namespace cosmos
