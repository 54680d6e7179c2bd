// One-line YAML input errors (core/io/yaml_input_errors.hpp): `file:LINE: key: reason` with
// the line 1-based, the file alone where no line is known, and the value described.
#include "core/io/yaml_input_errors.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/input_error.hpp"

namespace cosmos {
namespace {

namespace fs = std::filesystem;

// The message of the InputError `run` throws ("" when it throws none).
template <class Run>
std::string error_of(Run&& run) {
  try {
    run();
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

TEST(YamlInputErrors, NamesTheFileTheOneBasedLineTheKeyAndTheReason) {
  const YamlInputErrors errors("config/cell.yaml");
  EXPECT_EQ(error_of([&] { errors.fail_line(0, "tracking.gap_mm", "must be positive"); }),
            "config/cell.yaml:1: tracking.gap_mm: must be positive");
  EXPECT_EQ(error_of([&] { errors.fail_line(-1, "tracking", "missing"); }),
            "config/cell.yaml: tracking: missing");
  // A node's mark is 0-based: the third line is line 3.
  const YAML::Node root = YAML::Load("a: 1\nb:\n  c: wrong\n");
  EXPECT_EQ(error_of([&] { errors.fail(root["b"]["c"], "b.c", "expected a number"); }),
            "config/cell.yaml:3: b.c: expected a number");
  // An absent key has no line.
  EXPECT_EQ(error_of([&] { errors.fail(root["d"], "d", "missing"); }),
            "config/cell.yaml: d: missing");
}

TEST(YamlInputErrors, DescribesWhatAWrongValueWas) {
  const YAML::Node root = YAML::Load("list: [1, 2]\nmap: {a: 1}\nempty:\nword: wide\n");
  EXPECT_EQ(describe_yaml_node(root["list"]), "a list");
  EXPECT_EQ(describe_yaml_node(root["map"]), "a map");
  EXPECT_EQ(describe_yaml_node(root["empty"]), "nothing");
  EXPECT_EQ(describe_yaml_node(root["word"]), "'wide'");
}

class YamlInputErrorsFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("cosmos_yaml_input_errors_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path write(const std::string& name, const std::string& text) const {
    std::ofstream(dir_ / name) << text;
    return dir_ / name;
  }
  fs::path dir_;
};

TEST_F(YamlInputErrorsFile, LoadsTheRootOrSaysWhyNot) {
  const fs::path good = write("good.yaml", "tracking:\n  gap_mm: 5\n");
  EXPECT_EQ(YamlInputErrors(good).load_file("cell config")["tracking"]["gap_mm"].as<int>(), 5);
  const fs::path absent = dir_ / "absent.yaml";
  EXPECT_EQ(error_of([&] { YamlInputErrors(absent).load_file("cell config"); }),
            absent.string() + ": cell config not found");
  EXPECT_EQ(error_of([&] { YamlInputErrors(dir_).load_file("catalog"); }),
            dir_.string() + ": catalog not found");  // a directory is no file
  const fs::path broken = write("broken.yaml", "a: 1\nb: [1, 2\nc: 3\n");
  const std::string message = error_of([&] { YamlInputErrors(broken).load_file("cell config"); });
  EXPECT_EQ(message.rfind(broken.string() + ":", 0), 0u) << message;
  EXPECT_NE(message.find(": yaml: "), std::string::npos) << message;
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

}  // namespace
}  // namespace cosmos
