// Evaluation metrics against values worked out by hand: rates, percentiles, the geodesic
// rotation error, ADD and ADD-S (including a symmetric ring, where only ADD-S is 0), and the
// stable JSON key set with null for empty sets.
#include "sim/evaluation/evaluation_metrics.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <map>
#include <numbers>
#include <random>
#include <set>
#include <stdexcept>

#include "sim/evaluation/add_s_distance.hpp"
#include "sim/procedural_parts.hpp"

namespace cosmos {
namespace {

constexpr double kPi = std::numbers::pi;

Eigen::Matrix3d rotation_deg(double angle_deg, const Eigen::Vector3d& axis) {
  return Eigen::AngleAxisd(angle_deg * kPi / 180, axis.normalized()).toRotationMatrix();
}

// A grid of points 10 mm apart: a 1 mm shift keeps every point nearest to itself.
std::vector<Eigen::Vector3d> grid_points_mm() {
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j)
      for (int k = 0; k < 3; ++k) points.emplace_back(10.0 * i, 10.0 * j, 10.0 * k);
  return points;
}

// 36 points of a ring of radius 50 mm in the xy plane: symmetric under 10 degree turns about z.
std::vector<Eigen::Vector3d> ring_points_mm() {
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < 36; ++i)
    points.emplace_back(50 * std::cos(i * kPi / 18), 50 * std::sin(i * kPi / 18), 0);
  return points;
}

EvaluationRecord known_record(int truth, int predicted, int cluster_rank, double time_ms) {
  EvaluationRecord record;
  record.truth_part = truth;
  record.truth_name = "part" + std::to_string(truth);
  record.diameter_mm = 100;
  record.rejected = predicted < 0;
  record.predicted_part = predicted;
  record.true_cluster_rank = cluster_rank;
  record.recognition_ms = time_ms;
  return record;
}

EvaluationRecord unknown_record(int truth, int predicted, double time_ms) {
  EvaluationRecord record = known_record(truth, predicted, -1, time_ms);
  record.truth_in_model_base = false;
  return record;
}

// Every part has the grid as its model points.
EvaluationMetrics metrics_of(const std::vector<EvaluationRecord>& records) {
  const AddSDistance grid(grid_points_mm());
  return compute_metrics(records, [&](int) { return &grid; });
}

TEST(EvaluationMetrics, RatesMatchHandCount) {
  std::vector<EvaluationRecord> records = {
      known_record(0, 0, 0, 10),  known_record(0, 1, 1, 20),  known_record(1, 1, 4, 30),
      known_record(1, -1, 9, 40), known_record(2, 2, 12, 50), unknown_record(5, -1, 60),
      unknown_record(6, 0, 70),   unknown_record(7, -1, 80),
  };
  for (std::size_t i = 0; i < 5; ++i) {
    records[i].true_part_among_selected_views = (i == 0 || i == 1 || i == 4);
    records[i].fraction_db_examined = 0.1 * static_cast<double>(i + 1);
  }
  const EvaluationMetrics metrics = metrics_of(records);
  EXPECT_EQ(metrics.tests, 5);
  EXPECT_EQ(metrics.unknown_tests, 3);
  EXPECT_DOUBLE_EQ(*metrics.identification_rate, 3.0 / 5);
  // Ranks 0, 1, 4, 9, 12 against k = 1, 2, 5, 10.
  EXPECT_DOUBLE_EQ(*metrics.spectral_cluster_hit_rate[0], 1.0 / 5);
  EXPECT_DOUBLE_EQ(*metrics.spectral_cluster_hit_rate[1], 2.0 / 5);
  EXPECT_DOUBLE_EQ(*metrics.spectral_cluster_hit_rate[2], 3.0 / 5);
  EXPECT_DOUBLE_EQ(*metrics.spectral_cluster_hit_rate[3], 4.0 / 5);
  ASSERT_EQ(metrics.cluster_hit_rate_curve.size(), 13u);  // up to the largest rank + 1
  EXPECT_DOUBLE_EQ(metrics.cluster_hit_rate_curve[0], 1.0 / 5);
  EXPECT_DOUBLE_EQ(metrics.cluster_hit_rate_curve[11], 4.0 / 5);
  EXPECT_DOUBLE_EQ(metrics.cluster_hit_rate_curve[12], 1.0);
  EXPECT_DOUBLE_EQ(*metrics.spectral_view_selection_rate, 3.0 / 5);
  EXPECT_NEAR(*metrics.fraction_db_examined, 0.3, 1e-15);
  EXPECT_DOUBLE_EQ(*metrics.false_reject_rate, 1.0 / 5);
  EXPECT_DOUBLE_EQ(*metrics.unknown_reject_rate, 2.0 / 3);
  // Exact poses: every correct record is within both ADD-S thresholds.
  EXPECT_DOUBLE_EQ(*metrics.add_s_recall_10pct, 3.0 / 5);
  EXPECT_DOUBLE_EQ(*metrics.add_s_recall_2pct, 3.0 / 5);
  // Times 10..80 ms: nearest rank ceil(0.5 * 8) = 4 and ceil(0.99 * 8) = 8.
  EXPECT_DOUBLE_EQ(*metrics.recognition_ms_median, 40);
  EXPECT_DOUBLE_EQ(*metrics.recognition_ms_p99, 80);
  ASSERT_EQ(metrics.outcomes.size(), records.size());
  EXPECT_EQ(metrics.outcomes[0].status, RecordStatus::kCorrect);
  EXPECT_EQ(metrics.outcomes[1].status, RecordStatus::kMisidentified);
  EXPECT_EQ(metrics.outcomes[3].status, RecordStatus::kFalseReject);
  EXPECT_EQ(metrics.outcomes[5].status, RecordStatus::kUnknownRejected);
  EXPECT_EQ(metrics.outcomes[6].status, RecordStatus::kUnknownAccepted);
  EXPECT_FALSE(metrics.outcomes[1].add_s_mm.has_value());
}

