#include "calibration/cell_frame_calibration.hpp"

#include <gtest/gtest.h>

#include "sim/calibration_targets/calibration_target_simulator.hpp"
#include "tests/calibration/calibration_test_cell.hpp"

namespace cosmos {
namespace {

struct CellScan {
  SpherePlateScan scan;
  CalibrationTruth truth;
  TriangulationGeometry geometry;  // the true one, as a perfect belt calibration gives it
  StripeExtractionParameters extraction;
};

CellScan scan_sphere_plate(std::uint64_t seed) {
  const ScannerParameters nominal = test::small_sensor_scanner();
  CalibrationTargetSimulator simulator(nominal, test::mis_mounted_cell(), seed);
  return {simulator.sphere_plate_scan(8), simulator.truth(), simulator.true_geometry(),
          simulator.extraction_parameters()};
}

TEST(CellFrameCalibration, RecoversTCellScannerFromFourSpheres) {
  const CellScan cell = scan_sphere_plate(9);
  const CellFrameResult result = calibrate_cell_frame(cell.scan.frames, cell.scan.plate,
                                                      cell.geometry, cell.truth.encoder_mm_per_tick,
                                                      cell.truth.sheet_pitch_deg, cell.extraction);
  ASSERT_TRUE(result.ok) << result.reason;
  EXPECT_LT(rotation_angle_between_rad(result.T_cell_scanner.rotation,
                                       cell.truth.T_cell_scanner.rotation) *
                180.0 / std::numbers::pi,
            0.1);
  EXPECT_LT(
      (result.T_cell_scanner.translation_mm - cell.truth.T_cell_scanner.translation_mm).norm(),
      0.2);
  ASSERT_EQ(result.feature_residual_mm.size(), 4u);
  for (double residual : result.feature_residual_mm) EXPECT_LT(residual, 0.2);
}

TEST(CellFrameCalibration, RefusesATargetFileWithAnotherSphereCount) {
  CellScan cell = scan_sphere_plate(10);
  cell.scan.plate.centres_cell_mm.pop_back();
  const CellFrameResult result = calibrate_cell_frame(cell.scan.frames, cell.scan.plate,
                                                      cell.geometry, cell.truth.encoder_mm_per_tick,
                                                      cell.truth.sheet_pitch_deg, cell.extraction);
  EXPECT_FALSE(result.ok);
  EXPECT_EQ(result.reason,
            "the scan shows 4 spheres, the target file lists 3: the file does not match the scan");
}

TEST(CellFrameCalibration, RefusesATargetFileWhoseCentresDoNotFitTheScan) {
  CellScan cell = scan_sphere_plate(11);
  cell.scan.plate.centres_cell_mm[2] += Eigen::Vector3d(15.0, 0.0, 0.0);
  const CellFrameResult result = calibrate_cell_frame(cell.scan.frames, cell.scan.plate,
                                                      cell.geometry, cell.truth.encoder_mm_per_tick,
                                                      cell.truth.sheet_pitch_deg, cell.extraction);
  EXPECT_FALSE(result.ok);
  EXPECT_NE(result.reason.find("the target file does not match the scan"), std::string::npos)
      << result.reason;
}

}  // namespace
}  // namespace cosmos
