#pragma once
// The test scans of `cosmos eval`: which part each test scans, in which pose and with which
// noise, and the record its recognition gives (sim/evaluation/evaluation_metrics.hpp).
//
// Test i of a run with seed S scans known part (mix_seed(S, i) mod the known parts) in a pose
// drawn from mix_seed(S, i) and noise from another stream of it, so the plan is fixed by
// (S, N, pose mode) alone. The pose is uniformly random over SO(3), or one of the part's
// stable resting poses on the belt (sim/part_pose.hpp), as parts arrive on a real conveyor. The
// model views are scanned with the scanner's own seed stream (per view index), the tests with
// streams of S above 2^32: the two never share noise. Unknown parts (in the catalog, not in the
// base) are scanned as many times each as an average known part, with seeds following the known
// tests'.
#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

#include "core/modelbase/model_base.hpp"
#include "core/recognition/recognizer.hpp"
#include "scanner/conditioning_parameters.hpp"
#include "scanner/scanner_model.hpp"
#include "sim/evaluation/evaluation_metrics.hpp"
#include "sim/mesh.hpp"
#include "sim/part_catalog.hpp"

namespace cosmos {

struct EvaluationPart {
  std::string name;
  int catalog_index = -1;
  int base_index = -1;  // -1: not in the model base (an unknown part)
  bool symmetric = false;
  double diameter_mm = 0;
  std::string mesh_path;  // parts of one mesh at several sizes are size variants
  TriangleMesh mesh;
  std::vector<Eigen::Vector3d> model_points_mm;  // part-frame subsample for ADD-S
};

enum class EvaluationPoseMode { kRandom, kResting };

struct EvaluationTest {
  int part = 0;  // index into the parts list
  std::uint64_t seed = 0;
  int index = 0;  // position in the whole plan: the number the report shows
  EvaluationPoseMode pose = EvaluationPoseMode::kRandom;
};

// Known parts: the base's parts, found in the catalog by name (InputError naming a base part
// the catalog lacks); then the unknown ones (InputError for a name not in the catalog or one
// that is in the base).
std::vector<EvaluationPart> evaluation_parts(const ModelBase& base, const PartCatalog& catalog,
                                             const std::vector<std::string>& unknown_names);

std::vector<EvaluationTest> evaluation_plan(const std::vector<EvaluationPart>& parts, int tests,
                                            std::uint64_t seed,
                                            EvaluationPoseMode pose = EvaluationPoseMode::kRandom);

// The test's scan: its part in the test's pose (random or resting), with the test's noise, losing
// the belt at the conditioning's threshold (that of the base's views).
RangeImage scan_evaluation_test(const EvaluationTest& test,
                                const std::vector<EvaluationPart>& parts,
                                const ScannerParameters& scanner,
                                const ConditioningParameters& conditioning);

// Scans the test's part and recognizes it, analysing the scan with `workspace` (the calling
// thread's). Thread-safe: everything else shared is read-only.
EvaluationRecord run_evaluation_test(const EvaluationTest& test,
                                     const std::vector<EvaluationPart>& parts,
                                     const ScannerParameters& scanner,
                                     const ConditioningParameters& conditioning,
                                     const Recognizer& recognizer, const ModelBase& base,
                                     ViewAnalysisWorkspace& workspace);

}  // namespace cosmos
