// The model base's parameters text (sim/model_base_build/model_base_parameters.hpp), written by
// visiting the parameter structs: a change of any field that shapes the views (every field of
// cosmos, registration, grouping and the scanner but its line rate and frame drawing, and the
// belt threshold) changes it; the COSMOS parameters and the views' conditioning read back from
// it; a cell's conditioning is compared with the views' on both grid pitches.
#include "sim/model_base_build/model_base_parameters.hpp"

#include <gtest/gtest.h>

#include <string>

#include "core/input_error.hpp"
#include "tests/common/parameter_fields.hpp"

namespace cosmos {
namespace {

// Calls `check(changed_text, key)` once per field of the part of the settings `pick` selects,
// that field changed.
template <class Pick, class Check>
void for_each_changed_field(const ScannerParameters& scanner, const ModelBaseBuildSettings& base,
                            Pick pick, Check check) {
  ModelBaseBuildSettings counted = base;
  const int fields = testing::parameter_field_count(pick(counted));
  ASSERT_GT(fields, 0);
  for (int field = 0; field < fields; ++field) {
    ModelBaseBuildSettings settings = base;
    std::string key;
    pick(settings) = testing::with_field_changed(pick(settings), field, key);
    check(model_base_parameters_text(scanner, settings), key);
  }
}

TEST(ModelBaseParameters, ChangingAnyFieldOfTheBuildChangesTheText) {
  const ScannerParameters scanner;
  const ModelBaseBuildSettings defaults;
  const std::string text = model_base_parameters_text(scanner, defaults);
  const auto differs = [&](const std::string& changed, const std::string& key) {
    EXPECT_NE(changed, text) << key << " is not in the model base's parameters";
  };
  for_each_changed_field(
      scanner, defaults, [](ModelBaseBuildSettings & s) -> auto& { return s.cosmos; }, differs);
  for_each_changed_field(
      scanner, defaults, [](ModelBaseBuildSettings & s) -> auto& { return s.registration; },
      differs);
  for_each_changed_field(
      scanner, defaults, [](ModelBaseBuildSettings & s) -> auto& { return s.grouping; }, differs);
  ModelBaseBuildSettings more_views = defaults;
  more_views.view_count = 80;
  EXPECT_NE(model_base_parameters_text(scanner, more_views), text);

  // Of the conditioning only the belt threshold shapes the views (their grid is the scanner's).
  int conditioning_keys = 0;
  for_each_changed_field(
      scanner, defaults, [](ModelBaseBuildSettings & s) -> auto& { return s.conditioning; },
      [&](const std::string& changed, const std::string& key) {
        ++conditioning_keys;
        if (key == "height_threshold_mm") {
          EXPECT_NE(changed, text);
        } else {
          EXPECT_EQ(changed, text) << key;
        }
      });
  EXPECT_EQ(conditioning_keys, 6);
}

TEST(ModelBaseParameters, ChangingAnyScannerFieldButTheLineRateAndFramesChangesTheText) {
  const ModelBaseBuildSettings settings;
  const std::string text = model_base_parameters_text(ScannerParameters{}, settings);
  const int fields = testing::parameter_field_count(ScannerParameters{});
  EXPECT_EQ(fields, 27);
  for (int field = 0; field < fields; ++field) {
    std::string key;
    const ScannerParameters scanner = testing::with_field_changed(ScannerParameters{}, field, key);
    const std::string changed = model_base_parameters_text(scanner, settings);
    if (key == "line_rate_hz" || key.starts_with("camera.")) {
      EXPECT_EQ(changed, text) << key << ": paces or draws frames, does not shape views";
    } else {
      EXPECT_NE(changed, text) << key << " is not in the model base's parameters";
    }
  }
}

TEST(ModelBaseParameters, TheCosmosParametersReadBackFromTheBase) {
  ModelBaseBuildSettings settings;
  testing::FieldChanger changer(testing::FieldChanger::kAll);
  visit_parameters(changer, settings.cosmos);
  ModelBase base;
  base.parameters_text = model_base_parameters_text(ScannerParameters{}, settings);
  const CosmosParameters read = model_base_cosmos_parameters(base, "base.cmb");
  EXPECT_EQ(testing::parameter_leaves(read), testing::parameter_leaves(settings.cosmos));
  EXPECT_EQ(read.smoothing.iterations, 17);

  ModelBase older;
  older.parameters_text = "{\"cosmos\": {\"fit\": {\"window_size\": 5}}}";
  try {
    model_base_cosmos_parameters(older, "old.cmb");
    FAIL() << "a base without every COSMOS parameter was accepted";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()),
              "old.cmb: built without cosmos.fit.bicubic (a base older than that parameter): "
              "rebuild it");
  }
}

TEST(ModelBaseParameters, ACellsConditioningMustMatchTheViewsOnBothPitchesAndTheThreshold) {
  ModelBaseBuildSettings settings;
  ModelBase base;
  base.parameters_text = model_base_parameters_text(ScannerParameters{}, settings);
  const ModelViewConditioning views = model_base_view_conditioning(base, "base.cmb");
  EXPECT_EQ(views.grid_x_mm, 0.4);
  EXPECT_EQ(views.grid_y_mm, 0.4);
  EXPECT_EQ(views.height_threshold_mm, 0.5);

  const ConditioningParameters cell;
  EXPECT_EQ(conditioning_difference(views, cell), std::nullopt);

  ConditioningParameters coarser = cell;
  coarser.grid_mm = 0.5;
  const auto grid = conditioning_difference(views, coarser);
  ASSERT_TRUE(grid);
  EXPECT_EQ(grid->key, "conditioning.grid_x_mm");
  EXPECT_EQ(grid->expected, "0.5");
  EXPECT_EQ(grid->actual, "0.4");

  // Views across a finer scanner: the x pitch alone differs.
  ScannerParameters finer;
  finer.points_per_profile = 1280;
  const auto x = conditioning_difference(model_view_conditioning(finer, cell), cell);
  ASSERT_TRUE(x);
  EXPECT_EQ(x->key, "conditioning.grid_x_mm");
  EXPECT_EQ(x->actual, "0.2");
  // Views along a coarser belt step: the y pitch alone differs.
  ScannerParameters longer_step;
  longer_step.encoder_ticks_per_profile = 5;
  const auto y = conditioning_difference(model_view_conditioning(longer_step, cell), cell);
  ASSERT_TRUE(y);
  EXPECT_EQ(y->key, "conditioning.grid_y_mm");
  EXPECT_EQ(y->actual, "0.5");

  ConditioningParameters higher = cell;
  higher.height_threshold_mm = 0.8;
  const auto threshold = conditioning_difference(views, higher);
  ASSERT_TRUE(threshold);
  EXPECT_EQ(threshold->key, "conditioning.height_threshold_mm");
}

}  // namespace
}  // namespace cosmos
