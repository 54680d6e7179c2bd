#include "calibration/belt_calibration.hpp"

#include <gtest/gtest.h>

#include "sim/calibration_targets/calibration_target_simulator.hpp"
#include "tests/calibration/calibration_test_cell.hpp"

namespace cosmos {
namespace {

// The camera and laser plane as calibrated exactly: the belt's own errors are what is tested.
ScannerCalibration calibrated_lens_and_laser(const CalibrationTruth& truth) {
  ScannerCalibration calibration;
  calibration.camera = truth.camera;
  calibration.laser = truth.laser;
  return calibration;
}

TEST(BeltCalibration, RecoversRollHeightAndMillimetresPerTick) {
  const ScannerParameters nominal = test::small_sensor_scanner();
  CalibrationTargetSimulator simulator(nominal, test::mis_mounted_cell(), 7);
  const CalibrationTruth truth = simulator.truth();
  const RampBlock block;
  const BeltCalibrationResult result =
      calibrate_belt(simulator.empty_belt_frames(4), simulator.ramp_frames(block, 40), block,
                     nominal, calibrated_lens_and_laser(truth), simulator.extraction_parameters());
  ASSERT_TRUE(result.ok) << result.reason;
  EXPECT_NEAR(result.roll_deg, truth.roll_deg, 0.05);
  EXPECT_NEAR(result.camera_height_mm, truth.camera_height_mm, 0.05);
  EXPECT_NEAR(result.encoder_mm_per_tick / truth.encoder_mm_per_tick, 1.0, 0.002);
  EXPECT_LT(std::abs(result.belt_height_mm), 0.05);
  EXPECT_LT(std::abs(result.belt_slope_x), 0.05 * std::numbers::pi / 180.0);
  const RigidTransform& T = result.mount.T_scanner_camera;
  EXPECT_LT(rotation_angle_between_rad(T.rotation, truth.T_scanner_camera.rotation) * 180.0 /
                std::numbers::pi,
            0.05);
  EXPECT_LT((T.translation_mm - truth.T_scanner_camera.translation_mm).norm(), 0.2);
}

TEST(BeltCalibration, RefusesARampItCannotSeeWithTheReason) {
  const ScannerParameters nominal = test::small_sensor_scanner();
  CalibrationTargetSimulator simulator(nominal, test::mis_mounted_cell(), 8);
  const CalibrationTruth truth = simulator.truth();
  RampBlock told;  // the file says a taller block than the one scanned
  told.low_height_mm = 60.0;
  told.high_height_mm = 90.0;
  const BeltCalibrationResult result =
      calibrate_belt(simulator.empty_belt_frames(2), simulator.ramp_frames(RampBlock{}, 80), told,
                     nominal, calibrated_lens_and_laser(truth), simulator.extraction_parameters());
  EXPECT_FALSE(result.ok);
  EXPECT_EQ(result.reason,
            "ramp block: 0 frames see its slope (heights 64.5 to 85.5 mm), at least 5 needed: is "
            "it the block of the target file?");
}

}  // namespace
}  // namespace cosmos
