// The model base's parameters text (sim/model_base_build/model_base_parameters.hpp), written by
// visiting the parameter structs: a change of any field that shapes the views (every field of
// cosmos, registration, grouping and the scanner but its line rate and frame drawing, and the
// belt threshold) changes it.
#include "sim/model_base_build/model_base_parameters.hpp"

#include <gtest/gtest.h>

#include <string>

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
  EXPECT_EQ(conditioning_keys, 8);
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

}  // namespace
}  // namespace cosmos