TEST(EvaluationMetrics, RotationAngleIsGeodesic) {
  const Eigen::Matrix3d R_true = rotation_deg(37, {1, 2, 3});
  EXPECT_NEAR(rotation_angle_deg(R_true, R_true * rotation_deg(10, {-2, 1, 0.5})), 10, 1e-9);
  EXPECT_NEAR(rotation_angle_deg(R_true, rotation_deg(10, {0, 0, 1}) * R_true), 10, 1e-9);
  EXPECT_NEAR(rotation_angle_deg(R_true, R_true), 0, 1e-9);
  EXPECT_NEAR(rotation_angle_deg(R_true, R_true * rotation_deg(180, {1, 1, 0})), 180, 1e-9);
  EXPECT_NEAR(rotation_angle_deg(R_true, R_true * rotation_deg(1e-6, {0, 1, 0})), 1e-6, 1e-12);
}

TEST(EvaluationMetrics, RotationErrorSkipsSymmetricPartsTranslationDoesNot) {
  EvaluationRecord asymmetric = known_record(0, 0, 0, 1);
  asymmetric.R_estimated = rotation_deg(10, {0, 1, 0});
  asymmetric.t_estimated_mm = {3, 4, 0};
  EvaluationRecord symmetric = known_record(1, 1, 0, 1);
  symmetric.truth_symmetric = true;
  symmetric.R_estimated = rotation_deg(90, {0, 0, 1});
  symmetric.t_estimated_mm = {0, 0, 1};
  const EvaluationMetrics metrics = metrics_of({asymmetric, symmetric});
  EXPECT_NEAR(*metrics.rotation_error_deg.median, 10, 1e-9);
  EXPECT_NEAR(*metrics.rotation_error_deg.p95, 10, 1e-9);
  ASSERT_EQ(metrics.rotation_errors_deg.size(), 1u);
  EXPECT_FALSE(metrics.outcomes[1].rotation_error_deg.has_value());
  EXPECT_DOUBLE_EQ(*metrics.translation_error_mm.median, 1);  // nearest rank: the lower
  EXPECT_DOUBLE_EQ(*metrics.translation_error_mm.p95, 5);
}

TEST(AddSDistance, RingTurnedByItsSymmetryAngleIsZeroButAddIsNot) {
  const std::vector<Eigen::Vector3d> ring = ring_points_mm();
  const RigidPose truth{rotation_deg(25, {1, 0, 1}), {100, -20, 300}};
  const RigidPose turned{truth.R * rotation_deg(10, {0, 0, 1}), truth.t_mm};
  EXPECT_NEAR(AddSDistance(ring).add_s_mm(truth, turned), 0, 1e-9);
  // Each point moves by the chord of a 10 degree arc of radius 50 mm.
  EXPECT_NEAR(add_mm(ring, truth, turned), 2 * 50 * std::sin(5 * kPi / 180), 1e-9);
}

