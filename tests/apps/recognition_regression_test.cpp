// The recognition regression suite (ch. 5-6 on simulated scans with known ground truth): the
// small catalog's model base (5 parts x 80 views), 100 seeded random-pose test scans plus
// scans of a part the base does not hold, through the real `cosmos eval` and `cosmos
// recognize` binaries; and every way a model base or a scan can be bad.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/apps/cosmos_cli.hpp"
#include "tests/regression_model_base.hpp"

namespace cosmos::testing {
namespace {

namespace fs = std::filesystem;

class RecognitionRegression : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = fs::temp_directory_path() / ("cosmos-recognition-" + std::to_string(::getpid()));
    fs::create_directories(dir_);
    base_ = regression_model_base();
  }

  // The eval ctest runs once before the suite (tests/CMakeLists.txt, run_regression_eval);
  // run on its own, the binary runs it here when its metrics are missing.
  static const nlohmann::json& metrics() {
    static const nlohmann::json parsed = [] {
      const fs::path metrics_file = eval_dir() / "metrics.json";
      if (!fs::exists(metrics_file)) {
        const CliRun run = run_cosmos(
            "eval --modelbase '" + base_.string() + "' --catalog '" +
                std::string(COSMOS_SOURCE_DIR) +
                "/config/parts.yaml' --tests 100 --seed 11 --unknown bunny --threads 2 --out '" +
                eval_dir().string() + "'",
            dir_);
        EXPECT_EQ(run.exit_code, 0) << run.err;
      }
      return nlohmann::json::parse(read_text(metrics_file), nullptr, false);
    }();
    return parsed;
  }
  static fs::path eval_dir() { return COSMOS_REGRESSION_EVAL_DIR; }
  static void TearDownTestSuite() { fs::remove_all(dir_); }

  // Scans `part` with `cosmos sim scan` into the suite's directory.
  static fs::path scan(const std::string& part, int seed) {
    const fs::path image = dir_ / (part + "-" + std::to_string(seed) + ".tif");
    const CliRun run = run_cosmos("sim scan --part " + part + " --random-pose --seed " +
                                      std::to_string(seed) + " --out '" + image.string() + "'",
                                  dir_);
    EXPECT_EQ(run.exit_code, 0) << run.err;
    return image;
  }

  static nlohmann::json recognize(const fs::path& image) {
    const CliRun run = run_cosmos(
        "recognize --json --modelbase '" + base_.string() + "' '" + image.string() + "'", dir_);
    EXPECT_EQ(run.exit_code, 0) << run.err;
    return nlohmann::json::parse(run.out, nullptr, false);
  }

  static inline fs::path dir_, base_;
};

TEST_F(RecognitionRegression, IdentifiesAtLeast95PercentOf100Scans) {
  const nlohmann::json& m = metrics();
  ASSERT_TRUE(m.is_object());
  EXPECT_EQ(m["tests"], 100);
  EXPECT_GE(m["identification_rate"].get<double>(), 0.95);
  EXPECT_GE(m["add_s_recall_10pct"].get<double>(), 0.93);
  EXPECT_LE(m["false_reject_rate"].get<double>(), 0.05);
  // Correct identifications of the asymmetric parts come with an accurate pose.
  EXPECT_LE(m["rotation_error_deg"]["median"].get<double>(), 1.0);
  EXPECT_LE(m["translation_error_mm"]["median"].get<double>(), 1.0);
}

TEST_F(RecognitionRegression, RejectsThePartTheBaseDoesNotHold) {
  const nlohmann::json& m = metrics();
  ASSERT_TRUE(m.is_object());
  EXPECT_GE(m["unknown_reject_rate"].get<double>(), 0.9);
}

TEST_F(RecognitionRegression, ReportHasItsFilesAndStableKeys) {
  const nlohmann::json& m = metrics();
  for (const char* file : {"metrics.json", "report.html", "confusion_matrix.png",
                           "cluster_rate.png", "rotation_error_cdf.png"})
    EXPECT_TRUE(fs::exists(eval_dir() / file)) << file;
  for (const char* key :
       {"tests", "identification_rate", "spectral_cluster_hit_rate", "spectral_view_selection_rate",
        "fraction_db_examined", "rotation_error_deg", "translation_error_mm", "add_s_recall_10pct",
        "add_s_recall_2pct", "unknown_reject_rate", "false_reject_rate", "recognition_ms",
        "size_variants"})
    EXPECT_TRUE(m.contains(key)) << key;
  for (const char* k : {"1", "2", "5", "10"})
    EXPECT_TRUE(m["spectral_cluster_hit_rate"].contains(k)) << k;
}

TEST_F(RecognitionRegression, RecognizeJsonGivesPartPoseAndCandidates) {
  const fs::path image = scan("cow", 4242);
  const nlohmann::json result = recognize(image);
  ASSERT_TRUE(result.is_object());
  EXPECT_EQ(result["status"], "ok") << result.dump();
  EXPECT_EQ(result["part"], "cow");
  for (const char* key :
       {"reason", "view", "score", "spectral_distance", "registration_rms_mm", "inlier_fraction",
        "rotation", "translation_mm", "timings_ms", "candidates"})
    EXPECT_TRUE(result.contains(key)) << key;
  EXPECT_EQ(result["rotation"].size(), 3u);
  EXPECT_EQ(result["translation_mm"].size(), 3u);
  EXPECT_GE(result["candidates"].size(), 1u);
  // The pose against the scan's ground truth (its sidecar): well within a millimetre.
  const std::string sidecar = read_text(fs::path(image).replace_extension(".yaml"));
  EXPECT_NE(sidecar.find("part: cow"), std::string::npos);
  EXPECT_LT(result["registration_rms_mm"].get<double>(), 0.05);
}

