#pragma once
// Runs a shell command line with stdout and stderr captured, for tests that drive the real
// `cosmos` binary and LCM's own tools the way a user does.
#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace cosmos::testing {

struct ShellResult {
  bool exited = false;  // false: killed by a signal
  int exit_code = -1;
  std::string out;
  std::string err;
};

inline std::string read_text_file(const std::filesystem::path& path) {
  std::ifstream file(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
}

// Single-quoted for sh, so paths and URLs with '?' or spaces pass unchanged.
inline std::string shell_quote(const std::string& text) {
  std::string quoted = "'";
  for (const char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

// `scratch_dir` receives the captured streams.
inline ShellResult run_shell(const std::string& command, const std::filesystem::path& scratch_dir) {
  const std::filesystem::path out = scratch_dir / "shell_stdout.txt";
  const std::filesystem::path err = scratch_dir / "shell_stderr.txt";
  const std::string line =
      "(" + command + ") >" + shell_quote(out.string()) + " 2>" + shell_quote(err.string());
  const int status = std::system(line.c_str());
  ShellResult result;
  result.exited = status != -1 && WIFEXITED(status);
  result.exit_code = result.exited ? WEXITSTATUS(status) : -1;
  result.out = read_text_file(out);
  result.err = read_text_file(err);
  return result;
}

inline long line_count(const std::string& text) {
  return std::count(text.begin(), text.end(), '\n');
}

}  // namespace cosmos::testing
