// The simulated scanner's geometry against analytic truth: a sphere's heights, a tilted
// plane's slope, the camera-occlusion band behind a step and the laser shadow beside it, as
// the triangulation geometry predicts them.
#include "sim/laser_line_scanner.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <cstring>
#include <iostream>
#include <numbers>

#include "sim/procedural_meshes.hpp"
#include "tests/sim/scanner_test_scenes.hpp"

namespace cosmos {
namespace {

using testing::scan;
using testing::scan_profiles;
using testing::single_part_scene;

constexpr double kDegree = std::numbers::pi / 180.0;

struct SphereErrors {
  std::size_t valid = 0;
  std::size_t within = 0;
  double mean_mm = 0.0;
  double rms_mm = 0.0;
};

// Heights of a scanned sphere (radius R resting on the belt) against the analytic surface.
SphereErrors sphere_errors(const RangeImage& image, double radius_mm, double tolerance_mm) {
  SphereErrors errors;
  double sum = 0.0;
  double sum_squares = 0.0;
  for (int j = 0; j < image.height(); ++j) {
    for (int i = 0; i < image.width(); ++i) {
      if (!image.has_data(i, j)) continue;
      ++errors.valid;
      const double x = image.x_mm(i);
      const double y = image.y_mm(j);
      const double r2 = x * x + y * y;
      if (r2 >= radius_mm * radius_mm) continue;
      const double error = image.z_mm(i, j) - (radius_mm + std::sqrt(radius_mm * radius_mm - r2));
      sum += error;
      sum_squares += error * error;
      if (std::abs(error) <= tolerance_mm) ++errors.within;
    }
  }
  errors.mean_mm = sum / static_cast<double>(errors.valid);
  errors.rms_mm = std::sqrt(sum_squares / static_cast<double>(errors.valid));
  return errors;
}

class SphereScan : public ::testing::TestWithParam<int> {};

TEST_P(SphereScan, HeightsMatchTheAnalyticSphere) {
  const double radius_mm = 10.0;  // the 20 mm sphere
  const TriangleMesh sphere = make_icosphere(radius_mm, 5);
  const auto scene = single_part_scene(sphere, Eigen::Matrix3d::Identity());
  ScannerParameters parameters;
  parameters.points_per_profile = GetParam();
  const RangeImage image = scan(*scene, parameters);
  // The flat facets lie inside the sphere by the sag; on a slope of angle a a radial error
  // shows as a height error 1/cos(a) times larger, and slopes reach the incidence limit.
  const double sag_mm = icosphere_max_sag_mm(sphere, radius_mm);
  const double tolerance_mm =
      3.0 * parameters.z_noise_mm + sag_mm / std::cos(parameters.max_incidence_deg * kDegree);
  const SphereErrors errors = sphere_errors(image, radius_mm, tolerance_mm);
  std::cout << "[ sphere W=" << GetParam() << " ] valid " << errors.valid << ", within "
            << tolerance_mm << " mm: " << 100.0 * errors.within / errors.valid << " %, mean "
            << errors.mean_mm << " mm, rms " << errors.rms_mm << " mm (sigma "
            << parameters.z_noise_mm << ", sag " << sag_mm << ")\n";
  // The visible cap above the background threshold spans ~ pi (R sin 80°)^2 / dx dy pixels.
  const double dx = parameters.sample_spacing_mm(parameters.points_per_profile);
  EXPECT_GT(errors.valid, static_cast<std::size_t>(0.6 * std::numbers::pi * 90.0 / (dx * 0.4)));
  EXPECT_GE(static_cast<double>(errors.within), 0.99 * static_cast<double>(errors.valid));
  EXPECT_LT(std::abs(errors.mean_mm), 0.005);
  EXPECT_NEAR(errors.rms_mm, parameters.z_noise_mm, 0.005);
}

INSTANTIATE_TEST_SUITE_P(ProfileWidths, SphereScan, ::testing::Values(640, 1280, 3200));

// Least-squares plane z = a x + b y + c through the valid pixels within `half_mm` of (x, y).
Eigen::Vector3d fit_plane(const RangeImage& image, double x_mm, double y_mm, double half_mm) {
  Eigen::Matrix3d normal_matrix = Eigen::Matrix3d::Zero();
  Eigen::Vector3d rhs = Eigen::Vector3d::Zero();
  for (int j = 0; j < image.height(); ++j) {
    for (int i = 0; i < image.width(); ++i) {
      if (!image.has_data(i, j)) continue;
      if (std::abs(image.x_mm(i) - x_mm) > half_mm || std::abs(image.y_mm(j) - y_mm) > half_mm)
        continue;
      const Eigen::Vector3d row(image.x_mm(i), image.y_mm(j), 1.0);
      normal_matrix += row * row.transpose();
      rhs += row * image.z_mm(i, j);
    }
  }
  return normal_matrix.ldlt().solve(rhs);
}

TEST(TiltedPlaneScan, SlopeIsFifteenDegrees) {
  const TriangleMesh plate = make_box(60.0, 60.0, 2.0);
  for (const auto& [rx, ry] : {std::pair{15.0, 0.0}, std::pair{-15.0, 0.0}, std::pair{0.0, 15.0}}) {
    const auto scene = single_part_scene(plate, rotation_from_xyz_deg(rx, ry, 0.0));
    const RangeImage image = scan(*scene, ScannerParameters{});
    const Eigen::Vector3d plane = fit_plane(image, 0.0, 0.0, 20.0);
    const double slope_deg = std::atan(std::hypot(plane.x(), plane.y())) / kDegree;
    std::cout << "[ plate rx=" << rx << " ry=" << ry << " ] slope " << slope_deg << " deg\n";
    EXPECT_NEAR(slope_deg, 15.0, 0.2) << "rx " << rx << " ry " << ry;
    // The slope runs along the axis the plate was tilted about's normal.
    EXPECT_NEAR(std::atan(std::abs(ry != 0.0 ? plane.x() : plane.y())) / kDegree, 15.0, 0.2);
  }
}

// A 10 mm step: a 40 x 40 x 10 mm box. The camera looks from upstream (−y) at the
// triangulation angle, so the belt just downstream of the box's +y face is hidden from it
// while the sheet lights it: the line from a belt point at distance d beyond the face to the
// camera centre clears the box's top edge only when d >= h · tan(angle).
TEST(StepScan, OcclusionBandBehindTheStepMatchesTheGeometry) {
  const double height_mm = 10.0;
  const auto scene =
      single_part_scene(make_box(40.0, 40.0, height_mm), Eigen::Matrix3d::Identity());
  ScannerParameters parameters;
  const testing::ProfileScan profiles = scan_profiles(*scene, parameters, 15.0);
  const double predicted_mm = height_mm * std::tan(parameters.triangulation_angle_deg * kDegree);
  for (const double x_mm : {-10.0, 0.0, 10.0}) {
    // Downstream (+y, away from the camera): the first measured belt sample beyond the face.
    double first_seen_downstream_mm = 1e9;
    double last_seen_upstream_mm = -1e9;
    std::size_t nan_downstream = 0;
    for (std::size_t k = 0; k < profiles.profiles.size(); ++k) {
      const Profile& profile = profiles.profiles[k];
      const double y = profiles.y_mm[k];
      const bool measured = profile.has_data(testing::sample_at(profile, x_mm));
      if (y > 20.0 && measured) first_seen_downstream_mm = std::min(first_seen_downstream_mm, y);
      if (y > 20.0 && !measured) ++nan_downstream;
      if (y < -20.0 && measured) last_seen_upstream_mm = std::max(last_seen_upstream_mm, y);
    }
    const double band_mm = first_seen_downstream_mm - 20.0;
    std::cout << "[ step x=" << x_mm << " ] occlusion band " << band_mm << " mm (" << nan_downstream
              << " profiles), predicted " << predicted_mm << " mm\n";
    EXPECT_NEAR(band_mm, predicted_mm, parameters.profile_step_mm());
    EXPECT_NEAR(nan_downstream * parameters.profile_step_mm(), predicted_mm,
                parameters.profile_step_mm());
    // Upstream the camera sees the belt right up to the box.
    EXPECT_GE(last_seen_upstream_mm, -20.0 - parameters.profile_step_mm() - 1e-9);
  }
}

// Beside an off-centre step the belt is lost across x too. The fan laser, from above the
// belt centre at height L, leaves a laser shadow of width x_edge · h / (L − h) beyond the
// outer top edge; the camera, above the belt centre at height H, is hidden from a band of
// x_edge · h / (H − h). With the laser at 150 mm the shadow is the wider; a parallel sheet
// casts none, leaving only the camera's band.
TEST(StepScan, LaserShadowAndCameraBandBesideTheStep) {
  const double height_mm = 20.0;
  const double edge_mm = 80.0;
  const auto scene =
      single_part_scene(make_box(40.0, 40.0, height_mm), Eigen::Matrix3d::Identity(), 60.0);
  for (const LaserModel model : {LaserModel::kFan, LaserModel::kParallel}) {
    ScannerParameters parameters;
    parameters.laser_model = model;
    parameters.laser_height_mm = 150.0;
    LaserLineScanner laser(*scene, parameters, parameters.points_per_profile);
    LaserLine line;
    laser.trace(0.0, line);
    const LaserSampleState expected_state = model == LaserModel::kFan
                                                ? LaserSampleState::kLaserShadow
                                                : LaserSampleState::kCameraOccluded;
    const double predicted_mm =
        model == LaserModel::kFan ? edge_mm * height_mm / (parameters.laser_height_mm - height_mm)
                                  : edge_mm * height_mm / (parameters.camera_height_mm - height_mm);
    int band_samples = 0;
    double first_measured_mm = 1e9;
    for (int i = 0; i < line.width(); ++i) {
      if (line.x_mm(i) <= edge_mm) continue;
      const LaserSampleState state = line.state[static_cast<std::size_t>(i)];
      if (state == expected_state) ++band_samples;
      if (state == LaserSampleState::kMeasured)
        first_measured_mm = std::min(first_measured_mm, line.x_mm(i));
    }
    std::cout << "[ beside step, " << (model == LaserModel::kFan ? "fan" : "parallel") << " ] band "
              << band_samples * line.dx_mm << " mm, first measured " << first_measured_mm - edge_mm
              << " mm beyond the edge, predicted " << predicted_mm << " mm\n";
    EXPECT_NEAR(band_samples * line.dx_mm, predicted_mm, line.dx_mm);
    EXPECT_NEAR(first_measured_mm - edge_mm, predicted_mm, line.dx_mm);
  }
}

TEST(SimulatedScanner, SameSeedSameBytesOtherSeedOtherNoise) {
  const auto scene = single_part_scene(make_icosphere(10.0, 4), Eigen::Matrix3d::Identity());
  ScannerParameters parameters;
  const RangeImage a = scan(*scene, parameters);
  const RangeImage b = scan(*scene, parameters);
  ASSERT_EQ(a.z_mm.size(), b.z_mm.size());
  EXPECT_EQ(std::memcmp(a.z_mm.data(), b.z_mm.data(), a.z_mm.size() * sizeof(float)), 0);
  parameters.seed = 2;
  const RangeImage c = scan(*scene, parameters);
  ASSERT_EQ(a.z_mm.size(), c.z_mm.size());
  EXPECT_NE(std::memcmp(a.z_mm.data(), c.z_mm.data(), a.z_mm.size() * sizeof(float)), 0);
}

TEST(SimulatedScanner, RangeImageFrameHoldsTheGroundTruth) {
  // A box off-centre: its measured top must sit where T_belt_part puts it, and rows must run
  // in increasing y (not mirrored).
  const auto scene =
      single_part_scene(make_box(30.0, 20.0, 8.0), rotation_from_xyz_deg(0, 0, 30), 25.0, -40.0);
  const RangeImage image = scan(*scene, ScannerParameters{});
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  std::size_t count = 0;
  for (int j = 0; j < image.height(); ++j) {
    for (int i = 0; i < image.width(); ++i) {
      if (!image.has_data(i, j)) continue;
      sum += image.point_mm(i, j);
      ++count;
    }
  }
  ASSERT_GT(count, 1000u);
  const Eigen::Vector3d mean = sum / static_cast<double>(count);
  const Eigen::Vector3d centre = scene->parts().front().T_belt_part.translation();
  EXPECT_NEAR(mean.x(), centre.x(), 0.5);
  EXPECT_NEAR(mean.y(), centre.y(), 0.5);
  EXPECT_NEAR(mean.z(), 8.0, 0.01);
}

}  // namespace
}  // namespace cosmos

