#include "sim/source/simulated_conveyor.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

#include "core/input_error.hpp"
#include "sim/part_pose.hpp"
#include "sim/seeded_random.hpp"
#include "sim/source/part_layout.hpp"

namespace cosmos {
namespace {

// Independent random streams from the one settings seed.
constexpr std::uint64_t kSequenceStream = 0x5E9;
constexpr std::uint64_t kPoseStream = 0x9053;

void check_settings(const SimulatedConveyorSettings& settings) {
  if (settings.parts < 1) throw std::invalid_argument("simulated source: parts must be >= 1");
  if (!std::isfinite(settings.part_gap_mm) || settings.part_gap_mm < 0.0) {
    throw std::invalid_argument("simulated source: part_gap_mm must be >= 0");
  }
  if (!std::isfinite(settings.part_gap_max_mm) || !std::isfinite(settings.across_gap_mm) ||
      settings.across_gap_mm < 0.0) {
    throw std::invalid_argument(
        "simulated source: part_gap_max_mm and across_gap_mm must be finite, across_gap_mm >= 0");
  }
  if (!std::isfinite(settings.edge_margin_mm) || settings.edge_margin_mm < 0.0) {
    throw std::invalid_argument("simulated source: edge_margin_mm must be >= 0");
  }
}

std::string joined(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& name : names) text.append(text.empty() ? "" : ", ").append(name);
  return text;
}

// Indices (into `names`) of the parts the stream may draw from, in `names` order.
std::vector<std::size_t> allowed_parts(const std::vector<std::string>& names,
                                       const std::vector<std::string>& wanted,
                                       const std::string& source) {
  if (names.empty()) throw InputError(source + ": no parts to simulate");
  std::vector<std::size_t> allowed;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (wanted.empty() || std::find(wanted.begin(), wanted.end(), names[i]) != wanted.end()) {
      allowed.push_back(i);
    }
  }
  for (const std::string& name : wanted) {
    if (std::find(names.begin(), names.end(), name) == names.end()) {
      throw InputError("unknown part '" + name + "' in " + source + " (known: " + joined(names) +
                       ")");
    }
  }
  return allowed;
}

// The stream's parts, uniformly over the allowed ones: an entry of `allowed` per position.
std::vector<std::size_t> draw_sequence(const std::vector<std::size_t>& allowed,
                                       const SimulatedConveyorSettings& settings) {
  SeededRandom random(mix_seed(settings.seed, kSequenceStream));
  const auto count = static_cast<double>(allowed.size());
  std::vector<std::size_t> sequence;
  for (int i = 0; i < settings.parts; ++i) {
    const auto pick = static_cast<std::size_t>(std::floor(random.uniform() * count));
    sequence.push_back(allowed[std::min(pick, allowed.size() - 1)]);
  }
  return sequence;
}

Eigen::AlignedBox3d rotated_box(const TriangleMesh& mesh, const Eigen::Matrix3d& R) {
  Eigen::AlignedBox3d box;
  for (const Eigen::Vector3f& v : mesh.vertices) box.extend(R * v.cast<double>());
  return box;
}

}  // namespace

SimulatedConveyor::SimulatedConveyor(const PartCatalog& catalog,
                                     const ScannerParameters& parameters,
                                     const SimulatedConveyorSettings& settings)
    : parameters_(parameters) {
  check_settings(settings);
  std::vector<std::string> names;
  for (const PartEntry& part : catalog.parts) names.push_back(part.name);
  const std::vector<std::size_t> picks =
      draw_sequence(allowed_parts(names, settings.part_names, catalog.file.string()), settings);
  // Only the drawn meshes are loaded: a short stream need not read the whole catalog.
  std::map<std::size_t, std::size_t> model_of_catalog_index;
  std::vector<SimPartModel> models;
  for (const std::size_t index : picks) {
    if (model_of_catalog_index.count(index) != 0) continue;
    const PartEntry& part = catalog.parts[index];
    model_of_catalog_index[index] = models.size();
    models.push_back({part.name, load_mesh(part.mesh_path, part.size_mm), static_cast<int>(index)});
  }
  std::vector<const SimPartModel*> model_pointers;
  for (const SimPartModel& model : models) model_pointers.push_back(&model);
  std::vector<std::size_t> model_picks;
  for (const std::size_t index : picks) model_picks.push_back(model_of_catalog_index[index]);
  build(model_pointers, model_picks, settings);
}

