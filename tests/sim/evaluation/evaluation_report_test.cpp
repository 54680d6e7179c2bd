// The evaluation report: the five files, images OpenCV can read back at sensible sizes, a page
// that links the images and names every part, metrics.json equal to metrics_json, and one-line
// InputErrors for a directory that cannot be written.
#include "sim/evaluation/evaluation_report.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <Eigen/Geometry>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <numbers>
#include <opencv2/imgcodecs.hpp>
#include <stdexcept>

#include "core/input_error.hpp"

namespace cosmos {
namespace {

namespace fs = std::filesystem;

const std::vector<std::string> kPartNames = {"bracket", "flange", "gear_housing", "ring",
                                             "mystery_casting"};

std::string read_text(const fs::path& path) {
  std::ifstream file(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
}

EvaluationRecord record(int truth, int predicted, int cluster_rank, double rotation_error_deg) {
  EvaluationRecord r;
  r.truth_part = truth;
  r.truth_name = kPartNames[static_cast<std::size_t>(truth)];
  r.truth_in_model_base = truth != 4;
  r.truth_symmetric = truth == 3;
  r.diameter_mm = 80;
  r.rejected = predicted < 0;
  r.predicted_part = predicted;
  if (predicted >= 0) r.predicted_name = kPartNames[static_cast<std::size_t>(predicted)];
  r.true_cluster_rank = r.truth_in_model_base ? cluster_rank : -1;
  r.true_part_among_selected_views = cluster_rank < 3;
  r.fraction_db_examined = 0.05;
  r.R_estimated =
      Eigen::AngleAxisd(rotation_error_deg * std::numbers::pi / 180, Eigen::Vector3d::UnitZ())
          .toRotationMatrix();
  r.t_estimated_mm = {0.5, 0, 0};
  r.recognition_ms = 20 + rotation_error_deg;
  r.features_ms = 12;
  r.registration_ms = 6 + rotation_error_deg;
  return r;
}

class EvaluationReport : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("cosmos_evaluation_report_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    for (int i = 0; i < 60; ++i)
      model_points_.emplace_back(i % 4 * 20.0, i / 4 % 5 * 15.0, i / 20 * 10.0);
  }
  void TearDown() override { fs::remove_all(dir_); }

  EvaluationMetrics metrics_of(const std::vector<EvaluationRecord>& records) const {
    const AddSDistance add_s(model_points_);
    return compute_metrics(records, [&](int) { return &add_s; });
  }

  fs::path dir_;
  std::vector<Eigen::Vector3d> model_points_;
};

TEST_F(EvaluationReport, WritesSixReadableFiles) {
  const std::vector<EvaluationRecord> records = {
      record(0, 0, 0, 1.5), record(0, 0, 1, 3.0), record(1, 1, 0, 0.7),
      record(1, 2, 6, 0),   record(2, 2, 2, 8.0), record(2, -1, 14, 0),
      record(3, 3, 0, 45),  record(4, -1, -1, 0), record(4, 1, -1, 0),
  };
  const EvaluationMetrics metrics = metrics_of(records);
  const fs::path out = dir_ / "report";  // created by the writer
  write_evaluation_report(out, records, metrics, kPartNames);

  for (const char* name : {"confusion_matrix.png", "cluster_rate.png", "rotation_error_cdf.png"}) {
    const cv::Mat image = cv::imread((out / name).string());
    ASSERT_FALSE(image.empty()) << name;
    EXPECT_GE(image.cols, 200) << name;
    EXPECT_GE(image.rows, 150) << name;
    EXPECT_LE(image.cols, 2000) << name;
    EXPECT_LE(image.rows, 2000) << name;
  }
  EXPECT_EQ(nlohmann::json::parse(read_text(out / "metrics.json")), metrics_json(metrics));
  // tests.json: one object per test, in order, with the fields scripts read.
  const nlohmann::json tests = nlohmann::json::parse(read_text(out / "tests.json"));
  ASSERT_EQ(tests.size(), records.size());
  EXPECT_EQ(tests, tests_json(records, metrics));
  EXPECT_EQ(tests[0]["status"], "correct");
  EXPECT_EQ(tests[0]["predicted"], kPartNames[0]);
  EXPECT_DOUBLE_EQ(tests[0]["recognition_ms"].get<double>(), 21.5);
  EXPECT_DOUBLE_EQ(tests[0]["features_ms"].get<double>(), 12);
  EXPECT_DOUBLE_EQ(tests[0]["registration_ms"].get<double>(), 7.5);
  EXPECT_EQ(tests[3]["status"], "misidentified");
  EXPECT_TRUE(tests[3]["add_s_over_diameter"].is_null());
  EXPECT_TRUE(tests[5]["predicted"].is_null());
  EXPECT_EQ(tests[5]["status"], "false reject");
  EXPECT_EQ(tests[7]["truth_in_model_base"], false);

  const std::string html = read_text(out / "report.html");
  EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u);
  for (const char* image : {"confusion_matrix.png", "cluster_rate.png", "rotation_error_cdf.png"})
    EXPECT_NE(html.find(std::string("src=\"") + image + "\""), std::string::npos) << image;
  for (const std::string& name : kPartNames) EXPECT_NE(html.find(name), std::string::npos) << name;
  for (const char* text : {"identification_rate", "misidentified", "false reject",
                           "unknown, rejected", "unknown, accepted", "symmetric"})
    EXPECT_NE(html.find(text), std::string::npos) << text;
  // One table row per test, after the header rows of the metrics, parts and tests tables.
  std::size_t rows = 0;
  for (std::size_t at = html.find("<tr><td>"); at != std::string::npos;
       at = html.find("<tr><td>", at + 1))
    ++rows;
  const std::size_t metric_rows = 25;  // the leaves of metrics.json
  EXPECT_EQ(rows, metric_rows + kPartNames.size() + records.size());
}

TEST_F(EvaluationReport, EmptyRunStillWritesAReport) {
  write_evaluation_report(dir_, {}, metrics_of({}), kPartNames);
  for (const char* name : {"confusion_matrix.png", "cluster_rate.png", "rotation_error_cdf.png"})
    EXPECT_FALSE(cv::imread((dir_ / name).string()).empty()) << name;
  EXPECT_TRUE(
      nlohmann::json::parse(read_text(dir_ / "metrics.json"))["identification_rate"].is_null());
}

TEST_F(EvaluationReport, UnwritableDirectoryIsAnInputErrorNamingIt) {
  // A regular file where a directory should be: refused even for root, unlike permissions.
  std::ofstream(dir_ / "a_file") << "x";
  const fs::path out = dir_ / "a_file" / "report";
  try {
    write_evaluation_report(out, {}, metrics_of({}), kPartNames);
    FAIL() << "no InputError";
  } catch (const InputError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find(out.string()), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
  // A file in the way of one output file.
  fs::create_directories(dir_ / "blocked" / "metrics.json");
  EXPECT_THROW(write_evaluation_report(dir_ / "blocked", {}, metrics_of({}), kPartNames),
               InputError);
}

TEST_F(EvaluationReport, MetricsOfOtherRecordsAreRefused) {
  EXPECT_THROW(
      write_evaluation_report(dir_, std::vector{record(0, 0, 0, 1)}, metrics_of({}), kPartNames),
      std::invalid_argument);
}

}  // namespace
}  // namespace cosmos
