#include "realtime/config/cell_config.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>

#include "core/io/yaml_input_errors.hpp"
#include "core/io/yaml_parameter_reader.hpp"
#include "realtime/loop/sheet_deshear.hpp"
#include "scanner/scanner_config.hpp"

namespace cosmos {
namespace {

namespace fs = std::filesystem;

// Profiles wider than this are a typo (65,536 columns of 0.4 mm are 26 m of belt).
constexpr double kMaxGridColumns = 65536.0;

fs::path resolve(const fs::path& path, const fs::path& config_file) {
  return path.empty() || path.is_absolute() ? path : config_file.parent_path() / path;
}

// Each section by its struct's visit(), then the rules between its keys.
template <class Section>
void read_section(YamlSectionReader& section, const fs::path&, Section& parameters) {
  read_yaml_parameters(section, parameters);
}

void read_section(YamlSectionReader& section, const fs::path&, ScannerParameters& scanner) {
  read_scanner_section(section, scanner);
}

void read_section(YamlSectionReader& section, const fs::path& file, CellSettings& cell) {
  read_yaml_parameters(section, cell);
  cell.catalog = resolve(cell.catalog, file);
  cell.model_base = resolve(cell.model_base, file);
}

void read_section(YamlSectionReader& section, const fs::path&, ConditioningParameters& p) {
  read_yaml_parameters(section, p);
  // Reported at a key the file gave (the section when it gave neither).
  if (p.x_max_mm <= p.x_min_mm) {
    section.fail(section.has("x_max_mm") ? "x_max_mm" : "x_min_mm",
                 "x_max_mm must exceed x_min_mm");
  }
  if ((p.x_max_mm - p.x_min_mm) / p.grid_mm > kMaxGridColumns) {
    section.fail("grid_mm", "gives more than 65536 columns across [x_min_mm, x_max_mm)");
  }
  if (SheetDeshear::window_rows(p) > SheetDeshear::kMaxWindowRows) {
    section.fail(section.has("max_height_mm") ? "max_height_mm" : "sheet_pitch_deg",
                 "gives a de-shear window of more than 4096 rows (max_height_mm * "
                 "|tan(sheet_pitch_deg)| / grid_mm)");
  }
}

// Visits CellConfig: every section of the file.
class SectionLoader {
 public:
  SectionLoader(YamlSectionReader& root, const fs::path& file) : root_(root), file_(file) {}

  template <class Section>
  void operator()(const char* name, Section& section, const char*) {
    YamlSectionReader reader(root_.errors(), root_.value(name), name);
    read_section(reader, file_, section);
  }

 private:
  YamlSectionReader& root_;
  const fs::path& file_;
};

}  // namespace

int CellConfig::max_part_rows() const {
  return std::max(
      1, static_cast<int>(std::ceil(tracking.max_part_length_mm / scanner.profile_step_mm())));
}

CellConfig load_cell_config(const fs::path& yaml_path) {
  const YamlInputErrors errors(yaml_path);
  const YAML::Node root = errors.load_file("config file");
  if (!root.IsNull() && !root.IsMap()) {
    errors.fail_line(root.Mark().line, "config",
                     "expected a map of sections, got " + describe_yaml_node(root));
  }
  CellConfig config;
  config.file = yaml_path;
  // A null root (an empty file) reads every section as absent: all defaults.
  YamlSectionReader sections(errors, root, "");
  SectionLoader loader(sections, yaml_path);
  config.visit(loader);
  sections.reject_unknown_keys();
  return config;
}

}  // namespace cosmos
