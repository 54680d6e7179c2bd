#pragma once
// The report of `cosmos eval`: files a person opens after a run, written into one directory
// (created if missing):
//   metrics.json             metrics_json(metrics), pretty-printed: the stable keys.
//   confusion_matrix.png     rows the true parts (base parts, then unknown ones), columns the
//                            predicted parts and "rejected"; cells shaded by count.
//   cluster_rate.png         correct-part rate vs spectral clusters examined (thesis Fig. 4.8).
//   rotation_error_cdf.png   empirical CDF of the rotation error, correct asymmetric parts.
//   report.html              self-contained page: the metrics, the three images (relative
//                            links) and one row per test.
//   tests.json               one object per test, for scripts (bench/catalog_scaling.sh):
//                            test, truth, truth_in_model_base, predicted (null when
//                            rejected), status (record_status_name), reason, recognition_ms
//                            and its features_ms, matching_ms and registration_ms,
//                            pose_searched, catalog_searched, parts_left_out_by_size,
//                            parts_left_out_by_signature, confusable_parts_searched,
//                            resting_searched, thin_scene,
//                            truth_has_size_variants, taken_for_size_variant,
//                            add_s_over_diameter (null where it does not apply).
// Part labels come from part_names (catalog index -> name), falling back to the names in the
// records for indices it does not cover.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <span>
#include <string>

#include "sim/evaluation/evaluation_metrics.hpp"

namespace cosmos {

// `metrics` must be compute_metrics(records, ...) (std::invalid_argument when its per-record
// outcomes do not match the records). A directory or file that cannot be written throws
// InputError with one line naming the path.
void write_evaluation_report(const std::filesystem::path& out_dir,
                             std::span<const EvaluationRecord> records,
                             const EvaluationMetrics& metrics,
                             std::span<const std::string> part_names);

// tests.json's array; `metrics` as above.
nlohmann::json tests_json(std::span<const EvaluationRecord> records,
                          const EvaluationMetrics& metrics);

}  // namespace cosmos
