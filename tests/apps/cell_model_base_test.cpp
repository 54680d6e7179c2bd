// The model base a cell runs with (apps/cell_model_base.hpp), on the real binary: a configured
// base whose views were taken with another belt threshold or on another grid is refused in one
// line naming the base, the differing conditioning key and both values; so is a base damaged
// at start (faults.corrupt_model_base).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "tests/apps/cosmos_cli.hpp"
#include "tests/regression_model_base.hpp"

namespace cosmos {
namespace {

namespace fs = std::filesystem;

class CellModelBase : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("cosmos_cell_model_base_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // `cosmos cell` on the regression base with `extra` sections added to its config.
  testing::CliRun run_cell(const std::string& extra) const {
    const fs::path config = dir_ / "cell.yaml";
    std::ofstream(config) << "cell:\n  catalog: " << COSMOS_SOURCE_DIR
                          << "/config/parts-regression.yaml\n  model_base: "
                          << testing::regression_model_base().string() << "\n  model_views: 80\n"
                          << "sim_source:\n  parts: 1\n"
                          << extra;
    return testing::run_cosmos("cell --unpaced --config '" + config.string() + "'", dir_);
  }

  fs::path dir_;
};

TEST_F(CellModelBase, RefusesABaseWhoseViewsLostTheBeltAtAnotherHeight) {
  const testing::CliRun run = run_cell("conditioning:\n  height_threshold_mm: 0.6\n");
  testing::expect_one_line_failure(run, testing::regression_model_base().string() +
                                            ": its views were taken with other conditioning: "
                                            "conditioning.height_threshold_mm is 0.5, " +
                                            (dir_ / "cell.yaml").string() + " gives 0.6");
}

TEST_F(CellModelBase, RefusesABaseWhoseViewsLieOnAnotherGrid) {
  // A belt step of 0.5 mm and a grid to match: the live scans' pitches are 0.5 mm both ways,
  // the base's views 0.4 mm.
  const testing::CliRun run = run_cell(
      "scanner:\n  encoder_ticks_per_profile: 5\nconditioning:\n  grid_mm: 0.5\n"
      "  x_min_mm: -127.75\n  x_max_mm: 128.25\n");
  testing::expect_one_line_failure(
      run, "conditioning.grid_x_mm is 0.4, " + (dir_ / "cell.yaml").string() + " gives 0.5");
}

TEST_F(CellModelBase, RefusesABaseCorruptedAtStartInOneLine) {
  // The injected fault of a damaged base: one payload byte flipped as it is read.
  const testing::CliRun run = run_cell("faults:\n  seed: 5\n  corrupt_model_base: true\n");
  testing::expect_one_line_failure(run, testing::regression_model_base().string() + ": corrupted");
  EXPECT_NE(run.err.find("(faults.corrupt_model_base flipped byte "), std::string::npos) << run.err;
}

}  // namespace
}  // namespace cosmos