namespace cosmos {
namespace {

// A part's heights are its own: a taller part further down the belt must not change them in
// any bit (the probe once started above the whole scene, so its rounding followed the
// tallest part on the belt, and the same part scored differently in longer streams).
TEST(LaserLineScanner, APartsLineDoesNotDependOnTheOtherPartsOnTheBelt) {
  const TriangleMesh ball = make_icosphere(15.0, 3);
  const TriangleMesh tower = make_box(20.0, 20.0, 90.0);
  const ScannerParameters parameters;
  ConveyorScene alone;
  alone.add_part("ball", alone.add_mesh(ball), place_on_belt(ball, Eigen::Matrix3d::Identity()));
  alone.commit();
  ConveyorScene with_tower;
  with_tower.add_part("ball", with_tower.add_mesh(ball),
                      place_on_belt(ball, Eigen::Matrix3d::Identity()));
  with_tower.add_part("tower", with_tower.add_mesh(tower),
                      place_on_belt(tower, Eigen::Matrix3d::Identity(), 0.0, -200.0));
  with_tower.commit();
  LaserLineScanner scanner_alone(alone, parameters, parameters.points_per_profile);
  LaserLineScanner scanner_with_tower(with_tower, parameters, parameters.points_per_profile);
  LaserLine line_alone, line_with_tower;
  int lit = 0;
  for (double y_mm = -16.0; y_mm <= 16.0; y_mm += 0.4) {
    scanner_alone.trace(y_mm, line_alone);
    scanner_with_tower.trace(y_mm, line_with_tower);
    ASSERT_EQ(std::memcmp(line_alone.z_mm.data(), line_with_tower.z_mm.data(),
                          line_alone.z_mm.size() * sizeof(float)),
              0)
        << "y " << y_mm;
    for (const float z : line_alone.z_mm) lit += z > 1.0f ? 1 : 0;
  }
  EXPECT_GT(lit, 1000);  // the ball was scanned
}

// The rays are traced in each part's own frame, carried there in double precision, so a part
// scanned 120 m down the belt gives the line it gives at the belt's start. Floats of belt
// coordinates have steps of ~8 um there, more than the offset that keeps an occlusion ray off
// its own surface: a scene in belt coordinates speckled far parts with false occlusions.
TEST(LaserLineScanner, APartFarDownTheBeltGivesTheLineItGivesAtTheStart) {
  const TriangleMesh part = make_box(20.0, 30.0, 12.0);
  const Eigen::Matrix3d R = (Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitZ()) *
                             Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitX()))
                                .toRotationMatrix();
  const double far_mm = -120000.0;
  const ScannerParameters parameters;
  ConveyorScene near_scene;
  near_scene.add_part("near", near_scene.add_mesh(part), place_on_belt(part, R));
  near_scene.commit();
  ConveyorScene far_scene;
  far_scene.add_part("far", far_scene.add_mesh(part), place_on_belt(part, R, 0.0, far_mm));
  far_scene.commit();
  LaserLineScanner near_scanner(near_scene, parameters, parameters.points_per_profile);
  LaserLineScanner far_scanner(far_scene, parameters, parameters.points_per_profile);
  LaserLine near_line, far_line;
  int measured = 0;
  int occluded = 0;
  for (int k = -60; k <= 60; ++k) {
    const double y_mm = 0.4 * k;
    near_scanner.trace(y_mm, near_line);
    far_scanner.trace(far_mm + y_mm, far_line);
    for (std::size_t i = 0; i < near_line.z_mm.size(); ++i) {
      ASSERT_EQ(near_line.state[i], far_line.state[i]) << "y " << y_mm << " sample " << i;
      ASSERT_NEAR(near_line.z_mm[i], far_line.z_mm[i], 1e-4) << "y " << y_mm << " sample " << i;
      if (near_line.z_mm[i] > 1.0f) {
        measured += near_line.state[i] == LaserSampleState::kMeasured ? 1 : 0;
        occluded += near_line.state[i] == LaserSampleState::kCameraOccluded ? 1 : 0;
      }
    }
  }
  EXPECT_GT(measured, 2000);  // the part was scanned
  EXPECT_GT(occluded, 0);     // and its faces hide some of it from the camera
}

