// Camera mode (rendered sensor frames → firmware_bridge stripe extraction, triangulation,
// resampling) against profile mode (the geometry directly): the same surface within the
// noise, and nearly the same pixels measured.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <opencv2/core.hpp>

#include "sim/camera_frame_renderer.hpp"
#include "sim/mesh.hpp"
#include "sim/part_catalog.hpp"
#include "sim/procedural_meshes.hpp"
#include "tests/sim/scanner_test_scenes.hpp"

namespace cosmos {
namespace {

using testing::scan;
using testing::single_part_scene;

struct ModeComparison {
  std::size_t profile_valid = 0;
  std::size_t camera_valid = 0;
  std::size_t both_valid = 0;
  double rms_mm = 0.0;
};

// Pixel by pixel on the common grid (the two crops may differ).
ModeComparison compare(const RangeImage& profile_mode, const RangeImage& camera_mode) {
  const auto offset_x = static_cast<int>(std::lround(
      (profile_mode.origin_x_mm - camera_mode.origin_x_mm) / profile_mode.pixel_size_x_mm));
  const auto offset_y = static_cast<int>(std::lround(
      (profile_mode.origin_y_mm - camera_mode.origin_y_mm) / profile_mode.pixel_size_y_mm));
  ModeComparison result;
  double sum_squares = 0.0;
  for (int j = 0; j < camera_mode.height(); ++j) {
    for (int i = 0; i < camera_mode.width(); ++i) result.camera_valid += camera_mode.has_data(i, j);
  }
  for (int j = 0; j < profile_mode.height(); ++j) {
    for (int i = 0; i < profile_mode.width(); ++i) {
      if (!profile_mode.has_data(i, j)) continue;
      ++result.profile_valid;
      const int ci = i + offset_x;
      const int cj = j + offset_y;
      if (!camera_mode.z_mm.contains(ci, cj) || !camera_mode.has_data(ci, cj)) continue;
      ++result.both_valid;
      const double d = camera_mode.z_mm(ci, cj) - profile_mode.z_mm(i, j);
      sum_squares += d * d;
    }
  }
  result.rms_mm =
      std::sqrt(sum_squares / static_cast<double>(std::max<std::size_t>(result.both_valid, 1)));
  return result;
}

void expect_modes_agree(const ConveyorScene& scene, const ScannerParameters& parameters,
                        const std::string& what) {
  const RangeImage profile_mode = scan(scene, parameters, ScanMode::kProfile);
  const RangeImage camera_mode = scan(scene, parameters, ScanMode::kCamera);
  ASSERT_GT(profile_mode.width(), 0);
  ASSERT_GT(camera_mode.width(), 0);
  const ModeComparison c = compare(profile_mode, camera_mode);
  const double kept = static_cast<double>(c.both_valid) / static_cast<double>(c.profile_valid);
  std::cout << "[ camera vs profile, " << what << " ] profile-mode valid " << c.profile_valid
            << ", camera-mode valid " << c.camera_valid << ", both " << c.both_valid << " ("
            << 100.0 * kept << " % of profile-mode), rms " << c.rms_mm << " mm\n";
  EXPECT_LE(c.rms_mm, 2.0 * parameters.z_noise_mm + 0.02) << what;
  EXPECT_GE(kept, 0.95) << what;
}

TEST(CameraMode, AgreesWithProfileModeOnASphere) {
  const auto scene = single_part_scene(make_icosphere(15.0, 5), Eigen::Matrix3d::Identity());
  expect_modes_agree(*scene, ScannerParameters{}, "sphere");
}

TEST(CameraMode, AgreesWithProfileModeOnACatalogPart) {
  const std::filesystem::path catalog_path =
      std::filesystem::path(COSMOS_SOURCE_DIR) / "config" / "parts.yaml";
  const PartCatalog catalog = read_part_catalog(catalog_path);
  const PartEntry& part = catalog.at("fandisk");
  ASSERT_TRUE(std::filesystem::exists(part.mesh_path))
      << part.mesh_path << " missing: run scripts/fetch_catalog.sh";
  const TriangleMesh mesh = load_mesh(part.mesh_path, part.size_mm);
  const auto scene = single_part_scene(mesh, resting_rotation(mesh, 7), 0.0, 0.0, part.name);
  expect_modes_agree(*scene, ScannerParameters{}, part.name);
}

TEST(CameraMode, SixteenBitFramesAndSaturation) {
  const auto scene = single_part_scene(make_box(40.0, 40.0, 10.0), Eigen::Matrix3d::Identity());
  ScannerParameters parameters;
  parameters.camera.bit_depth = 12;
  parameters.camera.stripe_peak_level = 1.0;  // a white surface at normal incidence clips
  SimulatedScanner scanner(*scene, parameters, ScanMode::kCamera);
  Profile profile;
  scanner.reserve(profile);
  scanner.acquire(0, profile);  // the sheet crosses the middle of the box
  const cv::Mat& frame = scanner.last_frame();
  EXPECT_EQ(frame.type(), CV_16UC1);
  EXPECT_EQ(frame.cols, parameters.sensor_width_px);
  EXPECT_EQ(frame.rows, parameters.roi_height_px);
  double max_value = 0.0;
  cv::minMaxLoc(frame, nullptr, &max_value);
  EXPECT_EQ(max_value, 4095.0);
  EXPECT_GT(scanner.last_peaks().saturated_columns, 100);
  // Box top and belt, measured through the clipped stripe.
  const std::size_t top = testing::sample_at(profile, 0.0);
  const std::size_t belt = testing::sample_at(profile, 60.0);
  ASSERT_TRUE(profile.has_data(top));
  ASSERT_TRUE(profile.has_data(belt));
  EXPECT_NEAR(profile.z_mm[top], 10.0, 0.1);
  EXPECT_NEAR(profile.z_mm[belt], 0.0, 0.1);
}

}  // namespace
}  // namespace cosmos
