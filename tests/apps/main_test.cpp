// The `cosmos` front end (apps/main.cpp): alone it prints the help, not an error;
// `--version` prints the project's version and the commit it was built from.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include "tests/apps/cosmos_cli.hpp"

namespace cosmos {
namespace {

namespace fs = std::filesystem;

class CosmosFrontEnd : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("cosmos_front_end_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

// project(cosmos_cell VERSION x.y.z ...) of the top CMakeLists.txt.
std::string project_version() {
  std::ifstream file(std::string(COSMOS_SOURCE_DIR) + "/CMakeLists.txt");
  std::stringstream text;
  text << file.rdbuf();
  std::smatch match;
  const std::string content = text.str();
  return std::regex_search(content, match, std::regex(R"(project\(cosmos_cell VERSION ([0-9.]+))"))
             ? match[1].str()
             : "";
}

TEST_F(CosmosFrontEnd, AlonePrintsTheHelpWithEverySubcommand) {
  const testing::CliRun run = testing::run_cosmos("", dir_);
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_TRUE(run.err.empty()) << run.err;
  for (const char* command : {"cell", "eval", "listen", "modelbase", "service-unit"})
    EXPECT_NE(run.out.find(std::string("\n  ") + command + " "), std::string::npos)
        << command << " missing in: " << run.out;
}

TEST_F(CosmosFrontEnd, VersionNamesTheProjectVersionAndTheCommit) {
  const testing::CliRun run = testing::run_cosmos("--version", dir_);
  EXPECT_EQ(run.exit_code, 0) << run.err;
  ASSERT_FALSE(project_version().empty());
  EXPECT_TRUE(std::regex_match(
      run.out,
      std::regex("cosmos " + std::regex_replace(project_version(), std::regex(R"(\.)"), R"(\.)") +
                 R"( \((git [0-9a-f]{12}|no git commit: not built from a git checkout)\)\n)")))
      << run.out;
}

}  // namespace
}  // namespace cosmos
