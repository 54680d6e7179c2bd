#include "sim/evaluation/evaluation_metrics.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "sim/evaluation/add_s_distance.hpp"

namespace cosmos {
namespace {

// Clusters shown at least on the Fig. 4.8 curve: the largest k of the stable JSON keys.
constexpr int kMinimumCurveClusters = kClusterHitRanks.back();

std::optional<double> fraction(int count, int total) {
  if (total == 0) return std::nullopt;
  return static_cast<double>(count) / total;
}

RecordStatus status_of(const EvaluationRecord& record) {
  if (!record.truth_in_model_base)
    return record.rejected ? RecordStatus::kUnknownRejected : RecordStatus::kUnknownAccepted;
  if (record.rejected) return RecordStatus::kFalseReject;
  return record.predicted_part == record.truth_part ? RecordStatus::kCorrect
                                                    : RecordStatus::kMisidentified;
}

Median95 median_p95(const std::vector<double>& values) {
  return {nearest_rank_percentile(values, 50), nearest_rank_percentile(values, 95)};
}

nlohmann::json to_json(const std::optional<double>& value) {
  return value ? nlohmann::json(*value) : nlohmann::json(nullptr);
}

nlohmann::json to_json(const Median95& value) {
  return {{"median", to_json(value.median)}, {"p95", to_json(value.p95)}};
}

}  // namespace

const char* record_status_name(RecordStatus status) {
  switch (status) {
    case RecordStatus::kCorrect:
      return "correct";
    case RecordStatus::kMisidentified:
      return "misidentified";
    case RecordStatus::kFalseReject:
      return "false reject";
    case RecordStatus::kUnknownRejected:
      return "unknown, rejected";
    case RecordStatus::kUnknownAccepted:
      return "unknown, accepted";
  }
  return "?";
}

std::optional<double> nearest_rank_percentile(std::vector<double> values, double percent) {
  if (values.empty()) return std::nullopt;
  const auto count = static_cast<double>(values.size());
  const auto rank = std::clamp(static_cast<std::size_t>(std::ceil(percent / 100 * count)),
                               std::size_t{1}, values.size());
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(rank - 1),
                   values.end());
  return values[rank - 1];
}

double rotation_angle_deg(const Eigen::Matrix3d& R_a, const Eigen::Matrix3d& R_b) {
  const Eigen::Matrix3d R_ab = R_a.transpose() * R_b;
  // atan2 of sin and cos stays accurate near 0 and 180 degrees, where acos of the trace alone
  // loses half the digits.
  const double cos_angle = (R_ab.trace() - 1) / 2;
  const Eigen::Vector3d axis_times_2sin(R_ab(2, 1) - R_ab(1, 2), R_ab(0, 2) - R_ab(2, 0),
                                        R_ab(1, 0) - R_ab(0, 1));
  return std::atan2(axis_times_2sin.norm() / 2, cos_angle) * 180 / std::numbers::pi;
}

