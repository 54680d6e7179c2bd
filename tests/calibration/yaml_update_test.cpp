#include "calibration/yaml_update.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/io/yaml_section_reader.hpp"
#include "realtime/config/hardware_config.hpp"

namespace cosmos {
namespace {

namespace fs = std::filesystem;

TEST(YamlUpdate, WritesNestedSectionsAndKeepsTheOtherKeys) {
  const fs::path file = fs::path(::testing::TempDir()) / "yaml_update_test.yaml";
  {
    std::ofstream out(file);
    out << "scanner:\n  z_noise_mm: 0.03\n  encoder_mm_per_tick: 0.1\ncell:\n  model_views: 80\n";
  }
  RigidTransform T;
  T.rotation = rotation_from_xyz_angles_deg(1.5, -2.0, 91.0);
  T.translation_mm = Eigen::Vector3d(850.25, -420.5, 310.125);
  update_yaml_file(file, {{"scanner.encoder_mm_per_tick", YAML::Node(0.102)},
                          {"cell.T_cell_scanner", yaml_of_transform(T)}});
  const YAML::Node root = YAML::LoadFile(file.string());
  EXPECT_DOUBLE_EQ(root["scanner"]["z_noise_mm"].as<double>(), 0.03);
  EXPECT_DOUBLE_EQ(root["scanner"]["encoder_mm_per_tick"].as<double>(), 0.102);
  EXPECT_EQ(root["cell"]["model_views"].as<int>(), 80);
  const YAML::Node angles = root["cell"]["T_cell_scanner"]["rotation_deg"];
  EXPECT_NEAR(angles[0].as<double>(), 1.5, 1e-9);
  EXPECT_NEAR(angles[1].as<double>(), -2.0, 1e-9);
  EXPECT_NEAR(angles[2].as<double>(), 91.0, 1e-9);
  EXPECT_DOUBLE_EQ(root["cell"]["T_cell_scanner"]["translation_mm"][2].as<double>(), 310.125);
}

TEST(YamlUpdate, ACalibrationSectionReadsBackThroughTheHardwareReader) {
  const fs::path file = fs::path(::testing::TempDir()) / "yaml_update_hardware.yaml";
  {
    std::ofstream out(file);
    out << "camera:\n  device: simulated\ngpio:\n  chip: simulated\n";
  }
  ScannerCalibration calibration;
  calibration.camera = {true, 3500.5, 3499.5, 645.25, 507.75, -0.2, 0.01, 0, 0, 0};
  calibration.laser = {true, 0.0, 0.86, -0.51, 356.8};
  calibration.mount.calibrated = true;
  calibration.mount.T_scanner_camera.rotation = rotation_from_xyz_angles_deg(-149, 0.5, 0.2);
  update_yaml_file(file, {{"calibration", yaml_of(calibration)}});
  const HardwareConfig config = read_hardware_config(file);
  EXPECT_TRUE(config.calibration.camera.calibrated);
  EXPECT_DOUBLE_EQ(config.calibration.camera.fx_px, 3500.5);
  EXPECT_DOUBLE_EQ(config.calibration.camera.k1, -0.2);
  EXPECT_DOUBLE_EQ(config.calibration.laser.offset_mm, 356.8);
  EXPECT_LT(rotation_angle_between_rad(config.calibration.mount.T_scanner_camera.rotation,
                                       calibration.mount.T_scanner_camera.rotation),
            1e-9);
}

}  // namespace
}  // namespace cosmos
