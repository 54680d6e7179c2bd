// The client kit's example subscribers (clients/java/PoseSubscriber.java on
// cosmos_lcm_types.jar, clients/cpp/pose_subscriber.cpp built as a standalone project against
// the kit's CMake package) receive what `cosmos cell --parts 5` publishes on COSMOS_POSE in a
// private network namespace. The Java classes must decode every field exactly as the C++
// classes do (doubles bit for bit), and agree with the cell's own table and the simulated truth.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "tests/clients/client_kit_namespace.hpp"

namespace cosmos {
namespace {

constexpr int kPartCount = 5;

using Fields = std::map<std::string, std::string>;

// "pose k=v k=v ... reason=free text" lines into fields; other lines are ignored.
std::vector<Fields> pose_lines(const std::string& text) {
  std::vector<Fields> poses;
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line)) {
    if (line.rfind("pose ", 0) != 0) continue;
    Fields fields;
    const std::size_t reason = line.find(" reason=");
    fields["reason"] = reason == std::string::npos ? "<missing>" : line.substr(reason + 8);
    std::istringstream words(line.substr(5, reason - 5));
    std::string word;
    while (words >> word) {
      const std::size_t equals = word.find('=');
      if (equals != std::string::npos) fields[word.substr(0, equals)] = word.substr(equals + 1);
    }
    poses.push_back(fields);
  }
  return poses;
}

std::vector<double> numbers(const std::string& text) {
  std::vector<double> values;
  std::istringstream items(text);
  std::string item;
  while (std::getline(items, item, ',')) values.push_back(std::strtod(item.c_str(), nullptr));
  return values;
}

// A row of the cell's live table: part name status x_mm y_mm z_mm score rms_mm latency_ms
// [truth: name].
struct TableRow {
  int part = -1;
  std::string name, status;
  double x_mm = 0, y_mm = 0, z_mm = 0, score = 0, rms_mm = 0, latency_ms = 0;
  std::string truth;
};

std::vector<TableRow> table_rows(const std::string& text) {
  std::vector<TableRow> rows;
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line)) {
    std::istringstream words(line);
    TableRow row;
    std::string truth_label;
    if (!(words >> row.part >> row.name >> row.status >> row.x_mm >> row.y_mm >> row.z_mm >>
          row.score >> row.rms_mm >> row.latency_ms))
      continue;
    if (words >> truth_label >> row.truth && truth_label != "truth:") row.truth.clear();
    rows.push_back(row);
  }
  return rows;
}

const char* kDoubleFields[] = {"position_m", "orientation_wxyz", "score", "registration_rms_mm",
                               "latency_ms"};
const char* kExactFields[] = {"seq",        "part",  "status",        "part_index",
                              "view_index", "utime", "encoder_ticks", "reason"};

class PoseSubscribers : public testing::ClientKitNamespace {};

TEST_F(PoseSubscribers, JavaAndCppDecodeEveryFieldOfTheCellsPoses) {
  const auto out = [&](const char* name) { return dir_ / name; };
  std::ostringstream body;
  body << java(COSMOS_JAVA_EXAMPLE_CLASSES) << " PoseSubscriber --count " << kPartCount
       << " --timeout-s 120 >" << quote(out("java.out")) << " 2>" << quote(out("java.err"))
       << " &\njava_pid=$!\n"
       << quote(COSMOS_CPP_SUBSCRIBER) << " --count " << kPartCount << " --timeout-s 120 >"
       << quote(out("cpp.out")) << " 2>" << quote(out("cpp.err")) << " &\ncpp_pid=$!\n"
       << wait_for(out("java.err"), "listening on COSMOS_POSE", "java_pid", 22)
       << wait_for(out("cpp.err"), "listening on COSMOS_POSE", "cpp_pid", 23)
       << quote(COSMOS_BINARY) << " cell --config " << quote(cell_config()) << " --parts "
       << kPartCount << " --unpaced >" << quote(out("cell.out")) << " 2>" << quote(out("cell.err"))
       << " || { cat " << quote(out("cell.err")) << " >&2; exit 24; }\n"
       << "wait $java_pid || { cat " << quote(out("java.err")) << " >&2; exit 25; }\n"
       << "wait $cpp_pid || { cat " << quote(out("cpp.err")) << " >&2; exit 26; }\n";
  const testing::ShellResult result = run_in_namespace(body.str());
  ASSERT_TRUE(script_succeeded(result));

  const std::vector<Fields> java_poses = pose_lines(testing::read_text_file(out("java.out")));
  const std::vector<Fields> cpp_poses = pose_lines(testing::read_text_file(out("cpp.out")));
  const std::string table = testing::read_text_file(out("cell.out"));
  const std::vector<TableRow> rows = table_rows(table);
  ASSERT_EQ(java_poses.size(), static_cast<std::size_t>(kPartCount)) << table;
  ASSERT_EQ(cpp_poses.size(), java_poses.size());
  ASSERT_EQ(rows.size(), java_poses.size()) << table;

  int identified = 0;
  for (std::size_t i = 0; i < java_poses.size(); ++i) {
    const Fields& from_java = java_poses[i];
    const Fields& from_cpp = cpp_poses[i];
    for (const char* key : kExactFields) {
      ASSERT_TRUE(from_java.count(key)) << key << " missing in Java pose " << i;
      EXPECT_EQ(from_java.at(key), from_cpp.at(key)) << key << " of pose " << i;
    }
    for (const char* key : kDoubleFields) {
      ASSERT_TRUE(from_java.count(key)) << key << " missing in Java pose " << i;
      const std::vector<double> java_values = numbers(from_java.at(key));
      const std::vector<double> cpp_values = numbers(from_cpp.at(key));
      ASSERT_EQ(java_values.size(), cpp_values.size()) << key;
      for (std::size_t k = 0; k < java_values.size(); ++k)
        EXPECT_EQ(java_values[k], cpp_values[k]) << key << "[" << k << "] of pose " << i;
    }

    // The cell's table (millimetres, rounded) and the simulated truth.
    const TableRow& row = rows[i];
    EXPECT_EQ(from_java.at("seq"), std::to_string(row.part));
    EXPECT_EQ(from_java.at("part"), row.name);
    EXPECT_EQ(from_java.at("status"), row.status);
    const std::vector<double> position_m = numbers(from_java.at("position_m"));
    ASSERT_EQ(position_m.size(), 3U);
    EXPECT_NEAR(position_m[0] * 1000, row.x_mm, 0.0051);
    EXPECT_NEAR(position_m[1] * 1000, row.y_mm, 0.0051);
    EXPECT_NEAR(position_m[2] * 1000, row.z_mm, 0.0051);
    EXPECT_NEAR(std::strtod(from_java.at("score").c_str(), nullptr), row.score, 0.00051);
    EXPECT_NEAR(std::strtod(from_java.at("registration_rms_mm").c_str(), nullptr), row.rms_mm,
                0.000051);
    EXPECT_NEAR(std::strtod(from_java.at("latency_ms").c_str(), nullptr), row.latency_ms, 0.051);
    const std::vector<double> q = numbers(from_java.at("orientation_wxyz"));
    ASSERT_EQ(q.size(), 4U);
    EXPECT_NEAR(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3], 1.0, 1e-9);
    EXPECT_GE(q[0], 0.0);
    identified += from_java.at("status") == "OK" && from_java.at("part") == row.truth ? 1 : 0;
  }
  // The recognizer's own accuracy is tested elsewhere; here the names must carry through.
  EXPECT_GE(identified, kPartCount - 1) << table;
}

}  // namespace
}  // namespace cosmos
