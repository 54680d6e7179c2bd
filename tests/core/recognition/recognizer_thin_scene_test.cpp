// The recognizer's path for scenes without a fitted surface (thin_scene.hpp), on seeded scans
// of the blade (150 mm long, under a millimetre thick) in random poses that show it edge-on:
// no CSMP and too few control points to register, only a ribbon of range points. A base that
// holds the blade names it from that ribbon, in its pose (ADD-S within 5 % of its diameter,
// most within 2 %); a base of the blade at two sizes names a ribbon's size only when the other
// reaches over the belt beyond the ribbon's ends, and never the wrong one; a base without it
// rejects the scene rather than fit another part into the ribbon; with the path switched off, or
// without the belt mask that tells the parts apart, the scene is rejected as before.
#include <gtest/gtest.h>

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "core/recognition/recognizer.hpp"
#include "sim/evaluation/add_s_distance.hpp"
#include "sim/model_base_build/model_base_builder.hpp"
#include "sim/part_catalog.hpp"
#include "sim/part_pose.hpp"
#include "sim/part_scan.hpp"

namespace cosmos {
namespace {

// Random poses (sim/part_pose.hpp random_rotation) in which the blade's scan has no fitted
// surface to register, with from 20 to 800 range points: the first six leave a ribbon of 20
// to 60 points.
const std::vector<std::uint64_t> kEdgeOnSeeds = {12, 55, 59, 70, 235, 252, 2,  7,  14,
                                                 15, 16, 28, 47, 58,  72,  79, 97, 112};
// A pose whose ribbon has fewer range points than the path needs (ThinSceneParameters::
// min_points): 19.
constexpr std::uint64_t kTooFewPointsSeed = 346;

class ThinSceneRecognition : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    catalog_ = std::make_unique<PartCatalog>(
        read_part_catalog(std::filesystem::path(COSMOS_SOURCE_DIR) / "config/parts.yaml"));
    with_blade_ = std::make_unique<ModelBase>(build_base({"blade", "fandisk", "couplingdown"}));
    without_blade_ = std::make_unique<ModelBase>(build_base({"fandisk", "couplingdown"}));
    PartEntry larger = catalog_->at("blade");
    larger.name = "blade-110";
    larger.size_mm *= 1.1;
    PartCatalog family;
    family.parts = {catalog_->at("blade"), larger, catalog_->at("fandisk")};
    ModelBaseBuildSettings settings;
    settings.view_count = 80;
    settings.threads = 2;
    blade_sizes_ =
        std::make_unique<ModelBase>(build_model_base(family, ScannerParameters{}, settings));
    const PartEntry& blade = catalog_->at("blade");
    blade_mesh_ = std::make_unique<TriangleMesh>(load_mesh(blade.mesh_path, blade.size_mm));
    larger_blade_mesh_ =
        std::make_unique<TriangleMesh>(load_mesh(larger.mesh_path, larger.size_mm));
  }
  static void TearDownTestSuite() {
    blade_mesh_.reset();
    larger_blade_mesh_.reset();
    without_blade_.reset();
    blade_sizes_.reset();
    with_blade_.reset();
    catalog_.reset();
  }

  static ModelBase build_base(const std::vector<std::string>& names) {
    PartCatalog catalog;
    for (const std::string& name : names) catalog.parts.push_back(catalog_->at(name));
    ModelBaseBuildSettings settings;
    settings.view_count = 80;
    settings.threads = 2;
    return build_model_base(catalog, ScannerParameters{}, settings);
  }

  static RangeImage edge_on_scan(std::uint64_t seed, bool larger = false) {
    ScannerParameters scanner;
    scanner.seed = seed;
    return scan_single_part(larger ? *larger_blade_mesh_ : *blade_mesh_,
                            larger ? "blade-110" : "blade", random_rotation(seed), scanner,
                            ConditioningParameters{});
  }

  static inline std::unique_ptr<PartCatalog> catalog_;
  static inline std::unique_ptr<ModelBase> with_blade_;
  static inline std::unique_ptr<ModelBase> without_blade_;
  static inline std::unique_ptr<ModelBase> blade_sizes_;  // the blade and a copy 10 % larger
  static inline std::unique_ptr<TriangleMesh> blade_mesh_;
  static inline std::unique_ptr<TriangleMesh> larger_blade_mesh_;
};