// A pitched scanner head (the sheet leaning downstream by p): the sheet meets a box's top at
// in-sheet height h / cos p, h · tan p upstream of where an upright sheet first meets it; past
// the box's downstream edge the leaning sheet's lower part still lights the +y face, at the
// in-sheet height where the sheet crosses it.
TEST(LaserLineScanner, APitchedSheetMeetsABoxWhereItsLeanPutsIt) {
  const double height_mm = 10.0;
  const double pitch_deg = 3.0;
  const double lean_mm = height_mm * std::tan(pitch_deg * kDegree);
  const auto scene =
      single_part_scene(make_box(40.0, 40.0, height_mm), Eigen::Matrix3d::Identity());
  const ScannerParameters parameters;
  LaserLineScanner scanner(*scene, parameters, parameters.points_per_profile, pitch_deg);
  LaserLine line;
  scanner.reserve(line);
  const std::size_t centre = static_cast<std::size_t>(std::lround(-line.x0_mm / line.dx_mm));
  const auto height_at_centre = [&](double foot_y_mm) {
    scanner.trace(foot_y_mm, line);
    return static_cast<double>(line.z_mm[centre]);
  };
  const double top_s_mm = height_mm / std::cos(pitch_deg * kDegree);
  EXPECT_EQ(height_at_centre(-20.0 - lean_mm - 0.2), 0.0);
  EXPECT_NEAR(height_at_centre(-20.0 - lean_mm + 0.2), top_s_mm, 1e-3);
  EXPECT_NEAR(height_at_centre(0.0 - lean_mm), top_s_mm, 1e-3);
  EXPECT_NEAR(height_at_centre(20.0 - lean_mm - 0.2), top_s_mm, 1e-3);
  // Past the edge: the sheet crosses the face y = 20 at s = (20 − foot) / sin p.
  const double foot_mm = 20.0 - lean_mm + 0.2;
  EXPECT_NEAR(height_at_centre(foot_mm), (20.0 - foot_mm) / std::sin(pitch_deg * kDegree), 1e-2);
  EXPECT_EQ(height_at_centre(20.0 + 0.2), 0.0);
}

}  // namespace
}  // namespace cosmos
