#pragma once
// Running the real `cosmos` binary from CLI tests, and the contract every bad input must keep:
// a non-zero exit (not a crash: `exec` makes the shell become the binary, so a crash shows as
// a signal) and exactly one line on stderr naming what was wrong.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace cosmos::testing {

struct CliRun {
  bool exited = false;  // false: killed by a signal (a crash)
  int exit_code = -1;
  std::string out;
  std::string err;
};

inline std::string read_text(const std::filesystem::path& path) {
  std::ifstream file(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
}

// Runs `cosmos ARGS`, capturing stdout and stderr in files inside `dir`.
inline CliRun run_cosmos(const std::string& args, const std::filesystem::path& dir) {
  const std::filesystem::path out = dir / "stdout.txt", err = dir / "stderr.txt";
  const std::string command = std::string("exec '") + COSMOS_BINARY + "' " + args + " >'" +
                              out.string() + "' 2>'" + err.string() + "'";
  const int status = std::system(command.c_str());
  CliRun result;
  result.exited = WIFEXITED(status);
  result.exit_code = result.exited ? WEXITSTATUS(status) : -1;
  result.out = read_text(out);
  result.err = read_text(err);
  return result;
}

inline void expect_one_line_failure(const CliRun& result, const std::string& needle) {
  EXPECT_TRUE(result.exited) << "killed by a signal";
  EXPECT_NE(result.exit_code, 0);
  EXPECT_LT(result.exit_code, 128);
  ASSERT_FALSE(result.err.empty());
  EXPECT_EQ(result.err.back(), '\n') << result.err;
  EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
  EXPECT_NE(result.err.find(needle), std::string::npos)
      << "'" << needle << "' not in: " << result.err;
}

}  // namespace cosmos::testing
