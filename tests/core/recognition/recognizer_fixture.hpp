#pragma once
// The recognizer's tests against the regression model base (5 parts x 80 views,
// tests/regression_model_base.hpp): simulated random-pose scans of catalog parts, whose ground
// truth is known, and what the tests measure on them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "core/io/model_base_file.hpp"
#include "core/recognition/recognizer.hpp"
#include "sim/mesh.hpp"
#include "sim/part_catalog.hpp"
#include "sim/part_pose.hpp"
#include "sim/part_scan.hpp"
#include "tests/regression_model_base.hpp"

namespace cosmos {

class RecognizerOnRegressionBase : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    base_ = std::make_unique<ModelBase>(read_model_base(testing::regression_model_base()));
    // The full catalog holds the base's five parts and the bunny, which the base lacks.
    catalog_ = std::make_unique<PartCatalog>(
        read_part_catalog(std::filesystem::path(COSMOS_SOURCE_DIR) / "config/parts.yaml"));
    recognizer_ = std::make_unique<Recognizer>(*base_, CosmosParameters{}, RecognitionParameters{});
  }
  static void TearDownTestSuite() {
    recognizer_.reset();
    catalog_.reset();
    base_.reset();
  }

  // A scan of `name` in the random pose of `seed`, with noise seeded by it too.
  static TriangleMesh mesh_of(const std::string& name) {
    const PartEntry& entry = catalog_->at(name);
    return load_mesh(entry.mesh_path, entry.size_mm);
  }
  static RangeImage scan(const std::string& name, std::uint64_t seed) {
    const TriangleMesh mesh = mesh_of(name);
    ScannerParameters scanner;
    scanner.seed = seed;
    return scan_single_part(mesh, name, random_rotation(seed), scanner, ConditioningParameters{});
  }
  static RangeImage far_half_cut(const std::string& name, std::uint64_t seed);
  // The far-half scans the searches' tests share: seeds 131-140, the base's parts in turn.
  struct FarHalfCut {
    std::string name;
    std::uint64_t seed = 0;
    RangeImage image;
  };
  static std::vector<FarHalfCut> far_half_cuts();

  static double degrees(double radians) { return radians * 180 / std::numbers::pi; }

  // ADD-S (mean distance from each model point in the true pose to the nearest model point in
  // the estimated one) over about 1,000 of the mesh's vertices, by brute force: a pose that
  // turns a part of revolution about its axis scores 0 here, as it fits the scan as well.
  static double add_s_mm(const TriangleMesh& mesh, const GroundTruthPose& truth,
                         const RigidTransform& estimate) {
    const std::size_t step = std::max<std::size_t>(1, mesh.vertices.size() / 1000);
    std::vector<Eigen::Vector3d> in_truth, in_estimate;
    for (std::size_t i = 0; i < mesh.vertices.size(); i += step) {
      const Eigen::Vector3d p = mesh.vertices[i].cast<double>();
      in_truth.push_back(truth.rotation * p + truth.translation_mm);
      in_estimate.push_back(estimate.apply(p));
    }
    double sum_mm = 0;
    for (const Eigen::Vector3d& p : in_truth) {
      double nearest_mm2 = std::numeric_limits<double>::infinity();
      for (const Eigen::Vector3d& q : in_estimate)
        nearest_mm2 = std::min(nearest_mm2, (p - q).squaredNorm());
      sum_mm += std::sqrt(nearest_mm2);
    }
    return sum_mm / static_cast<double>(in_truth.size());
  }

  static inline std::unique_ptr<ModelBase> base_;
  static inline std::unique_ptr<PartCatalog> catalog_;
  static inline std::unique_ptr<Recognizer> recognizer_;
};

// A regression scan whose far half is replaced by measured belt: a scene that shows only
// part of most views, the rest of them where the scanner saw the belt.
inline RangeImage RecognizerOnRegressionBase::far_half_cut(const std::string& name,
                                                           std::uint64_t seed) {
  RangeImage image = scan(name, seed);
  EXPECT_TRUE(image.belt_known()) << name;
  int first_row = image.height(), last_row = -1;
  for (int row = 0; row < image.height(); ++row)
    for (int column = 0; column < image.width(); ++column)
      if (!std::isnan(image.z_mm(column, row))) {
        first_row = std::min(first_row, row);
        last_row = std::max(last_row, row);
      }
  EXPECT_LT(first_row, last_row) << name;
  for (int row = (first_row + last_row) / 2; row <= last_row; ++row)
    for (int column = 0; column < image.width(); ++column) {
      image.z_mm(column, row) = std::numeric_limits<float>::quiet_NaN();
      image.belt_seen(column, row) = 1;
    }
  return image;
}

inline std::vector<RecognizerOnRegressionBase::FarHalfCut>
RecognizerOnRegressionBase::far_half_cuts() {
  std::vector<FarHalfCut> cuts;
  for (std::uint64_t seed = 131; seed < 141; ++seed) {
    const std::string& name = base_->parts[static_cast<std::size_t>(seed % 5)].name;
    cuts.push_back({name, seed, far_half_cut(name, seed)});
  }
  return cuts;
}

// Whether the result's winner came from the search over every part with less than
// min_accepted_seen_fraction of its view seen.
inline bool accepted_with_view_contradicted(const RecognitionResult& result) {
  const auto winner = std::find_if(result.candidates.begin(), result.candidates.end(),
                                   [&](const RecognitionCandidate& c) {
                                     return c.part == result.part && c.view == result.view;
                                   });
  return result.status == RecognitionStatus::kOk &&
         result.seen_fraction < RecognitionParameters{}.min_accepted_seen_fraction &&
         winner != result.candidates.end() && winner->from_pose_search;
}

}  // namespace cosmos
