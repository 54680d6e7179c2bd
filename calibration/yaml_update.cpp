#include "calibration/yaml_update.hpp"

#include <cmath>
#include <fstream>
#include <numbers>

#include "core/input_error.hpp"

namespace cosmos {

YAML::Node yaml_of_transform(const RigidTransform& T) {
  const Eigen::Matrix3d& r = T.rotation;
  constexpr double kDegPerRad = 180.0 / std::numbers::pi;
  // R = Rz(γ) Ry(β) Rx(α): r20 = −sin β, r21 = cos β sin α, r10 = sin γ cos β.
  const double beta = std::asin(std::clamp(-r(2, 0), -1.0, 1.0));
  const double alpha = std::atan2(r(2, 1), r(2, 2));
  const double gamma = std::atan2(r(1, 0), r(0, 0));
  YAML::Node node(YAML::NodeType::Map);
  YAML::Node rotation(YAML::NodeType::Sequence);
  rotation.SetStyle(YAML::EmitterStyle::Flow);
  for (double angle : {alpha, beta, gamma}) rotation.push_back(angle * kDegPerRad);
  YAML::Node translation(YAML::NodeType::Sequence);
  translation.SetStyle(YAML::EmitterStyle::Flow);
  for (int k = 0; k < 3; ++k) translation.push_back(T.translation_mm(k));
  node["rotation_deg"] = rotation;
  node["translation_mm"] = translation;
  return node;
}

namespace {

// Fresh handles at every level (copy construction, never Node assignment, which in yaml-cpp
// would re-point a handle rather than set the tree's child).
void set_at(YAML::Node map, const std::string& dotted, const YAML::Node& value) {
  const std::size_t dot = dotted.find('.');
  const std::string key = dotted.substr(0, dot);
  if (dot == std::string::npos) {
    map[key] = value;
    return;
  }
  if (!map[key].IsMap()) map[key] = YAML::Node(YAML::NodeType::Map);
  set_at(map[key], dotted.substr(dot + 1), value);
}

}  // namespace

void update_yaml_file(const std::filesystem::path& file, const YamlEntries& entries) {
  YAML::Node root(YAML::NodeType::Map);
  if (std::filesystem::exists(file)) {
    try {
      root = YAML::LoadFile(file.string());
    } catch (const YAML::Exception& error) {
      throw InputError(file.string() + ": " + error.what());
    }
    if (root.IsNull()) root = YAML::Node(YAML::NodeType::Map);
    if (!root.IsMap()) throw InputError(file.string() + ": expected a map of sections");
  }
  for (const auto& [dotted, value] : entries) set_at(root, dotted, value);
  YAML::Emitter out;
  out.SetDoublePrecision(12);
  out << root;
  std::ofstream stream(file);
  stream << out.c_str() << '\n';
  if (!stream) throw InputError(file.string() + ": cannot write");
}

}  // namespace cosmos