SimulatedConveyor::SimulatedConveyor(const std::vector<SimPartModel>& models,
                                     const ScannerParameters& parameters,
                                     const SimulatedConveyorSettings& settings)
    : parameters_(parameters) {
  check_settings(settings);
  std::vector<std::string> names;
  std::vector<const SimPartModel*> model_pointers;
  for (const SimPartModel& model : models) {
    names.push_back(model.name);
    model_pointers.push_back(&model);
  }
  build(model_pointers,
        draw_sequence(allowed_parts(names, settings.part_names, "the part list"), settings),
        settings);
}

SimulatedConveyor::~SimulatedConveyor() = default;

void SimulatedConveyor::build(const std::vector<const SimPartModel*>& models,
                              const std::vector<std::size_t>& picks,
                              const SimulatedConveyorSettings& settings) {
  scene_ = std::make_unique<ConveyorScene>();
  std::vector<int> scene_mesh(models.size(), -1);
  const double step_mm = parameters_.profile_step_mm();
  std::vector<Eigen::Matrix3d> rotations;
  std::vector<Eigen::Vector3d> box_sizes_mm;
  for (std::size_t i = 0; i < picks.size(); ++i) {
    const SimPartModel& model = *models[picks[i]];
    const std::uint64_t pose_seed = mix_seed(mix_seed(settings.seed, kPoseStream), i);
    rotations.push_back(settings.pose == PoseMode::kResting
                            ? resting_rotation(model.mesh, pose_seed)
                            : random_rotation(pose_seed));
    box_sizes_mm.push_back(rotated_box(model.mesh, rotations.back()).sizes());
  }
  const std::vector<PartPlacement> placements =
      lay_out_parts(box_sizes_mm, settings, 0.5 * parameters_.field_of_view_mm);
  for (std::size_t i = 0; i < picks.size(); ++i) {
    const SimPartModel& model = *models[picks[i]];
    if (scene_mesh[picks[i]] < 0) scene_mesh[picks[i]] = scene_->add_mesh(model.mesh);
    const int part = scene_->add_part(
        model.name, scene_mesh[picks[i]],
        place_on_belt(model.mesh, rotations[i], placements[i].x_mm, placements[i].y_mm));
    const PlacedPart& placed = scene_->parts()[static_cast<std::size_t>(part)];
    PlacedSimPart truth;
    truth.catalog_index = model.catalog_index;
    truth.name = model.name;
    truth.scene_mesh = scene_mesh[picks[i]];
    truth.T_belt_part = placed.T_belt_part;
    truth.bounds_mm = placed.bounds_mm;
    // Profile k's sheet is at y = −k · Δy: inside the box for −y_max <= k · Δy <= −y_min.
    truth.first_profile =
        static_cast<std::int64_t>(std::ceil(-placed.bounds_mm.max().y() / step_mm));
    truth.last_profile =
        static_cast<std::int64_t>(std::floor(-placed.bounds_mm.min().y() / step_mm));
    placed_.push_back(truth);
  }
  scene_->commit();
  // The tolerance keeps a gap of a whole number of steps from gaining one through rounding.
  std::int64_t last_part_profile = 0;
  for (const PlacedSimPart& part : placed_)
    last_part_profile = std::max(last_part_profile, part.last_profile);
  last_profile_ = last_part_profile +
                  static_cast<std::int64_t>(std::ceil(lead_in_mm(settings) / step_mm - 1e-9));
}

const PlacedSimPart* SimulatedConveyor::placed_part_scanned_in(std::int64_t first_profile,
                                                               std::int64_t last_profile) const {
  const PlacedSimPart* best = nullptr;
  std::int64_t best_overlap = 0;
  for (const PlacedSimPart& part : placed_) {
    const std::int64_t overlap =
        std::min(last_profile, part.last_profile) - std::max(first_profile, part.first_profile) + 1;
    if (overlap > best_overlap) {
      best = &part;
      best_overlap = overlap;
    }
  }
  return best;
}

}  // namespace cosmos

namespace cosmos {

const PlacedSimPart* SimulatedConveyor::placed_part_at(const Eigen::Vector3d& point_belt_mm,
                                                       std::int64_t first_profile,
                                                       std::int64_t last_profile) const {
  const PlacedSimPart* best = nullptr;
  double best_distance_mm = 0;
  for (const PlacedSimPart& part : placed_) {
    if (part.last_profile < first_profile || part.first_profile > last_profile) continue;
    // A pose's position is the part frame's origin, a rejection's a centroid of surface:
    // both lie in or near the part's box, and the origin tells touching parts apart.
    const double distance_mm = std::sqrt(part.bounds_mm.squaredExteriorDistance(point_belt_mm)) +
                               (part.T_belt_part.translation() - point_belt_mm).norm();
    if (!best || distance_mm < best_distance_mm) {
      best = &part;
      best_distance_mm = distance_mm;
    }
  }
  return best;
}

}  // namespace cosmos
