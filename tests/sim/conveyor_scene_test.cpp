// Several parts on the belt: placement, the non-touching rule, the belt motion, and one scan
// that measures every part where its ground truth puts it.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "sim/procedural_meshes.hpp"
#include "tests/sim/scanner_test_scenes.hpp"

namespace cosmos {
namespace {

TEST(ConveyorScene, TwoPartsScannedTogetherLieWhereTheirPosesSay) {
  ConveyorScene scene;
  const TriangleMesh box = make_box(30.0, 20.0, 10.0);
  const TriangleMesh ball = make_icosphere(12.0, 4);
  const int box_mesh = scene.add_mesh(box);
  const int ball_mesh = scene.add_mesh(ball);
  scene.add_part("box", box_mesh, place_on_belt(box, rotation_from_xyz_deg(0, 0, 20), -40.0, 30.0));
  scene.add_part("ball", ball_mesh, place_on_belt(ball, Eigen::Matrix3d::Identity(), 50.0, -35.0));
  // A third part on top of the box's footprint is refused.
  EXPECT_THROW(scene.add_part("overlap", ball_mesh,
                              place_on_belt(ball, Eigen::Matrix3d::Identity(), -35.0, 25.0)),
               std::invalid_argument);
  scene.commit();
  ASSERT_EQ(scene.parts().size(), 2u);

  const RangeImage image = testing::scan(scene, ScannerParameters{});
  ASSERT_GT(image.width(), 0);
  // The box's top (z = 10) around its centre, the ball's top (z = 24) at its centre.
  const auto pixel = [&](double x_mm, double y_mm) {
    return std::pair{
        static_cast<int>(std::lround((x_mm - image.origin_x_mm) / image.pixel_size_x_mm)),
        static_cast<int>(std::lround((y_mm - image.origin_y_mm) / image.pixel_size_y_mm))};
  };
  const auto [bi, bj] = pixel(-40.0, 30.0);
  ASSERT_TRUE(image.has_data(bi, bj));
  EXPECT_NEAR(image.z_mm(bi, bj), 10.0, 0.1);
  const auto [si, sj] = pixel(50.0, -35.0);
  ASSERT_TRUE(image.has_data(si, sj));
  EXPECT_NEAR(image.z_mm(si, sj), 24.0, 0.1);
  // Between the parts lies the belt: background.
  const auto [gi, gj] = pixel(5.0, 0.0);
  EXPECT_FALSE(image.has_data(gi, gj));
}

TEST(ConveyorScene, BeltMotionAndScanRange) {
  ScannerParameters parameters;
  EXPECT_NEAR(T_scanner_belt(parameters, 40).translation().y(), 4.0, 1e-12);
  EXPECT_NEAR(laser_y_belt_mm(parameters, 10), -4.0, 1e-12);
  EXPECT_EQ(parameters.time_us_of_profile(2500), 1000000);
  ConveyorScene scene;
  const TriangleMesh box = make_box(10.0, 20.0, 5.0);
  scene.add_part("box", scene.add_mesh(box),
                 place_on_belt(box, Eigen::Matrix3d::Identity(), 0.0, 100.0));
  scene.commit();
  // The part spans y in [90, 110] at tick 0: the sheet (y_belt = -k 0.4) reaches its
  // downstream end at k = -275 and leaves its upstream end at k = -225.
  const ProfileRange range = profiles_covering(scene, parameters, 0.0);
  EXPECT_EQ(range.first, -275);
  EXPECT_EQ(range.last, -225);
}

}  // namespace
}  // namespace cosmos