// A knob of revolution meshed coarsely, as CAD exports are: rings of 18 vertices, 20 degrees
// apart. Turned by half a ring's step about its axis it is where it was to within the
// facets' sag, which ADD-S against the surface sees and ADD-S against the vertices does not.
TEST(AddSDistance, ACoarseSolidOfRevolutionTurnedAboutItsAxisIsOnItsOwnSurface) {
  const std::vector<Eigen::Vector2d> profile_rz_mm = {{0, 0},   {25, 0},  {25, 10},
                                                      {15, 20}, {15, 40}, {0, 40}};
  const TriangleMesh knob = make_revolution(profile_rz_mm, 18);
  std::vector<Eigen::Vector3d> vertices_mm;
  for (const Eigen::Vector3f& v : knob.vertices) vertices_mm.push_back(v.cast<double>());
  const RigidPose truth{rotation_deg(35, {1, 2, 0}), {10, 20, 30}};
  const RigidPose turned{truth.R * rotation_deg(10, {0, 0, 1}), truth.t_mm};
  const double surface_mm = AddSDistance(vertices_mm, knob).add_s_mm(truth, turned);
  const double vertex_mm = AddSDistance(vertices_mm).add_s_mm(truth, turned);
  // A ring vertex of radius r lands mid-facet, r (1 - cos 10 deg) from the facet's plane:
  // 0.38 mm at 25 mm; a vertex on the axis does not move.
  EXPECT_LT(surface_mm, 25 * (1 - std::cos(10 * kPi / 180)));
  EXPECT_GT(surface_mm, 0.0);
  // Against the vertices it moves by at least the chord to its ring's nearest vertex: 2.6 mm
  // on the 15 mm rings.
  EXPECT_GT(vertex_mm, 2.0);
  // An untouched pose is exact either way, and a shift is a shift.
  EXPECT_NEAR(AddSDistance(vertices_mm, knob).add_s_mm(truth, truth), 0, 1e-6);
  const RigidPose lifted{truth.R, truth.t_mm + truth.R * Eigen::Vector3d(0, 0, 100)};
  EXPECT_GT(AddSDistance(vertices_mm, knob).add_s_mm(truth, lifted), 20);
}

TEST(AddSDistance, OneMillimetreShiftIsOneMillimetre) {
  const std::vector<Eigen::Vector3d> grid = grid_points_mm();
  const RigidPose truth{rotation_deg(40, {0, 1, 1}), {5, 6, 7}};
  const RigidPose shifted{truth.R, truth.t_mm + Eigen::Vector3d(0.6, 0, 0.8)};
  EXPECT_NEAR(AddSDistance(grid).add_s_mm(truth, shifted), 1, 1e-12);
  EXPECT_NEAR(add_mm(grid, truth, shifted), 1, 1e-12);
}

TEST(AddSDistance, KdTreeAgreesWithBruteForce) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coordinate(-60, 60);
  std::vector<Eigen::Vector3d> points(2000);
  for (auto& p : points) p = {coordinate(random), coordinate(random), 0.3 * coordinate(random)};
  const AddSDistance add_s(points);
  for (int query = 0; query < 200; ++query) {
    const Eigen::Vector3d q(2 * coordinate(random), coordinate(random), coordinate(random));
    double brute_mm2 = std::numeric_limits<double>::infinity();
    for (const auto& p : points) brute_mm2 = std::min(brute_mm2, (p - q).squaredNorm());
    ASSERT_EQ(add_s.nearest_squared_mm2(q), brute_mm2) << "query " << query;
  }
  const RigidPose truth{rotation_deg(30, {1, 1, 1}), {1, 2, 3}};
  const RigidPose estimate{rotation_deg(33, {1, 1.1, 1}), {2, 2, 3}};
  double brute_sum_mm = 0;
  for (const auto& p : points) {
    double best_mm2 = std::numeric_limits<double>::infinity();
    for (const auto& q : points)
      best_mm2 = std::min(
          best_mm2, ((truth.R * p + truth.t_mm) - (estimate.R * q + estimate.t_mm)).squaredNorm());
    brute_sum_mm += std::sqrt(best_mm2);
  }
  EXPECT_NEAR(add_s.add_s_mm(truth, estimate), brute_sum_mm / 2000, 1e-9);
}

