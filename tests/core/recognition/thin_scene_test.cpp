// The range points a thin scene is searched with (thin_scene.hpp range_points), on the plate
// scene: every pixel with data, evenly thinned to at most the number asked for, where the
// pixel is, facing the sensor. And ThinSceneFit on the plate scene with a 20 x 20 x 5 mm box
// whose top face is the plate: a pose lifted off the belt is set down on it, one moved off
// the plate is aligned back onto it, and one off the silhouette, reaching over the belt or
// beyond the image, is not taken.
#include "core/recognition/thin_scene.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <vector>

#include "tests/core/recognition/plate_scene.hpp"

namespace cosmos {
namespace {

using testing::kPlateHeightMm;
using testing::plate_scene;
using testing::plate_scene_on_belt;

// The box: its hull's corners about its centre, and its top face (a 0.5 mm grid) as the field
// and the surface sample.
struct PlateBox {
  ModelPart part;
  PartSearchModel model;
};

PlateBox plate_box() {
  PlateBox box;
  for (double x : {-10.0, 10.0})
    for (double y : {-10.0, 10.0})
      for (double z : {-2.5, 2.5}) box.part.hull_vertices_mm.emplace_back(x, y, z);
  std::vector<Eigen::Vector3d> top_mm;
  for (double x = -9.75; x < 10; x += 0.5)
    for (double y = -9.75; y < 10; y += 0.5) top_mm.emplace_back(x, y, 2.5);
  box.model.field = PartDistanceField(top_mm, {});
  box.model.surface_sample_mm.resize(3, static_cast<Eigen::Index>(top_mm.size()));
  for (std::size_t i = 0; i < top_mm.size(); ++i)
    box.model.surface_sample_mm.col(static_cast<Eigen::Index>(i)) = top_mm[i];
  return box;
}

// T_part_scene of the box with its centre at (x, y, z) in the scene.
RigidTransform box_at(double x_mm, double y_mm, double z_mm) {
  return RigidTransform{Eigen::Matrix3d::Identity(), Eigen::Vector3d(x_mm, y_mm, z_mm)}.inverse();
}

TEST(ThinScene, EveryPixelWithDataIsARangePointWhenFewEnough) {
  const RegistrationPoints points = range_points(plate_scene(), 5000);
  ASSERT_EQ(points.size(), 40 * 40);  // the plate's 20 x 20 mm of 0.5 mm pixels
  // Row-major from the plate's first pixel.
  EXPECT_DOUBLE_EQ(points.position_mm(0, 0), 10.0);
  EXPECT_DOUBLE_EQ(points.position_mm(1, 0), 10.0);
  EXPECT_DOUBLE_EQ(points.position_mm(0, 1), 10.5);
  EXPECT_DOUBLE_EQ(points.position_mm(1, 40), 10.5);
  for (int i = 0; i < points.size(); ++i) {
    EXPECT_DOUBLE_EQ(points.position_mm(2, i), kPlateHeightMm);
    EXPECT_EQ(points.normal.col(i), Eigen::Vector3d::UnitZ());
  }
}

TEST(ThinScene, ManyPixelsAreThinnedEvenlyToAtMostTheNumberAsked) {
  const RegistrationPoints points = range_points(plate_scene(), 400);
  ASSERT_EQ(points.size(), 400);  // every 4th of 1,600
  EXPECT_DOUBLE_EQ(points.position_mm(0, 1) - points.position_mm(0, 0), 2.0);
  EXPECT_LE(range_points(plate_scene(), 7).size(), 7);
  EXPECT_GE(range_points(plate_scene(), 7).size(), 6);
}

TEST(ThinScene, AnEmptySceneHasNoRangePoints) {
  RangeImage scene = plate_scene();
  for (float& z : scene.z_mm.values()) z = std::numeric_limits<float>::quiet_NaN();
  EXPECT_EQ(range_points(scene, 400).size(), 0);
}

class ThinSceneFitOnThePlate : public ::testing::Test {
 protected:
  const RangeImage scene_ = plate_scene_on_belt();
  const RegistrationPoints points_ = range_points(scene_, 400);
  const ThinSceneParameters parameters_;
  const RestingSearchParameters resting_;
  const ThinSceneFit fit_{scene_, points_, parameters_, resting_, 10.0};
  const PlateBox box_ = plate_box();
};

TEST_F(ThinSceneFitOnThePlate, APoseLiftedOffTheBeltIsSetDownOnIt) {
  // The true centre is (20, 20, 2.5): the top face at the plate's 5 mm.
  const SettledPose settled = fit_.settle(0, box_.part, box_.model, box_at(20, 20, 6.5));
  const Eigen::Vector3d centre_mm = settled.T_part_scene.inverse().translation_mm;
  EXPECT_NEAR(centre_mm.z(), 2.5, 1e-9);
  EXPECT_NEAR(centre_mm.x(), 20, 0.5);
  EXPECT_NEAR(centre_mm.y(), 20, 0.5);
  EXPECT_DOUBLE_EQ(settled.fraction_over_belt, 0.0);
  EXPECT_LT(settled.mean_square_mm2, 0.05);
}

TEST_F(ThinSceneFitOnThePlate, AlignedInTheFieldAPoseOffTheSilhouetteComesBack) {
  const SettledPose settled = fit_.settle(0, box_.part, box_.model, box_at(30, 20, 2.5));
  EXPECT_NEAR(settled.T_part_scene.inverse().translation_mm.x(), 20, 2.5);
  EXPECT_LT(settled.fraction_over_belt, 0.05);
}

TEST_F(ThinSceneFitOnThePlate, APoseOffTheSilhouetteIsNotTaken) {
  ThinSceneParameters set_down_only;
  set_down_only.settle_rounds = 0;
  const ThinSceneFit fit(scene_, points_, set_down_only, resting_, 10.0);
  // 10 mm along x: the box's far half reaches over the belt to the image's edge at 40 mm.
  const SettledPose off = fit.settle(0, box_.part, box_.model, box_at(30, 20, 2.5));
  EXPECT_GT(off.fraction_over_belt, 0.3);
  // 25 mm along x: most of it beyond the image, which counts as belt here.
  const SettledPose beyond = fit.settle(0, box_.part, box_.model, box_at(45, 20, 2.5));
  EXPECT_GT(beyond.fraction_over_belt, 0.9);
  const std::vector<FieldHypothesis> poses = {{box_at(30, 20, 2.5), 0}, {box_at(20, 20, 6.5), 0}};
  const std::optional<SettledPose> best = fit.best_settled(0, box_.part, box_.model, poses, 0.05);
  ASSERT_TRUE(best.has_value());
  EXPECT_NEAR(best->T_part_scene.inverse().translation_mm.x(), 20, 1e-9);
  EXPECT_DOUBLE_EQ(best->inlier_fraction, 1.0);  // every plate point on the box's top
  EXPECT_FALSE(fit.best_settled(0, box_.part, box_.model, {poses[0]}, 0.05).has_value());
}

TEST_F(ThinSceneFitOnThePlate, APartWithoutHullCornersStaysWhereItWas) {
  PlateBox box = plate_box();
  box.part.hull_vertices_mm.clear();
  const SettledPose settled = fit_.settle(0, box.part, box.model, box_at(20, 20, 2.5));
  EXPECT_NEAR(settled.T_part_scene.inverse().translation_mm.z(), 2.5, 1e-6);
}

}  // namespace
}  // namespace cosmos
