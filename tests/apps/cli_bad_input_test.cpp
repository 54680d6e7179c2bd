// The CLI contract on bad input, checked on the real `cosmos` binary: every bad file or option
// ends in a non-zero exit (not a crash), exactly one line on stderr, naming the file or option.
// Also: `synth` writes files that load back bit-identical to the library's surface.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>

#include "core/io/range_image_file.hpp"
#include "sim/analytic_surface.hpp"
#include "tests/apps/cosmos_cli.hpp"
#include "tests/sim/handmade_image_files.hpp"

namespace cosmos {
namespace {

namespace fs = std::filesystem;
using testing::CliRun;
using testing::read_text;
using testing::run_cosmos;
using testing::TiffSampleFormat;

class CliBadInput : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("cosmos_cli_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path file(const std::string& name) const { return dir_ / name; }

  CliRun run(const std::string& args) const { return run_cosmos(args, dir_); }

  void expect_one_line_failure(const std::string& args, const std::string& needle) const {
    SCOPED_TRACE("cosmos " + args);
    testing::expect_one_line_failure(run(args), needle);
  }

  void expect_inspect_rejects(const fs::path& range, const std::string& needle) const {
    expect_one_line_failure(
        "inspect '" + range.string() + "' --out '" + file("inspect_out").string() + "'", needle);
  }

  void write_valid_range(const fs::path& path) const {
    AnalyticSurfaceSpec spec;
    spec.radius_mm = 5.0;
    write_range_image(make_analytic_surface(spec).range, path);
  }

  fs::path dir_;
};

TEST_F(CliBadInput, InspectRejectsMissingAndUnknownFiles) {
  expect_inspect_rejects(file("absent.tiff"), "absent.tiff");
  testing::write_text_file(file("photo.png"), "\x89PNG\r\n\x1a\n");
  expect_inspect_rejects(file("photo.png"), "photo.png");
  testing::write_text_file(file("garbage.tiff"), "not a tiff");
  testing::write_text_file(file("garbage.yaml"), "pixel_size_mm: [1, 1]\n");
  expect_inspect_rejects(file("garbage.tiff"), "garbage.tiff");
}

TEST_F(CliBadInput, InspectRejectsWrongPixelTypes) {
  const std::string sidecar = "pixel_size_mm: [0.5, 0.5]\n";
  testing::write_handmade_tiff(file("rgb8.tiff"), 8, 6, 8, 3, TiffSampleFormat::kUnsigned);
  testing::write_text_file(file("rgb8.yaml"), sidecar);
  expect_inspect_rejects(file("rgb8.tiff"), "rgb8.tiff");
  testing::write_handmade_pfm(file("rgb.pfm"), 8, 6, 3, 1.0f);
  testing::write_text_file(file("rgb.yaml"), sidecar);
  expect_inspect_rejects(file("rgb.pfm"), "rgb.pfm");
  testing::write_handmade_tiff(file("gray8.tiff"), 8, 6, 8, 1, TiffSampleFormat::kUnsigned);
  testing::write_text_file(file("gray8.yaml"), sidecar);
  expect_inspect_rejects(file("gray8.tiff"), "gray8.tiff");
  testing::write_handmade_tiff(file("gray16.tif"), 8, 6, 16, 1, TiffSampleFormat::kUnsigned);
  testing::write_text_file(file("gray16.yaml"), sidecar);
  expect_inspect_rejects(file("gray16.tif"), "gray16.tif");
}

TEST_F(CliBadInput, InspectRejectsAllNaNAndInfinity) {
  write_range_image(RangeImage(8, 6, 0.5, 0.5), file("blank.tiff"));
  expect_inspect_rejects(file("blank.tiff"), "blank.tiff");
  RangeImage image(8, 6, 0.5, 0.5);
  image.z_mm(2, 2) = 1.0f;
  image.z_mm(3, 2) = std::numeric_limits<float>::infinity();
  write_range_image(image, file("inf.pfm"));
  expect_inspect_rejects(file("inf.pfm"), "inf.pfm");
}

TEST_F(CliBadInput, InspectRejectsBadSidecars) {
  write_valid_range(file("lonely.tiff"));
  fs::remove(file("lonely.yaml"));
  expect_inspect_rejects(file("lonely.tiff"), "lonely");
  write_valid_range(file("nosize.tiff"));
  testing::write_text_file(file("nosize.yaml"), "origin_mm: [0, 0]\n");
  expect_inspect_rejects(file("nosize.tiff"), "nosize.yaml");
  write_valid_range(file("broken.tiff"));
  testing::write_text_file(file("broken.yaml"), "pixel_size_mm: [0.5, 0.5\nfoo: : :\n");
  expect_inspect_rejects(file("broken.tiff"), "broken.yaml");
  write_valid_range(file("negative.tiff"));
  testing::write_text_file(file("negative.yaml"), "pixel_size_mm: [-0.5, 0.5]\n");
  expect_inspect_rejects(file("negative.tiff"), "negative.yaml:1: pixel_size_mm");
}

TEST_F(CliBadInput, SynthRejectsBadShapesAndFiles) {
  const std::string out = " --out '" + file("x.tiff").string() + "'";
  expect_one_line_failure("synth blob" + out, "blob");
  expect_one_line_failure("synth" + out, "SHAPE");
  expect_one_line_failure("synth sphere", "--out");
  expect_one_line_failure("synth sphere --out '" + file("x.png").string() + "'", "x.png");
  expect_one_line_failure("synth sphere --out '" + (dir_ / "no_dir" / "y.tiff").string() + "'",
                          "y.tiff");
  EXPECT_FALSE(fs::exists(file("x.tiff")));
}

TEST_F(CliBadInput, SynthRejectsBadNumbers) {
  const std::string base = "synth sphere --out '" + file("x.tiff").string() + "' ";
  expect_one_line_failure(base + "--radius-mm -1", "--radius-mm");
  expect_one_line_failure(base + "--radius-mm abc", "--radius-mm");
  expect_one_line_failure(base + "--radius-mm 3mm", "--radius-mm");
  expect_one_line_failure(base + "--pixel-mm 0", "--pixel-mm");
  expect_one_line_failure(base + "--pixel-mm nan", "--pixel-mm");
  expect_one_line_failure(base + "--noise-mm -0.5", "--noise-mm");
  expect_one_line_failure(base + "--seed -3", "--seed");
  expect_one_line_failure(base + "--rotate-deg inf", "--rotate-deg");
  expect_one_line_failure(base + "--pixel-mm 0.00001", "pixel");  // a 5-gigapixel grid
  EXPECT_FALSE(fs::exists(file("x.tiff")));
}

TEST_F(CliBadInput, SynthSphereLoadsBack) {
  const CliRun result = run("synth sphere --out '" + file("sphere.tiff").string() + "'");
  ASSERT_TRUE(result.exited);
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_TRUE(result.err.empty()) << result.err;
  const RangeImage image = read_range_image(file("sphere.tiff"));
  const AnalyticSurface expected = make_analytic_surface(AnalyticSurfaceSpec{});
  ASSERT_EQ(image.width(), expected.range.width());
  ASSERT_EQ(image.height(), expected.range.height());
  EXPECT_EQ(
      std::memcmp(image.z_mm.data(), expected.range.z_mm.data(), image.z_mm.size() * sizeof(float)),
      0);
  EXPECT_EQ(image.pixel_size_x_mm, 0.5);
  EXPECT_EQ(image.origin_x_mm, expected.range.origin_x_mm);
  ASSERT_TRUE(image.ground_truth.has_value());
  EXPECT_EQ(image.ground_truth->part, "sphere");
}

TEST_F(CliBadInput, SynthOptionsReachTheSurface) {
  const CliRun result =
      run("synth box-corner --out '" + file("corner.pfm").string() +
          "' --radius-mm 10 --pixel-mm 0.25 --noise-mm 0.1 --seed 5 --rotate-deg -30");
  ASSERT_TRUE(result.exited);
  ASSERT_EQ(result.exit_code, 0) << result.err;
  AnalyticSurfaceSpec spec;
  spec.shape = AnalyticShape::kBoxCorner;
  spec.radius_mm = 10;
  spec.pixel_size_mm = 0.25;
  spec.noise_mm = 0.1;
  spec.seed = 5;
  spec.rotate_deg = -30;
  const AnalyticSurface expected = make_analytic_surface(spec);
  const RangeImage image = read_range_image(file("corner.pfm"));
  ASSERT_EQ(image.width(), expected.range.width());
  ASSERT_EQ(image.height(), expected.range.height());
  EXPECT_EQ(
      std::memcmp(image.z_mm.data(), expected.range.z_mm.data(), image.z_mm.size() * sizeof(float)),
      0);
  EXPECT_EQ(image.pixel_size_y_mm, 0.25);
  ASSERT_TRUE(image.ground_truth.has_value());
  EXPECT_EQ(image.ground_truth->part, "box-corner");
  EXPECT_EQ(image.ground_truth->rotation, expected.range.ground_truth->rotation);
}

// The option sets sim_source.parts and is checked against its declared range before the
// config is read: 0 and -3 used to run the config's parts.
// Numeric options are held to the ranges of the parameters they set: a huge
// --smoothing-iterations ran for minutes.
TEST_F(CliBadInput, InspectOptionsAreHeldToTheParametersRanges) {
  write_valid_range(file("ok.tiff"));
  const std::string base =
      "inspect '" + file("ok.tiff").string() + "' --out '" + file("out").string() + "' ";
  expect_one_line_failure(base + "--smoothing-iterations 100000000",
                          "--smoothing-iterations: cosmos.smoothing.iterations must be in [0, "
                          "1000], got 100000000");
  expect_one_line_failure(base + "--smoothing-iterations -2",
                          "--smoothing-iterations: cosmos.smoothing.iterations must be in");
  expect_one_line_failure(base + "--max-patches -1",
                          "--max-patches: cosmos.segmentation.max_patches must be in [0, 10000]");
  expect_one_line_failure(base + "--max-patches 2.5", "--max-patches: '2.5' is not a whole number");
  EXPECT_FALSE(fs::exists(file("out")));
}

TEST_F(CliBadInput, EvalOptionsAreRangeChecked) {
  const std::string base = "eval --modelbase '" + file("absent.cmb").string() + "' --out '" +
                           file("eval").string() + "' ";
  expect_one_line_failure(base + "--threads 0", "--threads: must be in [1, 1024], got 0");
  expect_one_line_failure(base + "--threads 1000000000", "--threads: must be in [1, 1024]");
  expect_one_line_failure(base + "--tests 0", "--tests: must be in [1, 1000000], got 0");
  expect_one_line_failure(base + "--noise-mm 1e6", "--noise-mm: scanner.z_noise_mm must be in");
}

// A damaged image whose decoder throws inside OpenCV: imread printed its own line on stderr
// before the reader's.
TEST_F(CliBadInput, DamagedImagesGiveOnlyTheReadersLine) {
  write_valid_range(file("cut.tiff"));
  const std::string tiff = read_text(file("cut.tiff"));
  testing::write_text_file(file("cut.tiff"), tiff.substr(0, tiff.size() / 2));
  expect_inspect_rejects(file("cut.tiff"), "cut.tiff");
  testing::write_text_file(file("header.tiff"), tiff.substr(0, 12));
  fs::copy_file(file("cut.yaml"), file("header.yaml"));
  expect_inspect_rejects(file("header.tiff"), "header.tiff");
  testing::write_text_file(file("huge.pfm"), "Pf\n100000 100000\n-1.0\n0000");
  fs::copy_file(file("cut.yaml"), file("huge.yaml"));
  expect_inspect_rejects(file("huge.pfm"), "huge.pfm");
  testing::write_text_file(file("short.pfm"), "Pf\n8 6\n-1.0\n0000");
  fs::copy_file(file("cut.yaml"), file("short.yaml"));
  expect_inspect_rejects(file("short.pfm"), "short.pfm");
}

TEST_F(CliBadInput, CellRejectsAPartCountOutOfRange) {
  expect_one_line_failure("cell --parts 0 --config '" + file("absent.yaml").string() + "'",
                          "--parts: sim_source.parts must be in [1, 1000000], got 0");
  expect_one_line_failure("cell --parts -3 --config '" + file("absent.yaml").string() + "'",
                          "--parts: sim_source.parts must be in [1, 1000000], got -3");
  expect_one_line_failure("cell --parts many --config '" + file("absent.yaml").string() + "'",
                          "--parts");
}

}  // namespace
}  // namespace cosmos