TEST_F(ThinSceneRecognition, ABladeSeenEdgeOnIsNamedFromItsRangePointsInItsPose) {
  const Recognizer recognizer(*with_blade_, CosmosParameters{}, RecognitionParameters{});
  std::vector<Eigen::Vector3d> vertices_mm;
  for (const auto& vertex : blade_mesh_->vertices) vertices_mm.push_back(vertex.cast<double>());
  const AddSDistance add_s(vertices_mm);
  const double diameter_mm = with_blade_->parts.front().diameter_mm;
  int within_2_percent = 0;
  for (const std::uint64_t seed : kEdgeOnSeeds) {
    const RangeImage scene = edge_on_scan(seed);
    const RecognitionResult result = recognizer.recognize(scene);
    EXPECT_TRUE(result.thin_scene) << "seed " << seed;
    ASSERT_EQ(result.status, RecognitionStatus::kOk) << "seed " << seed << ": " << result.reason;
    EXPECT_EQ(with_blade_->parts[static_cast<std::size_t>(result.part)].name, "blade");
    const GroundTruthPose& truth = *scene.ground_truth;
    const double error_mm =
        add_s.add_s_mm({truth.rotation, truth.translation_mm},
                       {result.T_scanner_part.rotation, result.T_scanner_part.translation_mm});
    EXPECT_LT(error_mm / diameter_mm, 0.05) << "seed " << seed;
    within_2_percent += error_mm / diameter_mm < 0.02 ? 1 : 0;
  }
  // The pose rests on a ribbon and the belt: most within the eval's ADD-S@2 %.
  EXPECT_GE(within_2_percent, 14);
}

// The parts too small or too thick for the ribbon (part_size_gate.hpp, on its range points) are
// not fitted to it, and the scene is named and posed as when every part is fitted.
TEST_F(ThinSceneRecognition, TheRibbonIsFittedOnlyByThePartsItsSizeAllows) {
  const Recognizer recognizer(*with_blade_, CosmosParameters{}, RecognitionParameters{});
  RecognitionParameters ungated;
  ungated.size_gate.enabled = false;
  const Recognizer every_part(*with_blade_, CosmosParameters{}, ungated);
  int gated = 0;
  for (const std::uint64_t seed : kEdgeOnSeeds) {
    const RangeImage scene = edge_on_scan(seed);
    const RecognitionResult result = recognizer.recognize(scene);
    const RecognitionResult reference = every_part.recognize(scene);
    ASSERT_TRUE(result.thin_scene) << "seed " << seed;
    EXPECT_EQ(reference.parts_smaller_than_scene + reference.parts_thicker_than_scene, 0);
    const int left_out = result.parts_smaller_than_scene + result.parts_thicker_than_scene;
    EXPECT_LT(left_out, 3) << "seed " << seed;  // never the blade
    gated += left_out > 0 ? 1 : 0;
    EXPECT_EQ(result.part, reference.part) << "seed " << seed;
    EXPECT_NEAR(
        (result.T_scanner_part.translation_mm - reference.T_scanner_part.translation_mm).norm(), 0,
        1e-9)
        << "seed " << seed;
  }
  EXPECT_GE(gated, 6);
}

TEST_F(ThinSceneRecognition, ABaseWithoutTheBladeRejectsItsRibbon) {
  const Recognizer recognizer(*without_blade_, CosmosParameters{}, RecognitionParameters{});
  for (const std::uint64_t seed : kEdgeOnSeeds) {
    const RecognitionResult result = recognizer.recognize(edge_on_scan(seed));
    EXPECT_TRUE(result.thin_scene) << "seed " << seed;
    EXPECT_EQ(result.status, RecognitionStatus::kRejected) << "seed " << seed;
    EXPECT_EQ(result.part, -1) << "seed " << seed;
  }
}

TEST_F(ThinSceneRecognition, ARibbonNeverNamesTheWrongSizeOfTheBlade) {
  // A ribbon shows a rim: a larger blade whose extra length lies in a shadow explains it as
  // well, and such a scene is rejected as ambiguous rather than guessed.
  const Recognizer recognizer(*blade_sizes_, CosmosParameters{}, RecognitionParameters{});
  int named = 0;
  for (const std::uint64_t seed : kEdgeOnSeeds) {
    const RecognitionResult result = recognizer.recognize(edge_on_scan(seed));
    EXPECT_TRUE(result.thin_scene) << "seed " << seed;
    if (result.status != RecognitionStatus::kOk) {
      EXPECT_TRUE(result.reason.find("ambiguous between blade") != std::string::npos ||
                  result.reason.find("no part stands inside") != std::string::npos)
          << "seed " << seed << ": " << result.reason;
      continue;
    }
    EXPECT_EQ(blade_sizes_->parts[static_cast<std::size_t>(result.part)].name, "blade")
        << "seed " << seed;
    ++named;
  }
  // ... while a ribbon the larger size cannot explain (its ends would reach over the belt)
  // is still named.
  EXPECT_GE(named, 3);
}