TEST(EvaluationMetrics, AddSRecallCountsRejectsAndMisidentificationsAsFailures) {
  EvaluationRecord small = known_record(0, 0, 0, 1);  // ADD-S 1 mm of 20 mm: 5 %
  small.diameter_mm = 20;
  small.t_estimated_mm = {1, 0, 0};
  EvaluationRecord large = known_record(1, 1, 0, 1);  // ADD-S 1 mm of 100 mm: 1 %
  large.t_estimated_mm = {0, 1, 0};
  const EvaluationMetrics metrics =
      metrics_of({small, large, known_record(2, -1, 0, 1), known_record(3, 0, 0, 1)});
  EXPECT_DOUBLE_EQ(*metrics.add_s_recall_10pct, 2.0 / 4);
  EXPECT_DOUBLE_EQ(*metrics.add_s_recall_2pct, 1.0 / 4);
  EXPECT_NEAR(*metrics.outcomes[0].add_s_over_diameter, 0.05, 1e-12);
}

TEST(EvaluationMetrics, AMissingAddSMeasureIsRefused) {
  EXPECT_THROW(compute_metrics(std::vector{known_record(0, 0, 0, 1)},
                               [](int) -> const AddSDistance* { return nullptr; }),
               std::invalid_argument);
}

TEST(NearestRankPercentile, KnownVectors) {
  EXPECT_EQ(nearest_rank_percentile({5, 1, 4, 2, 3}, 50), 3);
  EXPECT_EQ(nearest_rank_percentile({5, 1, 4, 2, 3}, 95), 5);
  EXPECT_EQ(nearest_rank_percentile({5, 1, 4, 2, 3}, 20), 1);
  EXPECT_EQ(nearest_rank_percentile({4, 3, 2, 1}, 50), 2);
  EXPECT_EQ(nearest_rank_percentile({7}, 99), 7);
  std::vector<double> hundred;
  for (int i = 100; i >= 1; --i) hundred.push_back(i);
  EXPECT_EQ(nearest_rank_percentile(hundred, 95), 95);
  EXPECT_EQ(nearest_rank_percentile(hundred, 99), 99);
  EXPECT_EQ(nearest_rank_percentile(hundred, 100), 100);
  EXPECT_FALSE(nearest_rank_percentile({}, 50).has_value());
}

// Size variants: only the records of parts with another size in the base count, and a record
// counts against the rate when it took the part for one of those sizes (identified as it, or
// rejected as ambiguous with it), not when it took it for an unrelated part or rejected it
// for another reason.
TEST(EvaluationMetrics, SizeVariantsToldApartCountsOnlyConfusionsWithinAFamily) {
  std::vector<EvaluationRecord> records = {
      known_record(0, 0, 0, 1), known_record(0, 1, 0, 1), known_record(1, -1, 0, 1),
      known_record(1, 1, 0, 1), known_record(2, 3, 0, 1), known_record(3, 3, 0, 1),
  };
  for (int i : {0, 1, 2, 3, 4}) records[static_cast<std::size_t>(i)].truth_has_size_variants = true;
  records[1].taken_for_size_variant = true;  // part 0 identified as its variant, part 1
  records[2].taken_for_size_variant = true;  // part 1 rejected as ambiguous with part 0
  const EvaluationMetrics metrics = metrics_of(records);
  EXPECT_EQ(metrics.size_variant_tests, 5);
  EXPECT_DOUBLE_EQ(*metrics.size_variants_told_apart_rate, 3.0 / 5);
  EXPECT_DOUBLE_EQ(*metrics.identification_rate, 3.0 / 6);
}

// Only the records whose search ranked the parts by quick fit count; a true part it left out
// by size (rank -1) is a miss.
TEST(EvaluationMetrics, QuickFitHitRatesCountOnlyScansWhoseSearchRankedTheParts) {
  std::vector<EvaluationRecord> records = {
      known_record(0, 0, 0, 1), known_record(1, 1, 0, 1), known_record(2, -1, 0, 1),
      known_record(3, 3, 0, 1), known_record(4, 4, 0, 1), unknown_record(5, -1, 1),
  };
  const int ranks[] = {0, 1, 7, -1};
  for (std::size_t i = 0; i < 4; ++i) {
    records[i].quick_fits_ranked = true;
    records[i].true_part_quick_fit_rank = ranks[i];
  }
  records[5].quick_fits_ranked = true;  // an unknown part has no rank to count
  const EvaluationMetrics metrics = metrics_of(records);
  EXPECT_EQ(metrics.quick_fit_tests, 4);
  EXPECT_DOUBLE_EQ(*metrics.quick_fit_hit_rate[0], 1.0 / 4);  // first
  EXPECT_DOUBLE_EQ(*metrics.quick_fit_hit_rate[1], 2.0 / 4);  // among the first 2
  EXPECT_DOUBLE_EQ(*metrics.quick_fit_hit_rate[2], 2.0 / 4);  // 5
  EXPECT_DOUBLE_EQ(*metrics.quick_fit_hit_rate[3], 3.0 / 4);  // 10
  const nlohmann::json json = metrics_json(metrics)["quick_fit_order"];
  EXPECT_EQ(json["tests"], 4);
  EXPECT_EQ(json["hit_rate"]["10"], 0.75);
}

