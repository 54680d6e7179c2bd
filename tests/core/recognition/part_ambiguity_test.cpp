// The ambiguity decision (part_ambiguity.hpp) on seeded scans: a base holding a part and a
// copy of it a quarter percent larger (0.15 mm at the ends of the cow's 120 mm, under the
// 0.2 mm support distance) cannot tell which of the two it sees, and says so instead of
// naming one; a base of two different parts decides as before; and a size family (one mesh at
// three sizes 10 % apart, as catalogs hold) is told apart, each size named as itself. The spool
// is the hard case: seen end-on, a larger spool explains a smaller one's scene as well, and
// §5.2's selection (area-normalized spectra) proposes whichever size.
#include "core/recognition/part_ambiguity.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <memory>
#include <string>

#include "core/recognition/recognizer.hpp"
#include "sim/model_base_build/model_base_builder.hpp"
#include "sim/part_catalog.hpp"
#include "sim/part_pose.hpp"
#include "sim/part_scan.hpp"
#include "tests/common/plane_view_points.hpp"

namespace cosmos {
namespace {

PartCatalog catalog_of(const std::vector<PartEntry>& parts) {
  PartCatalog catalog;
  catalog.parts = parts;
  return catalog;
}

const PartCatalog& cell_catalog() {
  static const PartCatalog catalog =
      read_part_catalog(std::filesystem::path(COSMOS_SOURCE_DIR) / "config/parts.yaml");
  return catalog;
}

ModelBase build_base(const PartCatalog& catalog) {
  ModelBaseBuildSettings settings;
  settings.view_count = 80;
  settings.threads = 2;
  return build_model_base(catalog, ScannerParameters{}, settings);
}

RangeImage scan(const PartEntry& entry, std::uint64_t seed) {
  ScannerParameters scanner;
  scanner.seed = seed;
  return scan_single_part(load_mesh(entry.mesh_path, entry.size_mm), entry.name,
                          random_rotation(seed), scanner, ConditioningParameters{});
}

// Two parts whose placed views are one plane explain every point of a scene on it alike: only
// the surface each puts where the scene contradicts it tells them apart. Evidence for each:
// the scene only it explains (none here) plus the share of the other's view contradicted
// beyond the floor (0.15 by default).
TEST(PartAmbiguity, PartsThatExplainTheSceneAlikeAreToldApartByTheSurfaceTheSceneContradicts) {
  ModelBase base;
  base.parts = {{"plate", "plate.off", 24, 24, false, {}, {}, {}, {}, {}},
                {"bracket", "bracket.off", 24, 24, false, {}, {}, {}, {}, {}}};
  for (int part : {0, 1}) {
    ModelBaseView view;
    view.part_index = part;
    view.registration = testing::plane_view_points(-6.0);
    base.views.push_back(view);
  }
  const RegistrationPoints scene = testing::plane_view_points(-6.0);
  ModelSurfaces surfaces(base, ModelSurfaceCacheParameters{});
  const std::vector<int> winner_views = {0}, rival_views = {1};
  const auto judge = [&](double winner_seen, double rival_seen) {
    return judge_part_ambiguity(
        scene, base, {0, RigidTransform::identity(), winner_seen, winner_views},
        {1, RigidTransform::identity(), rival_seen, rival_views}, RegistrationParameters{},
        PartSupportParameters{}, PartAmbiguityParameters{}, surfaces);
  };
  // The winner's view seen at 95 %, the rival's at 45 %: 0.4 of evidence against none.
  const PartAmbiguity decided = judge(0.95, 0.45);
  EXPECT_EQ(decided.winner_only_points, 0);
  EXPECT_EQ(decided.rival_only_points, 0);
  EXPECT_NEAR(decided.discriminating_fraction, 0.4, 1e-12);
  EXPECT_NEAR(decided.discriminating_share, 1.0, 1e-12);
  EXPECT_FALSE(decided.ambiguous);
  // The other way round the winner has the weaker evidence (0.05 against 0.25)...
  const PartAmbiguity weaker = judge(0.6, 0.8);
  EXPECT_NEAR(weaker.discriminating_fraction, 0.3, 1e-12);
  EXPECT_NEAR(weaker.discriminating_share, 0.05 / 0.3, 1e-12);
  EXPECT_TRUE(weaker.ambiguous);
  // ... and views contradicted within the floor are no evidence at all.
  const PartAmbiguity alike = judge(0.9, 0.86);
  EXPECT_EQ(alike.discriminating_fraction, 0.0);
  EXPECT_TRUE(alike.ambiguous);
}

TEST(PartAmbiguity, APartAndItsSlightlyScaledCopyAreRejectedAsAmbiguousNotGuessed) {
  const PartEntry cow = cell_catalog().at("cow");
  PartEntry copy = cow;
  copy.name = "cow-copy";
  copy.size_mm = cow.size_mm * 1.0025;
  const ModelBase base = build_base(catalog_of({cow, copy}));
  const Recognizer recognizer(base, CosmosParameters{}, RecognitionParameters{});
  for (std::uint64_t seed : {61, 62, 63}) {
    const RecognitionResult result = recognizer.recognize(scan(cow, seed));
    SCOPED_TRACE("seed " + std::to_string(seed) + ": " + result.reason);
    EXPECT_EQ(result.status, RecognitionStatus::kRejected);
    EXPECT_EQ(result.part, -1);
    EXPECT_EQ(result.reason.rfind("ambiguous between ", 0), 0u);
    EXPECT_NE(result.reason.find("cow-copy"), std::string::npos);
    // Both were registered and explain the scene alike: the copy is the runner-up, close
    // behind, and few points of the scene are explained by one of them alone (the scan's noise
    // puts some on either side of the support distance: a few percent, never a tenth).
    ASSERT_GE(result.runner_up_part, 0);
    EXPECT_GE(result.inlier_fraction, RecognitionParameters{}.min_inlier_fraction);
    EXPECT_TRUE(result.ambiguity_examined);
    EXPECT_TRUE(result.ambiguity.ambiguous);
    EXPECT_LT(result.score - result.runner_up_score,
              RecognitionParameters{}.ambiguity.examined_score_margin);
    EXPECT_LT(result.ambiguity.discriminating_fraction, 0.1);
  }
}

TEST(PartAmbiguity, TwoDifferentPartsAreDecided) {
  const PartEntry cow = cell_catalog().at("cow");
  const PartEntry coupling = cell_catalog().at("couplingdown");
  const ModelBase base = build_base(catalog_of({cow, coupling}));
  const Recognizer recognizer(base, CosmosParameters{}, RecognitionParameters{});
  for (std::uint64_t seed : {61, 62}) {
    const RecognitionResult result = recognizer.recognize(scan(cow, seed));
    SCOPED_TRACE("seed " + std::to_string(seed) + ": " + result.reason);
    ASSERT_EQ(result.status, RecognitionStatus::kOk);
    EXPECT_EQ(result.part, 0);
    EXPECT_FALSE(result.ambiguity.ambiguous);
  }
}

TEST(PartAmbiguity, ASizeFamilyTenPercentApartIsToldApart) {
  const PartEntry spool = cell_catalog().at("spool");
  std::vector<PartEntry> family;
  for (double scale : {1.0, 1.1, 1.21}) {
    PartEntry size = spool;
    size.name = spool.name + "-" + std::to_string(static_cast<int>(std::lround(100 * scale)));
    size.size_mm = spool.size_mm * scale;
    family.push_back(size);
  }
  const ModelBase base = build_base(catalog_of(family));
  const Recognizer recognizer(base, CosmosParameters{}, RecognitionParameters{});
  int told_apart = 0, scans = 0;
  for (std::size_t truth = 0; truth < family.size(); ++truth)
    for (std::uint64_t seed : {71, 72, 73, 74}) {
      const RecognitionResult result = recognizer.recognize(scan(family[truth], seed));
      SCOPED_TRACE(family[truth].name + ", seed " + std::to_string(seed) + ": " + result.reason);
      ++scans;
      EXPECT_EQ(result.status, RecognitionStatus::kOk);
      EXPECT_EQ(result.part, static_cast<int>(truth));
      // The runner-up is another size, and fits the scene worse both ways (size_variants.hpp).
      EXPECT_GT(result.size_fit, result.runner_up_size_fit);
      if (result.status == RecognitionStatus::kOk && result.part == static_cast<int>(truth))
        ++told_apart;
    }
  EXPECT_EQ(told_apart, scans);
}

}  // namespace
}  // namespace cosmos
