// `cosmos sim scan` and `cosmos sim views` on the real binary: every bad input ends in a
// non-zero exit (never a crash) with one line naming the file or option and the reason; good
// input writes range images with ground truth, the same bytes for the same seed.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "core/io/range_image_file.hpp"
#include "tests/apps/cosmos_cli.hpp"

namespace cosmos {
namespace {

namespace fs = std::filesystem;
using testing::CliRun;
using testing::read_text;
using testing::run_cosmos;

// A 40 x 30 x 20 box as OFF quads.
constexpr const char* kBoxOff =
    "OFF\n8 6 0\n"
    "0 0 0\n40 0 0\n40 30 0\n0 30 0\n0 0 20\n40 0 20\n40 30 20\n0 30 20\n"
    "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n";

class SimCli : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("cosmos_sim_cli_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    write("box.off", kBoxOff);
    write("catalog.yaml", "parts:\n  - {name: box, mesh: ./box.off, size_mm: 40}\n");
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string file(const std::string& name) const { return (dir_ / name).string(); }
  void write(const std::string& name, const std::string& text) const {
    std::ofstream(dir_ / name) << text;
  }

  CliRun run(const std::string& args) const { return run_cosmos(args, dir_); }

  void expect_one_line_failure(const std::string& args, const std::string& needle) const {
    SCOPED_TRACE("cosmos " + args);
    testing::expect_one_line_failure(run(args), needle);
  }

  std::string scan_mesh(const std::string& mesh, const std::string& size = "40") const {
    return "sim scan --mesh '" + file(mesh) + "' --size-mm " + size + " --out '" +
           file("out.tiff") + "'";
  }

  fs::path dir_;
};

TEST_F(SimCli, CatalogListShowsEveryPartAndWhetherItLoads) {
  const CliRun listed = run("catalog list --catalog '" + file("catalog.yaml") + "'");
  EXPECT_EQ(listed.exit_code, 0) << listed.err;
  EXPECT_NE(listed.out.find("name"), std::string::npos) << listed.out;
  // The box: 8 vertices, its 6 quads as 12 triangles, sized 40 mm, loading.
  EXPECT_NE(listed.out.find("box"), std::string::npos) << listed.out;
  EXPECT_NE(listed.out.find("40         8     12  ok"), std::string::npos) << listed.out;

  write("with-missing.yaml",
        "parts:\n  - {name: box, mesh: ./box.off, size_mm: 40}\n"
        "  - {name: ghost, mesh: ./missing.off, size_mm: 50}\n");
  const CliRun failing = run("catalog list --catalog '" + file("with-missing.yaml") + "'");
  EXPECT_NE(failing.out.find("ghost"), std::string::npos) << failing.out;
  EXPECT_NE(failing.out.find("FAILS: " + file("missing.off") + ": mesh file not found"),
            std::string::npos)
      << failing.out;
  testing::expect_one_line_failure(failing, "1 of 2 parts do not load");
}

TEST_F(SimCli, BadMeshesNameTheFileAndTheReason) {
  expect_one_line_failure(scan_mesh("absent.off"), "absent.off: mesh file not found");
  write("empty.off", "OFF\n0 0 0\n");
  expect_one_line_failure(scan_mesh("empty.off"), "empty.off");
  write("nan.off", "OFF\n3 1 0\n0 0 0\n1 0 0\nnan 1 0\n3 0 1 2\n");
  expect_one_line_failure(scan_mesh("nan.off"), "nan.off:5: vertex 2 (nan, 1, 0) has a NaN");
  write("part.xyz", kBoxOff);
  expect_one_line_failure(scan_mesh("part.xyz"), "part.xyz: unknown mesh extension");
  expect_one_line_failure(scan_mesh("box.off", "0"), "--size-mm: must be in (0, 5000], got 0");
  expect_one_line_failure(scan_mesh("box.off", "abc"), "--size-mm: 'abc' is not a number");
  EXPECT_FALSE(fs::exists(file("out.tiff")));
}

TEST_F(SimCli, BadPartsConfigsAndOptionsAreOneLine) {
  const std::string out = " --out '" + file("out.tiff") + "'";
  const std::string catalog = " --catalog '" + file("catalog.yaml") + "'";
  expect_one_line_failure("sim scan --part nosuch" + catalog + out, "unknown part 'nosuch'");
  write("cell.yaml", "scanner:\n  beam_width: 3\n");
  expect_one_line_failure(
      "sim scan --part box" + catalog + out + " --config '" + file("cell.yaml") + "'",
      "cell.yaml:2: scanner.beam_width: unknown key");
  write("range.yaml", "scanner:\n  points_per_profile: 5\n");
  expect_one_line_failure(
      "sim scan --part box" + catalog + out + " --config '" + file("range.yaml") + "'",
      "range.yaml:2: scanner.points_per_profile: must be in");
  expect_one_line_failure("sim scan --part box" + catalog + " --out '" + file("out.png") + "'",
                          "out.png");
  expect_one_line_failure("sim scan --part box" + catalog + " --out '" + file("no/dir.tiff") + "'",
                          "dir.tiff");
  expect_one_line_failure("sim scan --part box" + catalog, "--out");
  expect_one_line_failure("sim scan" + out, "--part");
  expect_one_line_failure("sim scan --part box" + catalog + out + " --mode laser",
                          "--mode 'laser'");
  expect_one_line_failure("sim scan --part box" + catalog + out + " --frames '" + file("f") + "'",
                          "--frames");
  expect_one_line_failure("sim scan --part box" + catalog + out + " --rotation-deg 1 2",
                          "--rotation-deg");
  expect_one_line_failure("sim scan --part box" + catalog + out + " --rotation-deg 1 x 2",
                          "--rotation-deg 'x'");
  expect_one_line_failure("sim scan --part box" + catalog + out + " --resting --random-pose",
                          "one of");
  expect_one_line_failure("sim scan --part box" + catalog + out + " --seed -1", "--seed '-1'");
  expect_one_line_failure("sim scan --part box" + catalog + out + " --noise-mm -1",
                          "--noise-mm: scanner.z_noise_mm must be in [0, 10], got -1");
  expect_one_line_failure("sim scan --part box" + catalog + out + " --noise-mm 50",
                          "--noise-mm: scanner.z_noise_mm must be in [0, 10], got 50");
  // 1e9 mm asked the scan for an unbounded range image (std::bad_alloc).
  expect_one_line_failure("sim scan --mesh '" + file("box.off") + "' --size-mm 1e9" + out,
                          "--size-mm: must be in (0, 5000], got 1e9");
  expect_one_line_failure("sim scan --mesh '" + file("box.off") + "' --size-mm 0" + out,
                          "--size-mm: must be in (0, 5000], got 0");
  expect_one_line_failure("sim views --part box" + catalog + " --out '" + file("v") + "' --count 0",
                          "--count '0'");
  expect_one_line_failure("sim views --part nosuch" + catalog + " --out '" + file("v") + "'",
                          "unknown part 'nosuch'");
  EXPECT_FALSE(fs::exists(file("out.tiff")));
}

TEST_F(SimCli, ScanWritesGroundTruthAndRepeatsByteForByte) {
  const std::string args =
      "sim scan --part box --catalog '" + file("catalog.yaml") + "' --random-pose --seed 4";
  for (const char* name : {"a.tiff", "b.tiff"}) {
    const CliRun result = run(args + " --out '" + file(name) + "'");
    ASSERT_TRUE(result.exited);
    ASSERT_EQ(result.exit_code, 0) << result.err;
  }
  EXPECT_EQ(read_text(file("a.tiff")), read_text(file("b.tiff")));
  EXPECT_EQ(read_text(file("a.yaml")), read_text(file("b.yaml")));
  const RangeImage image = read_range_image(file("a.tiff"));
  EXPECT_GT(image.count_valid(), 1000u);
  ASSERT_TRUE(image.ground_truth.has_value());
  EXPECT_EQ(image.ground_truth->part, "box");
  EXPECT_EQ(image.pixel_size_x_mm, 0.4);
  EXPECT_EQ(image.pixel_size_y_mm, 0.4);
}

TEST_F(SimCli, CameraModeDumpsFramesAndViewsWriteTheirPoses) {
  const std::string catalog = " --catalog '" + file("catalog.yaml") + "'";
  // A smaller sensor keeps the PNG writing short.
  write("small.yaml", "scanner:\n  sensor_width_px: 640\n  roi_height_px: 256\n");
  const CliRun scan =
      run("sim scan --part box" + catalog + " --resting --mode camera --frames '" + file("frames") +
          "' --config '" + file("small.yaml") + "' --out '" + file("camera.pfm") + "'");
  ASSERT_EQ(scan.exit_code, 0) << scan.err;
  EXPECT_GT(read_range_image(file("camera.pfm")).count_valid(), 1000u);
  EXPECT_TRUE(fs::exists(dir_ / "frames" / "frame_000010.png"));

  const CliRun views =
      run("sim views --part box" + catalog + " --count 3 --out '" + file("views") + "'");
  ASSERT_EQ(views.exit_code, 0) << views.err;
  for (const char* stem : {"view_000", "view_001", "view_002"}) {
    EXPECT_TRUE(fs::exists(dir_ / "views" / (std::string(stem) + ".tiff"))) << stem;
    EXPECT_NE(
        read_text(dir_ / "views" / (std::string(stem) + ".view.yaml")).find("direction_part: ["),
        std::string::npos);
  }
  EXPECT_FALSE(fs::exists(dir_ / "views" / "view_003.tiff"));
  const RangeImage view = read_range_image(dir_ / "views" / "view_001.tiff");
  ASSERT_TRUE(view.ground_truth.has_value());
}

}  // namespace
}  // namespace cosmos