std::set<std::string> keys_of(const nlohmann::json& json) {
  std::set<std::string> keys;
  for (const auto& item : json.items()) keys.insert(item.key());
  return keys;
}

TEST(MetricsJson, HasExactlyTheStableKeys) {
  const nlohmann::json json = metrics_json(metrics_of({known_record(0, 0, 0, 5)}));
  EXPECT_EQ(keys_of(json), (std::set<std::string>{
                               "tests", "identification_rate", "spectral_cluster_hit_rate",
                               "spectral_view_selection_rate", "quick_fit_order",
                               "fraction_db_examined", "rotation_error_deg", "translation_error_mm",
                               "add_s_recall_10pct", "add_s_recall_2pct", "unknown_reject_rate",
                               "false_reject_rate", "recognition_ms", "size_variants"}));
  EXPECT_EQ(keys_of(json["size_variants"]), (std::set<std::string>{"tests", "told_apart_rate"}));
  EXPECT_EQ(json["size_variants"]["tests"], 0);
  EXPECT_TRUE(json["size_variants"]["told_apart_rate"].is_null());
  EXPECT_EQ(keys_of(json["spectral_cluster_hit_rate"]),
            (std::set<std::string>{"1", "2", "5", "10"}));
  EXPECT_EQ(keys_of(json["quick_fit_order"]), (std::set<std::string>{"tests", "hit_rate"}));
  EXPECT_EQ(keys_of(json["quick_fit_order"]["hit_rate"]),
            (std::set<std::string>{"1", "2", "5", "10"}));
  EXPECT_EQ(json["quick_fit_order"]["tests"], 0);
  EXPECT_TRUE(json["quick_fit_order"]["hit_rate"]["1"].is_null());
  EXPECT_EQ(keys_of(json["rotation_error_deg"]), (std::set<std::string>{"median", "p95"}));
  EXPECT_EQ(keys_of(json["translation_error_mm"]), (std::set<std::string>{"median", "p95"}));
  EXPECT_EQ(keys_of(json["recognition_ms"]), (std::set<std::string>{"median", "p99"}));
  EXPECT_EQ(json["tests"], 1);
  EXPECT_EQ(json["identification_rate"], 1.0);
  EXPECT_EQ(json["rotation_error_deg"]["median"], 0.0);
  EXPECT_TRUE(json["unknown_reject_rate"].is_null());  // no unknown parts
}

TEST(MetricsJson, EmptySetsAreNullNeverNaN) {
  const nlohmann::json none = metrics_json(metrics_of({}));
  EXPECT_EQ(none["tests"], 0);
  for (const char* key :
       {"identification_rate", "spectral_view_selection_rate", "fraction_db_examined",
        "add_s_recall_10pct", "add_s_recall_2pct", "unknown_reject_rate", "false_reject_rate"})
    EXPECT_TRUE(none[key].is_null()) << key;
  EXPECT_TRUE(none["spectral_cluster_hit_rate"]["10"].is_null());
  EXPECT_TRUE(none["rotation_error_deg"]["p95"].is_null());
  EXPECT_TRUE(none["recognition_ms"]["median"].is_null());
  EXPECT_EQ(none.dump().find("NaN"), std::string::npos);

  // Only unknown parts: their reject rate and the times exist, the known-part rates do not.
  const nlohmann::json unknown_only = metrics_json(metrics_of({unknown_record(3, -1, 12)}));
  EXPECT_EQ(unknown_only["unknown_reject_rate"], 1.0);
  EXPECT_EQ(unknown_only["recognition_ms"]["p99"], 12.0);
  EXPECT_TRUE(unknown_only["identification_rate"].is_null());
  EXPECT_TRUE(unknown_only["translation_error_mm"]["median"].is_null());
}

}  // namespace
}  // namespace cosmos
