// `cosmos service-unit` (apps/command_service_unit.cpp): the systemd unit's limits follow the
// config's realtime: section, and it runs the cell with the config it names.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "tests/apps/cosmos_cli.hpp"

namespace cosmos {
namespace {

namespace fs = std::filesystem;

class ServiceUnit : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("cosmos_service_unit_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  testing::CliRun unit_for(const std::string& realtime_section) const {
    const fs::path config = dir_ / "cell.yaml";
    std::ofstream(config) << "realtime:\n" << realtime_section;
    return testing::run_cosmos("service-unit --config '" + config.string() +
                                   "' --unit-config /etc/cosmos-cell/cell.yaml --exec "
                                   "/usr/bin/cosmos --fetch-catalog /usr/libexec/f.sh",
                               dir_);
  }

  fs::path dir_;
};

bool has_line(const std::string& text, const std::string& line) {
  return ("\n" + text).find("\n" + line + "\n") != std::string::npos;
}

TEST_F(ServiceUnit, AsksForWhatTheRealtimeSectionAsks) {
  const testing::CliRun run =
      unit_for("  sched_fifo_priority: 80\n  cpu: 0\n  lock_memory: true\n");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_TRUE(has_line(run.out, "LimitRTPRIO=80")) << run.out;
  EXPECT_TRUE(has_line(run.out, "LimitMEMLOCK=infinity")) << run.out;
  EXPECT_TRUE(has_line(run.out, "Restart=on-failure")) << run.out;
  EXPECT_TRUE(has_line(run.out, "StateDirectory=cosmos-cell")) << run.out;
  EXPECT_TRUE(has_line(run.out, "Environment=COSMOS_CACHE_DIR=/var/lib/cosmos-cell")) << run.out;
  EXPECT_TRUE(has_line(run.out, "ExecStartPre=/usr/libexec/f.sh")) << run.out;
  EXPECT_TRUE(has_line(
      run.out,
      "ExecStart=/usr/bin/cosmos cell --config /etc/cosmos-cell/cell.yaml $COSMOS_CELL_ARGS"))
      << run.out;
  // Every CPU but the acquisition thread's 0 (that CPU alone on a one-CPU machine).
  const long cpus = ::sysconf(_SC_NPROCESSORS_ONLN);
  std::string expected = "CPUAffinity=";
  for (long cpu = 1; cpu < cpus; ++cpu) {
    if (cpu > 1) expected += ' ';
    expected += std::to_string(cpu);
  }
  if (cpus <= 1) expected += "0";
  EXPECT_TRUE(has_line(run.out, expected)) << run.out;
}

TEST_F(ServiceUnit, LeavesAffinityAndMemoryAloneWhenTheConfigDoes) {
  const testing::CliRun run = unit_for("  sched_fifo_priority: 0\n  cpu: -1\n");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_TRUE(has_line(run.out, "LimitRTPRIO=0")) << run.out;
  EXPECT_EQ(run.out.find("\nLimitMEMLOCK="), std::string::npos) << run.out;
  EXPECT_EQ(run.out.find("\nCPUAffinity="), std::string::npos) << run.out;
}

TEST_F(ServiceUnit, AMissingConfigFailsInOneLine) {
  testing::expect_one_line_failure(
      testing::run_cosmos("service-unit --config '" + (dir_ / "absent.yaml").string() + "'", dir_),
      "absent.yaml");
}

}  // namespace
}  // namespace cosmos