TEST_F(RecognitionRegression, UnknownPartIsRejectedWithAReason) {
  const nlohmann::json result = recognize(scan("bunny", 77));
  ASSERT_TRUE(result.is_object());
  EXPECT_EQ(result["status"], "rejected");
  EXPECT_TRUE(result["part"].is_null());
  EXPECT_FALSE(result["reason"].get<std::string>().empty());
}

TEST_F(RecognitionRegression, ScanWithNoObjectIsRejectedWithAReason) {
  // A flat patch of belt-height noise with a single valid speck: nothing to fit or register.
  const fs::path image = dir_ / "speck.pfm";
  {
    std::ofstream pfm(image, std::ios::binary);
    pfm << "Pf\n8 8\n-1.0\n";
    for (int i = 0; i < 64; ++i) {
      const float z = i == 27 ? 5.0f : std::numeric_limits<float>::quiet_NaN();
      pfm.write(reinterpret_cast<const char*>(&z), sizeof z);
    }
    std::ofstream(fs::path(image).replace_extension(".yaml")) << "pixel_size_mm: [0.4, 0.4]\n";
  }
  const nlohmann::json result = recognize(image);
  ASSERT_TRUE(result.is_object());
  EXPECT_EQ(result["status"], "rejected");
  EXPECT_FALSE(result["reason"].get<std::string>().empty());
}

TEST_F(RecognitionRegression, BadModelBasesAreRefusedInOneLine) {
  const fs::path image = scan("elephant", 5);
  const std::string bytes = read_text(base_);
  const auto write = [&](const std::string& name, const std::string& content) {
    const fs::path path = dir_ / name;
    std::ofstream(path, std::ios::binary) << content;
    return path;
  };
  const auto expect_refused = [&](const fs::path& base, const std::string& reason) {
    expect_one_line_failure(
        run_cosmos("recognize --modelbase '" + base.string() + "' '" + image.string() + "'", dir_),
        reason);
  };
  expect_refused(write("truncated.cmb", bytes.substr(0, bytes.size() / 2)), "truncated");
  std::string corrupted = bytes;
  corrupted[corrupted.size() / 2] ^= 0x5a;
  expect_refused(write("corrupted.cmb", corrupted), "corrupted");
  std::string other_version = bytes;
  other_version[8] = 99;
  expect_refused(write("version.cmb", other_version), "format version");
  expect_refused(write("text.cmb", "not a model base at all, just some text of some length"),
                 "not a COSMOS model base");
  expect_refused(dir_ / "missing.cmb", "missing.cmb");
}

// A report row's cells that do not depend on timing: number, truth, prediction, status and
// the pose errors.
std::string timeless_row(const std::string& html, int test) {
  const std::string start = "<tr><td>" + std::to_string(test) + "</td>";
  const std::size_t at = html.find(start, html.find("<h2>Tests</h2>"));
  if (at == std::string::npos) return "";
  std::size_t end = at;
  for (int cell = 0; cell < 7 && end != std::string::npos; ++cell)
    end = html.find("</td>", end + 1);
  return end == std::string::npos ? "" : html.substr(at, end - at);
}

TEST_F(RecognitionRegression, OnlyRerunsChosenTestsOfTheSamePlan) {
  const nlohmann::json& full = metrics();
  ASSERT_TRUE(full.is_object());
  const fs::path out = dir_ / "only";
  const CliRun run = run_cosmos("eval --modelbase '" + base_.string() + "' --catalog '" +
                                    std::string(COSMOS_SOURCE_DIR) +
                                    "/config/parts.yaml' --tests 100 --seed 11 --unknown bunny "
                                    "--only 57,3,100 --out '" +
                                    out.string() + "'",
                                dir_);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const nlohmann::json chosen = nlohmann::json::parse(read_text(out / "metrics.json"));
  EXPECT_EQ(chosen["tests"], 2);  // test 100 is the first scan of the unknown part
  const std::string whole = read_text(eval_dir() / "report.html");
  const std::string rerun = read_text(out / "report.html");
  for (int test : {57, 3, 100}) {
    EXPECT_NE(timeless_row(rerun, test), "") << test;
    EXPECT_EQ(timeless_row(rerun, test), timeless_row(whole, test)) << test;
  }
  EXPECT_EQ(timeless_row(rerun, 4), "");
  expect_one_line_failure(
      run_cosmos("eval --modelbase '" + base_.string() + "' --catalog '" +
                     std::string(COSMOS_SOURCE_DIR) +
                     "/config/parts.yaml' --tests 100 --only 500 --out '" + out.string() + "'",
                 dir_),
      "--only 500 is not a test of this plan");
}

}  // namespace
}  // namespace cosmos::testing
