#pragma once
// The client kit's tests run robot-side programs the way an integrator does, next to the real
// `cosmos cell`, inside a private network namespace (lo only, with a multicast route), so
// nothing they publish can leave this machine. When the namespace cannot be made the tests
// fail and say why; they never skip.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "tests/realtime/shell_command.hpp"
#include "tests/regression_model_base.hpp"

namespace cosmos::testing {

class ClientKitNamespace : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = std::filesystem::temp_directory_path() /
           ("cosmos_client_kit_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
    ASSERT_TRUE(std::filesystem::exists(COSMOS_BINARY)) << COSMOS_BINARY << " not built";
    ASSERT_TRUE(std::filesystem::exists(COSMOS_LCM_TYPES_JAR))
        << COSMOS_LCM_TYPES_JAR << " not built (needs javac and liblcm-java)";
  }
  void TearDown() override {
    if (!HasFailure()) std::filesystem::remove_all(dir_);
  }

  static std::string quote(const std::filesystem::path& path) { return shell_quote(path.string()); }

  // A config for `parts` parts of the regression catalog (seeded) on the regression base.
  std::filesystem::path cell_config() const {
    const std::filesystem::path config = dir_ / "cell.yaml";
    std::ofstream(config) << "cell:\n"
                          << "  catalog: " << COSMOS_SOURCE_DIR << "/config/parts-regression.yaml\n"
                          << "  model_base: " << regression_model_base().string() << "\n"
                          << "sim_source:\n  seed: 7\n";
    return config;
  }

  // The java command line with the kit's jar and LCM's on the classpath, plus `extra_classes`.
  static std::string java(const std::string& extra_classes) {
    return std::string("java -Djava.net.preferIPv4Stack=true -cp ") +
           shell_quote(std::string(LCM_JAR) + ":" + COSMOS_LCM_TYPES_JAR + ":" + extra_classes);
  }

  // Script lines that wait until `file` holds `text` while `pid_variable`'s process lives.
  static std::string wait_for(const std::filesystem::path& file, const std::string& text,
                              const std::string& pid_variable, int exit_code) {
    std::ostringstream lines;
    lines << "tries=0\n"
          << "until grep -q " << shell_quote(text) << " " << quote(file) << " 2>/dev/null; do\n"
          << "  kill -0 $" << pid_variable << " 2>/dev/null || { cat " << quote(file)
          << " >&2; exit " << exit_code << "; }\n"
          << "  tries=$((tries + 1)); [ $tries -lt 1200 ] || { echo " << shell_quote(text)
          << "' never appeared in " << file.filename().string() << "' >&2; exit " << exit_code
          << "; }\n"
          << "  sleep 0.05\n"
          << "done\n";
    return lines.str();
  }

  // Runs `body` with sh in a new network namespace whose lo is up with a multicast route.
  ShellResult run_in_namespace(const std::string& body) {
    const std::filesystem::path script = dir_ / "in_namespace.sh";
    std::ofstream(script) << "set -u\n"
                          << "echo entered > " << quote(dir_ / "stages") << "\n"
                          << "ip link set lo up || exit 20\n"
                          << "ip route add 224.0.0.0/4 dev lo || exit 21\n"
                          << body;
    const std::string unshare =
        ::geteuid() == 0 ? "unshare --net" : "unshare --net --map-root-user";
    return run_shell(unshare + " sh " + quote(script), dir_);
  }

  ::testing::AssertionResult script_succeeded(const ShellResult& result) const {
    if (read_text_file(dir_ / "stages").find("entered") == std::string::npos) {
      return ::testing::AssertionFailure()
             << "could not create a private network namespace with unshare --net (needs root, "
                "or unprivileged user namespaces): "
             << result.err;
    }
    if (result.exited && result.exit_code == 0) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure()
           << (result.exited ? "exit code " + std::to_string(result.exit_code) : "killed")
           << "; stderr: " << result.err;
  }

  std::filesystem::path dir_;
};

}  // namespace cosmos::testing
