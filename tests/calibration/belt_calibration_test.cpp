#include "calibration/belt_calibration.hpp"

#include <gtest/gtest.h>

#include <iostream>

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

TEST(BeltCalibration, RecoversRollHeightPitchAndMillimetresPerTick) {
  const ScannerParameters nominal = test::small_sensor_scanner();
  CalibrationTargetSimulator simulator(nominal, test::mis_mounted_cell(), 7);
  const CalibrationTruth truth = simulator.truth();
  const RampBlock block;
  const BeltCalibrationResult result =
      calibrate_belt(simulator.empty_belt_frames(4), simulator.ramp_frames(block, 40),
                     simulator.ramp_frames(block, 40, RampPlacement::kHighEndUpstream), block,
                     nominal, calibrated_lens_and_laser(truth), simulator.extraction_parameters());
  ASSERT_TRUE(result.ok) << result.reason;
  EXPECT_NEAR(result.roll_deg, truth.roll_deg, 0.05);
  EXPECT_NEAR(result.camera_height_mm, truth.camera_height_mm, 0.05);
  EXPECT_NEAR(result.encoder_mm_per_tick / truth.encoder_mm_per_tick, 1.0, 0.002);
  ASSERT_TRUE(result.pitch_measured);
  EXPECT_NEAR(result.sheet_pitch_deg, truth.sheet_pitch_deg, 0.05);
  EXPECT_LT(std::abs(result.belt_height_mm), 0.05);
  EXPECT_LT(std::abs(result.belt_slope_x), 0.05 * std::numbers::pi / 180.0);
  const RigidTransform& T = result.mount.T_scanner_camera;
  EXPECT_LT(rotation_angle_between_rad(T.rotation, truth.T_scanner_camera.rotation) * 180.0 /
                std::numbers::pi,
            0.05);
  EXPECT_LT((T.translation_mm - truth.T_scanner_camera.translation_mm).norm(), 0.2);
}

TEST(BeltCalibration, OneRampScanCannotTellAPitchedSheetFromTheEncoderScale) {
  const ScannerParameters nominal = test::small_sensor_scanner();
  SimulatedMounting pitched = test::mis_mounted_cell();
  pitched.sheet_pitch_deg = 2.0;
  CalibrationTargetSimulator simulator(nominal, pitched, 12);
  const CalibrationTruth truth = simulator.truth();
  const RampBlock block;
  const std::vector<StripeFrame> belt = simulator.empty_belt_frames(4);
  const std::vector<StripeFrame> drawn = simulator.ramp_frames(block, 40);
  const std::vector<StripeFrame> turned =
      simulator.ramp_frames(block, 40, RampPlacement::kHighEndUpstream);
  const ScannerCalibration lens = calibrated_lens_and_laser(truth);
  const StripeExtractionParameters extraction = simulator.extraction_parameters();
  // Alone, either scan takes the sheet as upright and puts its lean into the encoder: the
  // drawn block's slope falls towards the leaning sheet, the turned one's away from it.
  const BeltCalibrationResult drawn_only =
      calibrate_belt(belt, drawn, {}, block, nominal, lens, extraction);
  const BeltCalibrationResult turned_only =
      calibrate_belt(belt, turned, {}, block, nominal, lens, extraction);
  ASSERT_TRUE(drawn_only.ok && turned_only.ok) << drawn_only.reason << turned_only.reason;
  EXPECT_FALSE(drawn_only.pitch_measured);
  EXPECT_GT(drawn_only.encoder_mm_per_tick / truth.encoder_mm_per_tick, 1.004);
  EXPECT_LT(turned_only.encoder_mm_per_tick / truth.encoder_mm_per_tick, 0.996);
  const BeltCalibrationResult both =
      calibrate_belt(belt, turned, drawn, block, nominal, lens, extraction);
  ASSERT_TRUE(both.ok) << both.reason;
  std::cout << "[ pitch 2 deg ] measured " << both.sheet_pitch_deg << " deg, mm per tick "
            << both.encoder_mm_per_tick << " (true " << truth.encoder_mm_per_tick
            << "); one scan: " << drawn_only.encoder_mm_per_tick << " and "
            << turned_only.encoder_mm_per_tick << "\n";
  EXPECT_NEAR(both.sheet_pitch_deg, 2.0, 0.05);
  EXPECT_NEAR(both.encoder_mm_per_tick / truth.encoder_mm_per_tick, 1.0, 0.002);
}

TEST(BeltCalibration, RefusesASecondScanOfTheBlockTheSameWayRound) {
  const ScannerParameters nominal = test::small_sensor_scanner();
  CalibrationTargetSimulator simulator(nominal, test::mis_mounted_cell(), 13);
  const RampBlock block;
  const BeltCalibrationResult result = calibrate_belt(
      simulator.empty_belt_frames(2), simulator.ramp_frames(block, 80),
      simulator.ramp_frames(block, 80), block, nominal,
      calibrated_lens_and_laser(simulator.truth()), simulator.extraction_parameters());
  EXPECT_FALSE(result.ok);
  EXPECT_EQ(result.reason,
            "ramp block: both scans' heights change the same way with the encoder: turn the "
            "block round for the second scan");
}

TEST(BeltCalibration, RefusesARampItCannotSeeWithTheReason) {
  const ScannerParameters nominal = test::small_sensor_scanner();
  CalibrationTargetSimulator simulator(nominal, test::mis_mounted_cell(), 8);
  const CalibrationTruth truth = simulator.truth();
  RampBlock told;  // the file says a taller block than the one scanned
  told.low_height_mm = 60.0;
  told.high_height_mm = 90.0;
  const BeltCalibrationResult result = calibrate_belt(
      simulator.empty_belt_frames(2), simulator.ramp_frames(RampBlock{}, 80), {}, told, nominal,
      calibrated_lens_and_laser(truth), simulator.extraction_parameters());
  EXPECT_FALSE(result.ok);
  EXPECT_EQ(result.reason,
            "ramp block: 0 frames see its slope (heights 64.5 to 85.5 mm), at least 5 needed: is "
            "it the block of the target file?");
}

}  // namespace
}  // namespace cosmos