EvaluationMetrics compute_metrics(std::span<const EvaluationRecord> records,
                                  const AddSLookup& add_s_per_part) {
  EvaluationMetrics metrics;
  int correct = 0, view_selection_hits = 0, add_s_hits_10pct = 0, add_s_hits_2pct = 0;
  int false_rejects = 0, unknown_rejects = 0, largest_rank = -1, taken_for_size_variant = 0;
  double fraction_db_sum = 0;
  std::vector<int> cluster_ranks, quick_fit_ranks;
  std::vector<double> translation_errors_mm, recognition_times_ms;
  for (const EvaluationRecord& record : records) {
    RecordOutcome outcome;
    outcome.status = status_of(record);
    recognition_times_ms.push_back(record.recognition_ms);
    if (!record.truth_in_model_base) {
      ++metrics.unknown_tests;
      if (record.rejected) ++unknown_rejects;
      metrics.outcomes.push_back(outcome);
      continue;
    }
    ++metrics.tests;
    cluster_ranks.push_back(record.true_cluster_rank);
    largest_rank = std::max(largest_rank, record.true_cluster_rank);
    if (record.quick_fits_ranked) quick_fit_ranks.push_back(record.true_part_quick_fit_rank);
    if (record.true_part_among_selected_views) ++view_selection_hits;
    fraction_db_sum += record.fraction_db_examined;
    if (record.rejected) ++false_rejects;
    if (record.truth_has_size_variants) {
      ++metrics.size_variant_tests;
      if (record.taken_for_size_variant) ++taken_for_size_variant;
    }
    if (outcome.status == RecordStatus::kCorrect) {
      ++correct;
      if (!(record.diameter_mm > 0))
        throw std::invalid_argument("part " + std::to_string(record.truth_part) + " (" +
                                    record.truth_name + ") has no positive diameter_mm");
      if (!record.truth_symmetric) {
        outcome.rotation_error_deg = rotation_angle_deg(record.R_true, record.R_estimated);
        metrics.rotation_errors_deg.push_back(*outcome.rotation_error_deg);
      }
      outcome.translation_error_mm = (record.t_true_mm - record.t_estimated_mm).norm();
      translation_errors_mm.push_back(*outcome.translation_error_mm);
      const AddSDistance* add_s = add_s_per_part(record.truth_part);
      if (add_s == nullptr)
        throw std::invalid_argument("no ADD-S measure for part " +
                                    std::to_string(record.truth_part) + " (" + record.truth_name +
                                    ")");
      outcome.add_s_mm = add_s->add_s_mm({record.R_true, record.t_true_mm},
                                         {record.R_estimated, record.t_estimated_mm});
      outcome.add_s_over_diameter = *outcome.add_s_mm / record.diameter_mm;
      if (*outcome.add_s_over_diameter < 0.10) ++add_s_hits_10pct;
      if (*outcome.add_s_over_diameter < 0.02) ++add_s_hits_2pct;
    }
    metrics.outcomes.push_back(outcome);
  }

  const int known = metrics.tests;
  // The fraction of `ranks` below `first`, over `count` records.
  const auto ranked_within = [](const std::vector<int>& ranks, int first, int count) {
    return fraction(
        static_cast<int>(std::count_if(ranks.begin(), ranks.end(),
                                       [first](int rank) { return rank >= 0 && rank < first; })),
        count);
  };
  const auto hit_rate = [&](int clusters) { return ranked_within(cluster_ranks, clusters, known); };
  metrics.identification_rate = fraction(correct, known);
  metrics.quick_fit_tests = static_cast<int>(quick_fit_ranks.size());
  for (std::size_t i = 0; i < kClusterHitRanks.size(); ++i) {
    metrics.spectral_cluster_hit_rate[i] = hit_rate(kClusterHitRanks[i]);
    metrics.quick_fit_hit_rate[i] =
        ranked_within(quick_fit_ranks, kClusterHitRanks[i], metrics.quick_fit_tests);
  }
  if (known > 0)
    for (int k = 1; k <= std::max(kMinimumCurveClusters, largest_rank + 1); ++k)
      metrics.cluster_hit_rate_curve.push_back(*hit_rate(k));
  metrics.spectral_view_selection_rate = fraction(view_selection_hits, known);
  if (known > 0) metrics.fraction_db_examined = fraction_db_sum / known;
  std::sort(metrics.rotation_errors_deg.begin(), metrics.rotation_errors_deg.end());
  metrics.rotation_error_deg = median_p95(metrics.rotation_errors_deg);
  metrics.translation_error_mm = median_p95(translation_errors_mm);
  metrics.add_s_recall_10pct = fraction(add_s_hits_10pct, known);
  metrics.add_s_recall_2pct = fraction(add_s_hits_2pct, known);
  metrics.unknown_reject_rate = fraction(unknown_rejects, metrics.unknown_tests);
  metrics.false_reject_rate = fraction(false_rejects, known);
  metrics.recognition_ms_median = nearest_rank_percentile(recognition_times_ms, 50);
  metrics.recognition_ms_p99 = nearest_rank_percentile(recognition_times_ms, 99);
  metrics.size_variants_told_apart_rate =
      fraction(metrics.size_variant_tests - taken_for_size_variant, metrics.size_variant_tests);
  return metrics;
}

nlohmann::json metrics_json(const EvaluationMetrics& metrics) {
  nlohmann::json cluster_hits = nlohmann::json::object();
  nlohmann::json quick_fit_hits = nlohmann::json::object();
  for (std::size_t i = 0; i < kClusterHitRanks.size(); ++i) {
    const std::string rank = std::to_string(kClusterHitRanks[i]);
    cluster_hits[rank] = to_json(metrics.spectral_cluster_hit_rate[i]);
    quick_fit_hits[rank] = to_json(metrics.quick_fit_hit_rate[i]);
  }
  return {
      {"tests", metrics.tests},
      {"identification_rate", to_json(metrics.identification_rate)},
      {"spectral_cluster_hit_rate", cluster_hits},
      {"spectral_view_selection_rate", to_json(metrics.spectral_view_selection_rate)},
      {"quick_fit_order", {{"tests", metrics.quick_fit_tests}, {"hit_rate", quick_fit_hits}}},
      {"fraction_db_examined", to_json(metrics.fraction_db_examined)},
      {"rotation_error_deg", to_json(metrics.rotation_error_deg)},
      {"translation_error_mm", to_json(metrics.translation_error_mm)},
      {"add_s_recall_10pct", to_json(metrics.add_s_recall_10pct)},
      {"add_s_recall_2pct", to_json(metrics.add_s_recall_2pct)},
      {"unknown_reject_rate", to_json(metrics.unknown_reject_rate)},
      {"false_reject_rate", to_json(metrics.false_reject_rate)},
      {"recognition_ms",
       {{"median", to_json(metrics.recognition_ms_median)},
        {"p99", to_json(metrics.recognition_ms_p99)}}},
      {"size_variants",
       {{"tests", metrics.size_variant_tests},
        {"told_apart_rate", to_json(metrics.size_variants_told_apart_rate)}}},
  };
}

}  // namespace cosmos
