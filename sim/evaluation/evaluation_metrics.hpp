#pragma once
// What `cosmos eval` measures over a set of test scans, one EvaluationRecord per scan, and
// the stable JSON it reports. Pure: no files, no clock.
//
// Sets (every rate is a fraction in [0, 1]; a statistic of an empty set is std::nullopt, JSON
// null, never NaN):
//   known     records with truth_in_model_base;     unknown  the others.
//   correct   known, not rejected, predicted_part == truth_part.
// Metrics (JSON key: definition):
//   tests                          |known|.
//   identification_rate            |correct| / |known|.
//   spectral_cluster_hit_rate.k    fraction of known with 0 <= true_cluster_rank < k, for
//                                  k = 1, 2, 5, 10: the correct-part rate against clusters
//                                  examined (thesis Fig. 4.8).
//   spectral_view_selection_rate   fraction of known with true_part_among_selected_views (§5.2).
//   quick_fit_order.tests          |known records whose search over every part ranked the parts
//                                  by their quick field fits|.
//   quick_fit_order.hit_rate.k     fraction of those with 0 <= true_part_quick_fit_rank < k,
//                                  k = 1, 2, 5, 10: how near the front of that search the
//                                  scan's own part was.
//   fraction_db_examined           mean over known of fraction_db_examined.
//   rotation_error_deg             geodesic angle of R_true^T R_estimated over correct records
//                                  of parts not flagged symmetric: {median, p95}.
//   translation_error_mm           |t_true - t_estimated| over all correct records: {median, p95}.
//   add_s_recall_10pct, _2pct      fraction of known records that are correct AND have
//                                  ADD-S < 0.10 (0.02) x diameter_mm; rejected and misidentified
//                                  records count as failures. `cosmos eval` measures ADD-S from
//                                  a subsample of the part's vertices to its mesh's surface.
//   unknown_reject_rate            fraction of unknown records rejected.
//   false_reject_rate              fraction of known records rejected.
//   recognition_ms                 recognition_ms over all records: {median, p99}.
//   size_variants.tests            |known records whose part has size variants in the base|:
//                                  other base parts of the same mesh at other sizes.
//   size_variants.told_apart_rate  fraction of those neither identified as one of its size
//                                  variants nor rejected as ambiguous with one.
// Percentiles are nearest-rank: the p-th percentile of n sorted values is value number
// ceil(p/100 * n) (1-based, at least 1), so it is always an observed value; the median is the
// 50th, the lower middle value for an even count.
#include <Eigen/Core>
#include <array>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "sim/evaluation/add_s_distance.hpp"

