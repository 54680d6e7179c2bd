#include "calibration/target_file.hpp"

#include <yaml-cpp/yaml.h>

#include <fstream>

#include "core/input_error.hpp"
#include "core/io/yaml_input_errors.hpp"

namespace cosmos {
namespace {

namespace fs = std::filesystem;

double positive_number(const YamlInputErrors& errors, const YAML::Node& map, const char* key) {
  const YAML::Node node = map[key];
  if (!node.IsDefined()) errors.fail(map, key, "missing");
  double value = 0.0;
  if (!node.IsScalar() || !YAML::convert<double>::decode(node, value))
    errors.fail(node, key, "expected a number");
  if (!(value > 0.0)) errors.fail(node, key, "must be positive");
  return value;
}

YAML::Node load_map(const YamlInputErrors& errors, const char* what) {
  const YAML::Node root = errors.load_file(what);
  if (!root.IsMap()) errors.fail_line(root.Mark().line, what, "expected a map of keys");
  return root;
}

void write_text(const fs::path& file, const YAML::Emitter& out) {
  std::ofstream stream(file);
  stream << out.c_str() << '\n';
  if (!stream) throw InputError(file.string() + ": cannot write");
}

}  // namespace

RampBlock read_ramp_target(const fs::path& file) {
  const YamlInputErrors errors(file);
  const YAML::Node root = load_map(errors, "ramp target");
  RampBlock block;
  block.length_mm = positive_number(errors, root, "length_mm");
  block.width_mm = positive_number(errors, root, "width_mm");
  block.low_height_mm = positive_number(errors, root, "low_height_mm");
  block.high_height_mm = positive_number(errors, root, "high_height_mm");
  if (block.high_height_mm <= block.low_height_mm)
    errors.fail(root["high_height_mm"], "high_height_mm", "must exceed low_height_mm");
  return block;
}

SpherePlate read_sphere_target(const fs::path& file) {
  const YamlInputErrors errors(file);
  const YAML::Node root = load_map(errors, "sphere target");
  SpherePlate plate;
  plate.radius_mm = positive_number(errors, root, "radius_mm");
  plate.plate_height_mm = positive_number(errors, root, "plate_height_mm");
  const YAML::Node ticks = root["encoder_ticks"];
  if (!ticks.IsDefined() || !ticks.IsScalar() ||
      !YAML::convert<std::int64_t>::decode(ticks, plate.encoder_ticks))
    errors.fail(ticks.IsDefined() ? ticks : root, "encoder_ticks", "expected a whole number");
  const YAML::Node centres = root["centres_cell_mm"];
  if (!centres.IsSequence())
    errors.fail(centres.IsDefined() ? centres : root, "centres_cell_mm",
                "expected a list of [x, y, z]");
  for (const YAML::Node& centre : centres) {
    if (!centre.IsSequence() || centre.size() != 3)
      errors.fail(centre, "centres_cell_mm", "expected [x, y, z]");
    Eigen::Vector3d c;
    for (std::size_t k = 0; k < 3; ++k) {
      if (!YAML::convert<double>::decode(centre[k], c(static_cast<Eigen::Index>(k))))
        errors.fail(centre[k], "centres_cell_mm", "expected a number");
    }
    plate.centres_cell_mm.push_back(c);
  }
  return plate;
}

void write_ramp_target(const fs::path& file, const RampBlock& block) {
  YAML::Emitter out;
  out << YAML::BeginMap << YAML::Key << "length_mm" << YAML::Value << block.length_mm << YAML::Key
      << "width_mm" << YAML::Value << block.width_mm << YAML::Key << "low_height_mm" << YAML::Value
      << block.low_height_mm << YAML::Key << "high_height_mm" << YAML::Value << block.high_height_mm
      << YAML::EndMap;
  write_text(file, out);
}

void write_sphere_target(const fs::path& file, const SpherePlate& plate) {
  YAML::Emitter out;
  out.SetDoublePrecision(10);
  out << YAML::BeginMap << YAML::Key << "radius_mm" << YAML::Value << plate.radius_mm << YAML::Key
      << "plate_height_mm" << YAML::Value << plate.plate_height_mm << YAML::Key << "encoder_ticks"
      << YAML::Value << plate.encoder_ticks << YAML::Key << "centres_cell_mm" << YAML::Value
      << YAML::BeginSeq;
  for (const Eigen::Vector3d& c : plate.centres_cell_mm)
    out << YAML::Flow << YAML::BeginSeq << c.x() << c.y() << c.z() << YAML::EndSeq;
  out << YAML::EndSeq << YAML::EndMap;
  write_text(file, out);
}

}  // namespace cosmos
