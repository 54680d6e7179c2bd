// `cosmos calibrate` refusing bad input: one line naming the input and the reason, and
// neither the YAML it would update nor the report directory touched.
#include <gtest/gtest.h>

#include <filesystem>
#include <opencv2/imgcodecs.hpp>

#include "sim/calibration_targets/calibration_target_simulator.hpp"
#include "tests/apps/cosmos_cli.hpp"
#include "tests/calibration/calibration_test_cell.hpp"

namespace cosmos {
namespace {

namespace fs = std::filesystem;

class CalibrateCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::path(::testing::TempDir()) /
           ::testing::UnitTest::GetInstance()->current_test_info()->name();
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "images");
    fs::copy_file(fs::path(COSMOS_SOURCE_DIR) / "config" / "hardware-sim.yaml", hardware());
    original_ = testing::read_text(hardware());
  }
  fs::path hardware() const { return dir_ / "hardware.yaml"; }
  testing::CliRun calibrate_camera() const {
    return testing::run_cosmos("calibrate camera --images '" + (dir_ / "images").string() +
                                   "' --hardware '" + hardware().string() + "' --report '" +
                                   (dir_ / "report").string() + "'",
                               dir_);
  }
  void expect_nothing_written() const {
    EXPECT_EQ(testing::read_text(hardware()), original_);
    EXPECT_FALSE(fs::exists(dir_ / "report"));
  }

  fs::path dir_;
  std::string original_;
};

TEST_F(CalibrateCommand, AnImageWithoutTheBoardIsNamedAndNothingIsWritten) {
  const cv::Mat belt(512, 640, CV_8UC1, cv::Scalar(77));
  cv::imwrite((dir_ / "images" / "board-00.png").string(), belt);
  const testing::CliRun run = calibrate_camera();
  testing::expect_one_line_failure(run, "board-00.png: no 9x6 chessboard found (nothing written)");
  expect_nothing_written();
}

TEST_F(CalibrateCommand, TooFewViewsAreRefusedAndNothingIsWritten) {
  CalibrationTargetSimulator simulator(test::small_sensor_scanner(), test::mis_mounted_cell(), 2);
  const std::vector<BoardImage> boards = simulator.board_images(CalibrationBoard{}, 3);
  for (std::size_t i = 0; i < boards.size(); ++i)
    cv::imwrite((dir_ / "images" / ("board-0" + std::to_string(i) + ".png")).string(),
                boards[i].image);
  const testing::CliRun run = calibrate_camera();
  testing::expect_one_line_failure(
      run, "too few views: 3 boards found, at least 10 needed (nothing written)");
  expect_nothing_written();
}

}  // namespace
}  // namespace cosmos
