// The `scanner:` section of the cell config: defaults, overrides, and a one-line
// `file:LINE: scanner.key: reason` for every bad key, type and range.
#include "scanner/scanner_config.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "core/input_error.hpp"
#include "tests/common/config_file_test.hpp"

namespace cosmos {
namespace {

namespace fs = std::filesystem;

class ScannerConfig : public testing::ConfigFileTest {
 protected:
  std::string error_of(const std::string& text) const {
    return error_when_loading(text, [](const fs::path& file) { read_scanner_config(file); });
  }
};

TEST_F(ScannerConfig, ShippedConfigHoldsTheDefaults) {
  const ScannerParameters read =
      read_scanner_config(fs::path(COSMOS_SOURCE_DIR) / "config" / "cell.yaml");
  const ScannerParameters defaults;
  EXPECT_EQ(read.points_per_profile, defaults.points_per_profile);
  EXPECT_EQ(read.profile_step_mm(), defaults.profile_step_mm());
  EXPECT_EQ(read.line_rate_hz, defaults.line_rate_hz);
  EXPECT_EQ(read.triangulation_angle_deg, defaults.triangulation_angle_deg);
  EXPECT_EQ(read.field_of_view_mm, defaults.field_of_view_mm);
  EXPECT_EQ(read.z_noise_mm, defaults.z_noise_mm);
  EXPECT_EQ(read.seed, defaults.seed);
  EXPECT_NEAR(defaults.belt_speed_mm_per_s(), 1000.0, 1e-9);
  EXPECT_NO_THROW(check_scanner_parameters(read));
}

TEST_F(ScannerConfig, OverridesAndLeavesOtherSectionsAlone) {
  const ScannerParameters p =
      read_scanner_config(write("realtime: {anything: [1, 2]}\n"
                                "scanner:\n"
                                "  points_per_profile: 1280\n"
                                "  z_noise_mm: 0.05\n"
                                "  laser_model: parallel\n"
                                "  seed: 18446744073709551615\n"
                                "  camera:\n"
                                "    bit_depth: 12\n"
                                "    stripe_sigma_px: 2.5\n"));
  EXPECT_EQ(p.points_per_profile, 1280);
  EXPECT_EQ(p.z_noise_mm, 0.05);
  EXPECT_EQ(p.laser_model, LaserModel::kParallel);
  EXPECT_EQ(p.seed, 18446744073709551615ULL);
  EXPECT_EQ(p.camera.bit_depth, 12);
  EXPECT_EQ(p.camera.stripe_sigma_px, 2.5);
  EXPECT_EQ(p.triangulation_angle_deg, 30.0);
  // No scanner section at all: the defaults.
  EXPECT_EQ(read_scanner_config(write("other: 1\n")).points_per_profile, 640);
}

TEST_F(ScannerConfig, BadKeysTypesAndRangesNameFileLineAndKey) {
  const std::string file = (dir_ / "cell.yaml").string();
  EXPECT_EQ(error_of("scanner:\n  points_per_profile: 640\n  beam_width: 3\n")
                .rfind(file + ":3: scanner.beam_width: unknown key", 0),
            0u);
  EXPECT_EQ(error_of("scanner:\n  points_per_profile: abc\n"),
            file + ":2: scanner.points_per_profile: expected an integer, got 'abc'");
  EXPECT_EQ(error_of("scanner:\n  z_noise_mm: [1]\n"),
            file + ":2: scanner.z_noise_mm: expected a number, got a list");
  EXPECT_EQ(error_of("scanner:\n\n  triangulation_angle_deg: 90\n"),
            file + ":3: scanner.triangulation_angle_deg: must be in [5, 75], got 90");
  EXPECT_EQ(error_of("scanner:\n  points_per_profile: 0\n"),
            file + ":2: scanner.points_per_profile: must be in [16, 8192], got 0");
  EXPECT_EQ(error_of("scanner:\n  z_noise_mm: .nan\n")
                .rfind(file + ":2: scanner.z_noise_mm: must be in", 0),
            0u);
  EXPECT_EQ(error_of("scanner:\n  laser_model: beam\n"),
            file + ":2: scanner.laser_model: expected fan or parallel, got 'beam'");
  EXPECT_EQ(error_of("scanner:\n  seed: -1\n"),
            file + ":2: scanner.seed: expected a non-negative integer, got '-1'");
  EXPECT_EQ(error_of("scanner:\n  camera:\n    bit_depth: 9\n"),
            file + ":3: scanner.camera.bit_depth: must be 8, 10, 12 or 16, got 9");
  EXPECT_EQ(error_of("scanner:\n  camera:\n    gain: 2\n")
                .rfind(file + ":3: scanner.camera.gain: unknown key", 0),
            0u);
  EXPECT_EQ(error_of("scanner:\n  camera: 3\n"),
            file + ":2: scanner.camera: expected a map, got '3'");
  EXPECT_EQ(error_of("scanner:\n  roi_height_px: 2000\n"),
            file + ":2: scanner.roi_height_px: must not exceed sensor_height_px (1024), got 2000");
  EXPECT_EQ(error_of("scanner:\n  z_noise_mm: 1\n  z_noise_mm: 2\n"),
            file + ":3: scanner.z_noise_mm: key given twice");
  EXPECT_EQ(error_of("scanner: [1, 2]\n"), file + ":1: scanner: expected a map, got a list");
  EXPECT_EQ(error_of("scanner:\n  z_noise_mm: [1\n").rfind(file + ":", 0), 0u);
  EXPECT_EQ(error_of("scanner: {}\n"), "");
}

TEST_F(ScannerConfig, TheFormerBackgroundKeyNamesTheOneThatReplacedIt) {
  // Model views and live scans lose the belt at one threshold, the conditioning's.
  EXPECT_EQ(error_of("scanner:\n  z_noise_mm: 0.02\n  background_height_mm: 0.5\n"),
            (dir_ / "cell.yaml").string() +
                ":3: scanner.background_height_mm: replaced by conditioning.height_threshold_mm");
}

TEST_F(ScannerConfig, MissingFileIsOneLine) {
  try {
    read_scanner_config(dir_ / "absent.yaml");
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()),
              (dir_ / "absent.yaml").string() + ": config file not found");
  }
}

TEST(ScannerParametersCheck, RefusesOutOfRangeFieldsSetInCode) {
  ScannerParameters p;
  EXPECT_NO_THROW(check_scanner_parameters(p));
  p.max_incidence_deg = 95.0;
  EXPECT_THROW(check_scanner_parameters(p), std::invalid_argument);
  const auto message = [](const ScannerParameters& parameters) -> std::string {
    try {
      check_scanner_parameters(parameters);
    } catch (const std::invalid_argument& error) {
      return error.what();
    }
    return "";
  };
  EXPECT_EQ(message(p), "scanner.max_incidence_deg: must be in (0, 90), got 95");
  ScannerParameters camera;
  camera.camera.bit_depth = 9;
  EXPECT_EQ(message(camera), "scanner.camera.bit_depth: must be 8, 10, 12 or 16, got 9");
  ScannerParameters roi;
  roi.roi_height_px = 2000;
  EXPECT_EQ(message(roi),
            "scanner.roi_height_px: must not exceed sensor_height_px (1024), got 2000");
}

}  // namespace
}  // namespace cosmos
