// Whether a placed part's surface is where the scene shows surface (surface_seen.hpp), on a
// hand-made scene (plate_scene.hpp) whose pixels off the plate are belt (no data), and model
// points laid out on a 1 mm grid.
#include "core/recognition/surface_seen.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "tests/core/recognition/plate_scene.hpp"

namespace cosmos {
namespace {

using testing::kPlateHeightMm;
using testing::plate_scene;

// Points every 1 mm over [x0, x0 + 20) x [12, 28) at height z.
RegistrationPoints grid_points(double x0_mm, double z_mm) {
  std::vector<Eigen::Vector3d> positions;
  for (double y = 12; y < 28; y += 1)
    for (double x = x0_mm; x < x0_mm + 20; x += 1) positions.emplace_back(x, y, z_mm);
  RegistrationPoints points;
  points.position_mm.resize(3, static_cast<Eigen::Index>(positions.size()));
  for (std::size_t i = 0; i < positions.size(); ++i)
    points.position_mm.col(static_cast<Eigen::Index>(i)) = positions[i];
  return points;
}

TEST(SurfaceSeen, ThePlateItselfIsSeenEverywhere) {
  const SurfaceSeen seen = measure_surface_seen(plate_scene(), grid_points(10, kPlateHeightMm),
                                                RigidTransform::identity(), {});
  EXPECT_EQ(seen.seen, 20 * 16);
  EXPECT_EQ(seen.contradicted, 0);
  EXPECT_EQ(seen.hidden, 0);
  EXPECT_DOUBLE_EQ(seen.seen_fraction(), 1.0);
}

TEST(SurfaceSeen, SurfaceOverTheBeltIsContradicted) {
  // Shifted 10 mm: x in [20, 40), half of it over the belt. The column at x = 30 mm still
  // has plate pixels in its 3 x 3 neighbourhood (x = 29.5 mm), so 11 of 20 columns are seen.
  const SurfaceSeen seen = measure_surface_seen(plate_scene(), grid_points(20, kPlateHeightMm),
                                                RigidTransform::identity(), {});
  EXPECT_EQ(seen.seen, 11 * 16);
  EXPECT_EQ(seen.contradicted, 9 * 16);
  EXPECT_NEAR(seen.seen_fraction(), 11.0 / 20, 1e-12);
}

// The same shifted points over a scene whose belt mask says where the belt was measured: the
// strip x in [34, 40) mm beside the plate was the scanner's shadow (no data, no belt), the
// rest of the background belt. Points over the shadow say nothing; those over the belt still
// count against the part; with no mask every pixel without data does.
TEST(SurfaceSeen, SurfaceOverAShadowIsHiddenOverTheMeasuredBeltContradicted) {
  RangeImage scene = plate_scene();
  scene.belt_seen = PixelGrid<std::uint8_t>(scene.width(), scene.height(), 0);
  for (int row = 0; row < scene.height(); ++row)
    for (int column = 0; column < scene.width(); ++column)
      scene.belt_seen(column, row) = std::isnan(scene.z_mm(column, row)) && scene.x_mm(column) < 34;
  const SurfaceSeen seen =
      measure_surface_seen(scene, grid_points(20, kPlateHeightMm), RigidTransform::identity(), {});
  // Columns x = 20..30 are seen (as above); x = 31..34 have a belt pixel within a pixel (the
  // 3 x 3 neighbourhood of x = 34 mm reaches 33.5 mm); x = 35..39 lie over the shadow alone.
  EXPECT_EQ(seen.seen, 11 * 16);
  EXPECT_EQ(seen.contradicted, 4 * 16);
  EXPECT_EQ(seen.hidden, 5 * 16);
  EXPECT_NEAR(seen.seen_fraction(), 11.0 / 15, 1e-12);
}

TEST(SurfaceSeen, TheSamePoseGivenAsATransformCountsTheSame) {
  // T_model_scene moves scene points 10 mm in -x onto the model: the model at x0 = 10 is the
  // scene's [20, 40), as above.
  RigidTransform T_model_scene;
  T_model_scene.translation_mm = Eigen::Vector3d(-10, 0, 0);
  const SurfaceSeen seen =
      measure_surface_seen(plate_scene(), grid_points(10, kPlateHeightMm), T_model_scene, {});
  EXPECT_EQ(seen.seen, 11 * 16);
  EXPECT_EQ(seen.contradicted, 9 * 16);
}

TEST(SurfaceSeen, BelowTheSceneIsHiddenAboveItIsContradicted) {
  const RangeImage scene = plate_scene();
  const SurfaceSeen below = measure_surface_seen(scene, grid_points(10, kPlateHeightMm - 2),
                                                 RigidTransform::identity(), {});
  EXPECT_EQ(below.hidden, 20 * 16);
  EXPECT_EQ(below.seen + below.contradicted, 0);
  EXPECT_DOUBLE_EQ(below.seen_fraction(), 1.0);  // nothing to tell
  const SurfaceSeen above = measure_surface_seen(scene, grid_points(10, kPlateHeightMm + 2),
                                                 RigidTransform::identity(), {});
  EXPECT_EQ(above.contradicted, 20 * 16);
  EXPECT_DOUBLE_EQ(above.seen_fraction(), 0.0);
  // Within the tolerance it is seen.
  const SurfaceSeen near = measure_surface_seen(scene, grid_points(10, kPlateHeightMm + 0.9),
                                                RigidTransform::identity(), {});
  EXPECT_EQ(near.seen, 20 * 16);
}

// The default scanner's: the camera 600 mm above the belt, 30 degrees upstream (-y) of the laser
// sheet, and the fan's source 600 mm above the belt centre.
ScannerSight default_sight() {
  ScannerSight sight;
  sight.camera_mm = Eigen::Vector3d(0, -600 * std::tan(30 * std::numbers::pi / 180), 600);
  sight.laser_height_mm = 600;
  return sight;
}

RegistrationPoints with_normals(RegistrationPoints points, const Eigen::Vector3d& normal) {
  points.normal = normal.normalized().replicate(1, points.position_mm.cols());
  return points;
}

// Half of the shifted points lie over the belt. Facing the camera they count as they do without
// a sight; tilted 70 degrees downstream, away from a camera 30 degrees upstream, or facing the
// belt, away from the laser, no scan from this side measures them, so they say nothing.
TEST(SurfaceSeen, SurfaceFacingAwayFromTheCameraOrTheLaserIsHiddenWhereverItLies) {
  SurfaceSeenParameters parameters;
  parameters.sight = default_sight();
  const double tilt = 70 * std::numbers::pi / 180;
  const RegistrationPoints points = grid_points(20, kPlateHeightMm);
  const SurfaceSeen upstream = measure_surface_seen(
      plate_scene(), with_normals(points, {0, -std::sin(tilt), std::cos(tilt)}),
      RigidTransform::identity(), parameters);
  EXPECT_EQ(upstream.seen, 11 * 16);
  EXPECT_EQ(upstream.contradicted, 9 * 16);
  const SurfaceSeen downstream =
      measure_surface_seen(plate_scene(), with_normals(points, {0, std::sin(tilt), std::cos(tilt)}),
                           RigidTransform::identity(), parameters);
  EXPECT_EQ(downstream.seen, 0);
  EXPECT_EQ(downstream.contradicted, 0);
  EXPECT_EQ(downstream.hidden, 20 * 16);
  const SurfaceSeen underside = measure_surface_seen(
      plate_scene(), with_normals(points, {0, 0, -1}), RigidTransform::identity(), parameters);
  EXPECT_EQ(underside.hidden, 20 * 16);
  // Without the sight the downstream slope counts as any surface does.
  const SurfaceSeen unknown =
      measure_surface_seen(plate_scene(), with_normals(points, {0, std::sin(tilt), std::cos(tilt)}),
                           RigidTransform::identity(), {});
  EXPECT_EQ(unknown.seen, 11 * 16);
  EXPECT_EQ(unknown.contradicted, 9 * 16);
}

// The normals are the model's: the transform turns them into the scene with the points. A point
// facing straight up in the model, turned 70 degrees about x by T_scene_model, faces downstream.
TEST(SurfaceSeen, TheModelsNormalsAreTurnedIntoTheSceneBeforeFacingIsJudged) {
  SurfaceSeenParameters parameters;
  parameters.sight = default_sight();
  RigidTransform T_scene_model;
  T_scene_model.rotation =
      Eigen::AngleAxisd(-70 * std::numbers::pi / 180, Eigen::Vector3d::UnitX()).matrix();
  RegistrationPoints points =
      with_normals(grid_points(20, kPlateHeightMm), Eigen::Vector3d::UnitZ());
  points.position_mm = T_scene_model.inverse().rotation * points.position_mm;
  const SurfaceSeen seen =
      measure_surface_seen(plate_scene(), points, T_scene_model.inverse(), parameters);
  EXPECT_EQ(seen.hidden, 20 * 16);
}

}  // namespace
}  // namespace cosmos
