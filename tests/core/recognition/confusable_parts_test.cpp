// The confusable parts a base lists (confusable_parts.hpp), on a base of three parts built in
// code: a plate, a bracket one of whose legs is that plate, and a ball. The bracket explains
// the plate's views seen from the side of its outer face, so each is listed with the other;
// nothing explains the ball but the ball, and the ball explains neither flat part.
#include "core/recognition/confusable_parts.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <numeric>

#include "sim/model_base_build/model_base_builder.hpp"
#include "sim/procedural_meshes.hpp"
#include "sim/procedural_parts.hpp"
#include "tests/core/backwards_task_runner.hpp"

namespace cosmos {
namespace {

constexpr int kPlate = 0, kBracket = 1, kBall = 2;

const ModelBase& flat_and_round_base() {
  static const ModelBase base = [] {
    const std::filesystem::path folder =
        std::filesystem::temp_directory_path() / "cosmos-confusable-parts-test";
    std::filesystem::create_directories(folder);
    // The bracket's long leg, 40 x 4 x 30 mm, is the plate; its short leg stands 26 mm off it.
    const std::vector<Eigen::Vector2d> bracket = {{0, 0}, {40, 0}, {40, 4},
                                                  {4, 4}, {4, 30}, {0, 30}};
    const std::vector<Eigen::Vector2d> plate = {{0, 0}, {40, 0}, {40, 4}, {0, 4}};
    write_off_file(make_extrusion(plate, 30), folder / "plate.off");
    write_off_file(make_extrusion(bracket, 30), folder / "bracket.off");
    write_off_file(make_icosphere(15, 3), folder / "ball.off");
    PartCatalog catalog;
    catalog.parts = {{"plate", folder / "plate.off", 40, false},
                     {"bracket", folder / "bracket.off", 40, false},
                     {"ball", folder / "ball.off", 30, true}};
    ModelBaseBuildSettings settings;
    settings.view_count = 80;
    settings.threads = 2;
    return build_model_base(catalog, ScannerParameters{}, settings);
  }();
  return base;
}

std::vector<PartSearchModel> search_models(const ModelBase& base) {
  std::vector<PartSearchModel> models;
  for (int part = 0; part < static_cast<int>(base.parts.size()); ++part)
    models.push_back(build_part_search_model(base, part));
  return models;
}

TEST(ConfusableParts, ProbeViewsAreSpreadEvenlyThroughAPartsViews) {
  PartSearchModel part;
  part.views.resize(100);
  std::iota(part.views.begin(), part.views.end(), 500);
  const std::vector<int> probes = confusion_probe_views(part, 24);
  ASSERT_EQ(probes.size(), 24u);
  EXPECT_EQ(probes.front(), 500);
  EXPECT_EQ(probes[12], 550);
  EXPECT_TRUE(std::is_sorted(probes.begin(), probes.end()));
  EXPECT_EQ(std::adjacent_find(probes.begin(), probes.end()), probes.end());
  EXPECT_EQ(confusion_probe_views(part, 1000).size(), 100u);
  EXPECT_TRUE(confusion_probe_views(part, 0).empty());
}

TEST(ConfusableParts, ABracketAndThePlateThatIsOneOfItsLegsAreListedWithEachOther) {
  const ModelBase& base = flat_and_round_base();
  const std::vector<std::vector<int>> confusable =
      find_confusable_parts(base, search_models(base), ConfusablePartParameters{});
  ASSERT_EQ(confusable.size(), 3u);
  EXPECT_EQ(confusable[kBracket], std::vector<int>{kPlate});
  EXPECT_EQ(confusable[kPlate], std::vector<int>{kBracket});
  EXPECT_TRUE(confusable[kBall].empty());
  // The base's own build lists the same.
  for (int part : {kPlate, kBracket, kBall})
    EXPECT_EQ(base.parts[static_cast<std::size_t>(part)].confusable_parts,
              confusable[static_cast<std::size_t>(part)]);
}

TEST(ConfusableParts, ATighterFitListsFewerPartsAndNoneWhenDisabled) {
  const ModelBase& base = flat_and_round_base();
  const std::vector<PartSearchModel> models = search_models(base);
  ConfusablePartParameters parameters;
  parameters.close_fit_mm2 = 0;
  const std::vector<std::vector<int>> none = find_confusable_parts(base, models, parameters);
  EXPECT_TRUE(std::all_of(none.begin(), none.end(), [](const auto& list) { return list.empty(); }));
  parameters = {};
  parameters.enabled = false;
  const std::vector<std::vector<int>> disabled = find_confusable_parts(base, models, parameters);
  ASSERT_EQ(disabled.size(), 3u);
  EXPECT_TRUE(disabled[kBracket].empty());
}

TEST(ConfusableParts, TheListsAreTheSameForAnyRunner) {
  const ModelBase& base = flat_and_round_base();
  const std::vector<PartSearchModel> models = search_models(base);
  const BackwardsTaskRunner backwards;
  EXPECT_EQ(find_confusable_parts(base, models, ConfusablePartParameters{}, backwards),
            find_confusable_parts(base, models, ConfusablePartParameters{}));
  EXPECT_GT(backwards.tasks, 0);
}

}  // namespace
}  // namespace cosmos