namespace cosmos {

struct EvaluationRecord {
  int test_index = 0;   // the test's number in the seeded plan
  int truth_part = -1;  // catalog index of the scanned part
  std::string truth_name;
  bool truth_in_model_base = true;  // false for --unknown parts
  bool truth_symmetric = false;     // catalog flag: rotation error not meaningful
  // Another part of the base is the same mesh at another size; and this record took the part
  // for one of them (identified it as one, or rejected the two as ambiguous).
  bool truth_has_size_variants = false;
  bool taken_for_size_variant = false;
  double diameter_mm = 0;  // part diameter (largest vertex distance) for ADD-S
  bool rejected = false;
  std::string rejection_reason;  // the recognizer's reason when rejected
  int predicted_part = -1;       // catalog index, -1 when rejected
  std::string predicted_name;
  // Rank (0-based) of the first cluster of the true part in the spectral cluster ranking
  // (SpectralViewSelector::rank_clusters), -1 when the part is not in the base.
  int true_cluster_rank = -1;
  bool true_part_among_selected_views = false;  // §5.2 view selection hit
  // Whether the search over every part ranked the parts by their quick field fits
  // (RecognitionResult::quick_fits), and the true part's rank (0-based) in that order, -1 when
  // it did not rank them or left the true part out by size.
  bool quick_fits_ranked = false;
  int true_part_quick_fit_rank = -1;
  double fraction_db_examined = 0;  // views matched / views in the base
  // T_scanner_part; identity by default because Eigen leaves fixed matrices uninitialized.
  Eigen::Matrix3d R_true = Eigen::Matrix3d::Identity();
  Eigen::Matrix3d R_estimated = Eigen::Matrix3d::Identity();
  Eigen::Vector3d t_true_mm = Eigen::Vector3d::Zero();
  Eigen::Vector3d t_estimated_mm = Eigen::Vector3d::Zero();
  double recognition_ms = 0;
  // Where the time went (the report's per-test table): chapter-3 features, patch-group
  // matching, registration and pose search; and whether the §5.2 views left the fallback
  // pose search to run (over one part or all), and whether it ran over every part of the
  // catalog (neither the selected views nor the vote index's poses explained the scan).
  double features_ms = 0, matching_ms = 0, registration_ms = 0;
  bool pose_searched = false;
  bool catalog_searched = false;
  // Parts the search over every part left out by size (part_size_gate.hpp).
  int parts_left_out_by_size = 0;
  // Parts it never quick-fitted, their signatures far from the scan's (signature_rank.hpp).
  int parts_left_out_by_signature = 0;
  // The winner's confusable parts the decision searched before it decided (confusable_parts.hpp).
  int confusable_parts_searched = 0;
  bool resting_searched = false;  // the parts' resting poses were searched
  bool thin_scene = false;  // no fitted surface: searched with its range points (thin_scene.hpp)
  // The decision's margin: the winner's score (the best candidate's when rejected) and the
  // best candidate of another part, empty when none registered.
  double score = 0;
  std::string runner_up_name;
  double runner_up_score = 0;
  // Where the two were compared (core/recognition/part_ambiguity.hpp): the share of the
  // scene that tells them apart, and the winner's share of it.
  bool ambiguity_examined = false;
  double discriminating_fraction = 0, discriminating_share = 0;
  // How much of the winner's and the runner-up's placed surfaces the scene shows.
  double seen_fraction = 0, runner_up_seen_fraction = 0;
};

// A part's ADD-S measure (add_s_distance.hpp), by catalog index; nullptr when the part has
// none. Only asked for parts of correctly identified records.
using AddSLookup = std::function<const AddSDistance*(int part)>;

enum class RecordStatus {
  kCorrect,          // known part, identified
  kMisidentified,    // known part, taken for another one
  kFalseReject,      // known part, rejected
  kUnknownRejected,  // unknown part, rejected: the right answer
  kUnknownAccepted,  // unknown part, taken for a base part
};

const char* record_status_name(RecordStatus status);

// Per-record errors, for the per-test table; std::nullopt where the metric does not apply.
struct RecordOutcome {
  RecordStatus status = RecordStatus::kFalseReject;
  std::optional<double> rotation_error_deg;  // correct records of asymmetric parts
  std::optional<double> translation_error_mm;
  std::optional<double> add_s_mm;
  std::optional<double> add_s_over_diameter;
};

struct Median95 {
  std::optional<double> median, p95;
};

inline constexpr std::array<int, 4> kClusterHitRanks = {1, 2, 5, 10};

struct EvaluationMetrics {
  int tests = 0;          // known records
  int unknown_tests = 0;  // unknown records
  std::optional<double> identification_rate;
  std::array<std::optional<double>, kClusterHitRanks.size()> spectral_cluster_hit_rate;
  // Hit rate for k = 1 .. max(10, largest true_cluster_rank + 1) clusters examined
  // (entry k - 1), for the Fig. 4.8 plot; empty when there are no known records.
  std::vector<double> cluster_hit_rate_curve;
  std::optional<double> spectral_view_selection_rate;
  int quick_fit_tests = 0;  // known records with quick_fits_ranked
  std::array<std::optional<double>, kClusterHitRanks.size()> quick_fit_hit_rate;
  std::optional<double> fraction_db_examined;
  Median95 rotation_error_deg, translation_error_mm;
  std::optional<double> add_s_recall_10pct, add_s_recall_2pct;
  std::optional<double> unknown_reject_rate, false_reject_rate;
  std::optional<double> recognition_ms_median, recognition_ms_p99;
  int size_variant_tests = 0;
  std::optional<double> size_variants_told_apart_rate;
  std::vector<double> rotation_errors_deg;  // ascending, the set rotation_error_deg is over
  std::vector<RecordOutcome> outcomes;      // one per record, in record order
};

// std::invalid_argument when a correct record's part has no ADD-S measure or its
// diameter_mm is not positive: ADD-S would silently fail it otherwise.
EvaluationMetrics compute_metrics(std::span<const EvaluationRecord> records,
                                  const AddSLookup& add_s_per_part);

// Exactly the keys listed at the top of this file.
nlohmann::json metrics_json(const EvaluationMetrics& metrics);

// Nearest-rank percentile (see above), percent in (0, 100]; std::nullopt for no values.
std::optional<double> nearest_rank_percentile(std::vector<double> values, double percent);

// Geodesic distance between two rotations: the angle of R_a^T R_b, degrees, in [0, 180].
double rotation_angle_deg(const Eigen::Matrix3d& R_a, const Eigen::Matrix3d& R_b);

}  // namespace cosmos
