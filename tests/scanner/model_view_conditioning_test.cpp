// The conditioning a model base's views were taken with (scanner/model_view_conditioning.hpp),
// read back from its parameters text and compared with a cell's on both grid pitches and the
// belt threshold, naming the first key that differs. The laser sheet's pitch is the live
// scanner's alone (the views are rendered with an upright sheet): it never makes a base differ.
#include "scanner/model_view_conditioning.hpp"

#include <gtest/gtest.h>

#include <string>

namespace cosmos {
namespace {

TEST(ModelViewConditioning, ACellsConditioningMustMatchTheViewsOnBothPitchesAndTheThreshold) {
  // What the model-base build records: the default scanner's views, the default belt threshold.
  ParameterText text;
  text.set_parameters("conditioning",
                      model_view_conditioning(ScannerParameters{}, ConditioningParameters{}));
  ModelBase base;
  base.parameters_text = text.text();
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

TEST(ModelViewConditioning, ThePitchOfTheLiveSheetDoesNotMakeABaseDiffer) {
  ParameterText text;
  text.set_parameters("conditioning",
                      model_view_conditioning(ScannerParameters{}, ConditioningParameters{}));
  EXPECT_EQ(text.text().find("sheet_pitch_deg"), std::string::npos);
  EXPECT_EQ(text.text().find("max_height_mm"), std::string::npos);
  ModelBase base;
  base.parameters_text = text.text();
  ConditioningParameters pitched;
  pitched.sheet_pitch_deg = -4.5;
  pitched.max_height_mm = 80;
  EXPECT_EQ(conditioning_difference(model_base_view_conditioning(base, "base.cmb"), pitched),
            std::nullopt);
}

}  // namespace
}  // namespace cosmos
