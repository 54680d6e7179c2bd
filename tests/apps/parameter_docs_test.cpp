// docs/parameters.md is what the parameter structs declare (apps/parameter_docs.hpp): the
// committed file equals `cosmos config docs`, so a parameter added, renamed, retired or given
// another default, description or range cannot leave the documentation behind.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "tests/apps/cosmos_cli.hpp"

namespace cosmos {
namespace {

namespace fs = std::filesystem;

TEST(ParameterDocs, TheCommittedFileIsWhatTheStructsDeclare) {
  const fs::path dir = fs::temp_directory_path() / ("cosmos_docs_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const testing::CliRun run = testing::run_cosmos("config docs", dir);
  fs::remove_all(dir);
  ASSERT_TRUE(run.exited);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::string committed =
      testing::read_text(fs::path(COSMOS_SOURCE_DIR) / "docs" / "parameters.md");
  EXPECT_EQ(run.out, committed)
      << "docs/parameters.md is stale: build/apps/cosmos config docs > docs/parameters.md";
  // Every section of the cell config and of the model base has its table.
  for (const char* section : {"`scanner`", "`cell`", "`conditioning`", "`tracking`", "`lcm`",
                              "`realtime`", "`sim_source`", "`camera`", "`gpio`", "`cosmos`",
                              "`registration`", "`grouping`", "`recognition`"})
    EXPECT_NE(run.out.find(std::string("### ") + section), std::string::npos) << section;
  EXPECT_NE(run.out.find("| `smoothing.iterations` | `15` |"), std::string::npos);
  EXPECT_NE(run.out.find("| `buffer_count` | `4` | driver buffers | [2, 16] |"), std::string::npos);
  EXPECT_NE(run.out.find("| `photo_eye_min_off_us` | `20000` |"), std::string::npos);
  EXPECT_EQ(run.out.find("camera_trigger"), std::string::npos);
  EXPECT_NE(run.out.find("Retired: `depth_jump_mm`, replaced by cosmos.fit.depth_jump_mm"),
            std::string::npos);
}

}  // namespace
}  // namespace cosmos
