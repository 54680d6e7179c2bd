#include "sim/evaluation/evaluation_scans.hpp"

#include <algorithm>

#include "core/input_error.hpp"
#include "sim/part_pose.hpp"
#include "sim/part_scan.hpp"
#include "sim/seeded_random.hpp"

namespace cosmos {
namespace {

constexpr std::size_t kAddSPoints = 2000;
constexpr std::uint64_t kTestStreamBase = std::uint64_t{1} << 32;

std::vector<Eigen::Vector3d> spread_vertices(const TriangleMesh& mesh) {
  const std::size_t step = std::max<std::size_t>(1, mesh.vertices.size() / kAddSPoints);
  std::vector<Eigen::Vector3d> points;
  for (std::size_t i = 0; i < mesh.vertices.size(); i += step)
    points.push_back(mesh.vertices[i].cast<double>());
  return points;
}

EvaluationPart load_evaluation_part(const PartEntry& entry, int catalog_index, int base_index) {
  EvaluationPart part;
  part.name = entry.name;
  part.catalog_index = catalog_index;
  part.base_index = base_index;
  part.symmetric = entry.symmetric;
  part.mesh_path = entry.mesh_path.string();
  part.mesh = load_mesh(entry.mesh_path, entry.size_mm);
  part.model_points_mm = spread_vertices(part.mesh);
  part.diameter_mm = bounding_box(part.mesh).diagonal().norm();
  return part;
}

// Whether base part `base_part` is another size of `part`'s mesh.
bool is_size_variant(const ModelBase& base, const std::vector<EvaluationPart>& parts,
                     const EvaluationPart& part, int base_part) {
  if (base_part < 0 || base_part == part.base_index) return false;
  const std::string& name = base.parts[static_cast<std::size_t>(base_part)].name;
  for (const EvaluationPart& other : parts)
    if (other.name == name) return other.mesh_path == part.mesh_path;
  return false;
}

int catalog_index(const PartCatalog& catalog, const std::string& name) {
  for (std::size_t i = 0; i < catalog.parts.size(); ++i)
    if (catalog.parts[i].name == name) return static_cast<int>(i);
  return -1;
}

}  // namespace

std::vector<EvaluationPart> evaluation_parts(const ModelBase& base, const PartCatalog& catalog,
                                             const std::vector<std::string>& unknown_names) {
  std::vector<EvaluationPart> parts;
  for (std::size_t b = 0; b < base.parts.size(); ++b) {
    const int c = catalog_index(catalog, base.parts[b].name);
    if (c < 0)
      throw InputError(catalog.file.string() + ": has no part '" + base.parts[b].name +
                       "', which the model base holds");
    parts.push_back(
        load_evaluation_part(catalog.parts[static_cast<std::size_t>(c)], c, static_cast<int>(b)));
    // The base's diameter is the true one (farthest vertex pair), not the box diagonal.
    parts.back().diameter_mm = base.parts[b].diameter_mm;
  }
  for (const std::string& name : unknown_names) {
    const int c = catalog_index(catalog, name);
    if (c < 0) throw InputError("--unknown " + name + ": not in " + catalog.file.string());
    for (const ModelPart& known : base.parts)
      if (known.name == name) throw InputError("--unknown " + name + ": the model base holds it");
    parts.push_back(load_evaluation_part(catalog.parts[static_cast<std::size_t>(c)], c, -1));
  }
  return parts;
}

std::vector<EvaluationTest> evaluation_plan(const std::vector<EvaluationPart>& parts, int tests,
                                            std::uint64_t seed, EvaluationPoseMode pose) {
  std::vector<int> known, unknown;
  for (std::size_t p = 0; p < parts.size(); ++p)
    (parts[p].base_index >= 0 ? known : unknown).push_back(static_cast<int>(p));
  std::vector<EvaluationTest> plan;
  if (known.empty()) return plan;
  std::uint64_t stream = kTestStreamBase;
  for (int i = 0; i < tests; ++i, ++stream) {
    const std::uint64_t test_seed = mix_seed(seed, stream);
    plan.push_back(
        {known[test_seed % known.size()], test_seed, static_cast<int>(plan.size()), pose});
  }
  const int per_part =
      (tests + static_cast<int>(known.size()) - 1) / static_cast<int>(known.size());
  for (int part : unknown)
    for (int i = 0; i < per_part; ++i, ++stream)
      plan.push_back({part, mix_seed(seed, stream), static_cast<int>(plan.size()), pose});
  return plan;
}

RangeImage scan_evaluation_test(const EvaluationTest& test,
                                const std::vector<EvaluationPart>& parts,
                                const ScannerParameters& scanner,
                                const ConditioningParameters& conditioning) {
  const EvaluationPart& part = parts[static_cast<std::size_t>(test.part)];
  ScannerParameters noisy = scanner;
  noisy.seed = mix_seed(test.seed, 1);
  const std::uint64_t pose_seed = mix_seed(test.seed, 0);
  const Eigen::Matrix3d rotation = test.pose == EvaluationPoseMode::kResting
                                       ? resting_rotation(part.mesh, pose_seed)
                                       : random_rotation(pose_seed);
  return scan_single_part(part.mesh, part.name, rotation, noisy, conditioning);
}

EvaluationRecord run_evaluation_test(const EvaluationTest& test,
                                     const std::vector<EvaluationPart>& parts,
                                     const ScannerParameters& scanner,
                                     const ConditioningParameters& conditioning,
                                     const Recognizer& recognizer, const ModelBase& base,
                                     ViewAnalysisWorkspace& workspace) {
  const EvaluationPart& part = parts[static_cast<std::size_t>(test.part)];
  const RangeImage image = scan_evaluation_test(test, parts, scanner, conditioning);
  const RecognitionResult result = recognizer.recognize(image, workspace);

  EvaluationRecord record;
  record.test_index = test.index;
  record.truth_part = part.catalog_index;
  record.truth_name = part.name;
  record.truth_in_model_base = part.base_index >= 0;
  record.truth_symmetric = part.symmetric;
  record.diameter_mm = part.diameter_mm;
  record.rejected = result.status != RecognitionStatus::kOk;
  if (record.rejected) record.rejection_reason = result.reason;
  if (part.base_index >= 0) {
    for (std::size_t b = 0; b < base.parts.size(); ++b)
      record.truth_has_size_variants |= is_size_variant(base, parts, part, static_cast<int>(b));
    const bool ambiguous = record.rejected && result.ambiguity.ambiguous;
    record.taken_for_size_variant =
        (!record.rejected && is_size_variant(base, parts, part, result.part)) ||
        (ambiguous && (is_size_variant(base, parts, part, result.best_candidate_part) ||
                       is_size_variant(base, parts, part, result.runner_up_part)));
  }
  if (!record.rejected) {
    const std::string& name = base.parts[static_cast<std::size_t>(result.part)].name;
    for (const EvaluationPart& candidate : parts)
      if (candidate.name == name) record.predicted_part = candidate.catalog_index;
    record.predicted_name = name;
  }
  if (part.base_index >= 0) {
    const std::vector<int> ranking = recognizer.selector().rank_clusters(result.moments);
    for (std::size_t r = 0; r < ranking.size() && record.true_cluster_rank < 0; ++r)
      if (base.clusters[static_cast<std::size_t>(ranking[r])].part_index == part.base_index)
        record.true_cluster_rank = static_cast<int>(r);
    for (const RecognitionCandidate& candidate : result.candidates)
      record.true_part_among_selected_views |=
          !candidate.searched_over_views() && candidate.part == part.base_index;
    record.quick_fits_ranked = !result.quick_fits.empty();
    for (std::size_t r = 0; r < result.quick_fits.size(); ++r)
      if (result.quick_fits[r].part == part.base_index)
        record.true_part_quick_fit_rank = static_cast<int>(r);
  }
  record.fraction_db_examined =
      base.views.empty() ? 0.0 : static_cast<double>(result.views_examined) / base.views.size();
  if (image.ground_truth) {
    record.R_true = image.ground_truth->rotation;
    record.t_true_mm = image.ground_truth->translation_mm;
  }
  record.R_estimated = result.T_scanner_part.rotation;
  record.t_estimated_mm = result.T_scanner_part.translation_mm;
  record.recognition_ms = result.timings.total_ms;
  record.features_ms = result.timings.features_ms;
  record.matching_ms = result.timings.matching_ms;
  record.registration_ms = result.timings.registration_ms;
  for (const RecognitionCandidate& candidate : result.candidates)
    record.pose_searched |= candidate.from_pose_search;
  record.catalog_searched = result.catalog_searched;
  record.parts_left_out_by_size = result.parts_smaller_than_scene + result.parts_thicker_than_scene;
  record.parts_left_out_by_signature = result.parts_left_out_by_signature;
  record.confusable_parts_searched = static_cast<int>(result.confusable_parts_searched.size());
  record.resting_searched = result.resting_searched;
  record.thin_scene = result.thin_scene;
  record.score = result.score;
  if (result.runner_up_part >= 0) {
    record.runner_up_name = base.parts[static_cast<std::size_t>(result.runner_up_part)].name;
    record.runner_up_score = result.runner_up_score;
  }
  record.ambiguity_examined = result.ambiguity_examined;
  record.discriminating_fraction = result.ambiguity.discriminating_fraction;
  record.discriminating_share = result.ambiguity.discriminating_share;
  record.seen_fraction = result.seen_fraction;
  record.runner_up_seen_fraction = result.runner_up_seen_fraction;
  return record;
}

}  // namespace cosmos
