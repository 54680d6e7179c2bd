#pragma once
// The regression model base the recognition and simulated-cell tests share: the five parts of
// config/parts-regression.yaml, 80 views each. ctest builds it once before every test
// (tests/CMakeLists.txt, fixture regression_model_base); a test binary run on its own builds
// it here when it is missing.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

namespace cosmos::testing {

inline std::filesystem::path regression_model_base() {
  const std::filesystem::path path = COSMOS_REGRESSION_MODEL_BASE;
  if (!std::filesystem::exists(path)) {
    std::filesystem::create_directories(path.parent_path());
    const std::string command =
        std::string("'") + COSMOS_BINARY + "' modelbase build --catalog '" + COSMOS_SOURCE_DIR +
        "/config/parts-regression.yaml' --views 80 --out '" + path.string() + "' >/dev/null 2>&1";
    EXPECT_EQ(std::system(command.c_str()), 0) << command;
  }
  return path;
}

}  // namespace cosmos::testing