// The blade and the blade 10 % larger, each seen edge-on in the same poses: a size is named
// from its ribbon only when the other size, fitted to the whole ribbon too, reaches over the
// belt beyond its ends by size_variants.fit_margin more, and then it is the scanned size. With
// sizes never told apart (a margin of 1) at least three fewer ribbons are named.
TEST_F(ThinSceneRecognition, TheBladesSizesAreToldApartOnARibbonByTheBeltBeyondItsEnds) {
  const Recognizer recognizer(*blade_sizes_, CosmosParameters{}, RecognitionParameters{});
  RecognitionParameters never_told_apart;
  never_told_apart.size_variants.fit_margin = 1;
  const Recognizer undecided(*blade_sizes_, CosmosParameters{}, never_told_apart);
  int named = 0, named_undecided = 0;
  for (const bool larger : {false, true})
    for (const std::uint64_t seed : kEdgeOnSeeds) {
      const RangeImage scene = edge_on_scan(seed, larger);
      const RecognitionResult result = recognizer.recognize(scene);
      if (!result.thin_scene) continue;
      if (undecided.recognize(scene).status == RecognitionStatus::kOk) ++named_undecided;
      if (result.status != RecognitionStatus::kOk) continue;
      ++named;
      EXPECT_EQ(blade_sizes_->parts[static_cast<std::size_t>(result.part)].name,
                larger ? "blade-110" : "blade")
          << "seed " << seed;
    }
  EXPECT_GE(named, named_undecided + 3);
}

TEST_F(ThinSceneRecognition, SwitchedOffTheRibbonIsRejectedForItsMissingSurface) {
  RecognitionParameters parameters;
  parameters.thin_scene.enabled = false;
  const Recognizer recognizer(*with_blade_, CosmosParameters{}, parameters);
  for (const std::uint64_t seed : kEdgeOnSeeds) {
    const RecognitionResult result = recognizer.recognize(edge_on_scan(seed));
    EXPECT_FALSE(result.thin_scene) << "seed " << seed;
    EXPECT_EQ(result.status, RecognitionStatus::kRejected) << "seed " << seed;
    EXPECT_TRUE(result.reason.starts_with("no object") ||
                result.reason.starts_with("too little smooth surface"))
        << "seed " << seed << ": " << result.reason;
  }
}

TEST_F(ThinSceneRecognition, WithoutABeltMaskTheRibbonIsNotSearched) {
  // Only where the scanner saw the belt tells the blade's ribbon from another part's face.
  const Recognizer recognizer(*with_blade_, CosmosParameters{}, RecognitionParameters{});
  for (const std::uint64_t seed : kEdgeOnSeeds) {
    RangeImage scene = edge_on_scan(seed);
    scene.belt_seen = PixelGrid<std::uint8_t>();
    const RecognitionResult result = recognizer.recognize(scene);
    EXPECT_FALSE(result.thin_scene) << "seed " << seed;
    EXPECT_EQ(result.status, RecognitionStatus::kRejected) << "seed " << seed;
  }
}

TEST_F(ThinSceneRecognition, ARibbonOfTooFewPointsIsNotSearched) {
  const RangeImage scene = edge_on_scan(kTooFewPointsSeed);
  ASSERT_LT(scene.count_valid(), static_cast<std::size_t>(ThinSceneParameters{}.min_points));
  ASSERT_GT(scene.count_valid(), 0u);
  const Recognizer recognizer(*with_blade_, CosmosParameters{}, RecognitionParameters{});
  const RecognitionResult result = recognizer.recognize(scene);
  EXPECT_FALSE(result.thin_scene);
  EXPECT_EQ(result.status, RecognitionStatus::kRejected);
  EXPECT_EQ(result.part, -1);
}

}  // namespace
}  // namespace cosmos
