// Inter-process LCM as a user runs it: inside a private network namespace (so nothing can
// leave this machine), lcm-logger records, `cosmos listen` prints, and a separate publisher
// process (this test binary, started in a publisher mode) publishes on the default udpm URL.
// The log then decodes to exactly what was published. Then the real thing: `cosmos cell
// --parts 5` on the simulated conveyor with the regression catalog, recorded by lcm-logger.
// When the namespace cannot be made the tests fail and say why; they never skip.
#include <gtest/gtest.h>
#include <net/if.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <lcm/lcm-cpp.hpp>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "core/input_error.hpp"
#include "realtime/lcm/lcm_channels.hpp"
#include "realtime/lcm/lcm_log_reader.hpp"
#include "realtime/lcm/pose_publisher.hpp"
#include "tests/realtime/lcm_test_messages.hpp"
#include "tests/realtime/shell_command.hpp"
#include "tests/regression_model_base.hpp"

namespace cosmos {
namespace {

namespace fs = std::filesystem;

constexpr char kPublisherModeVariable[] = "COSMOS_LCM_TEST_PUBLISH_TO_LOG";
// The sync mode: sync messages until lcm-logger has subscribed (COSMOS_LCM_TEST_SYNC=ready)
// or until its log holds the cell's final status (=cell-ended), so that the script can start
// the cell, or stop the logger, knowing nothing is lost.
constexpr char kSyncModeVariable[] = "COSMOS_LCM_TEST_SYNC";
constexpr char kSyncLogVariable[] = "COSMOS_LCM_TEST_SYNC_LOG";
constexpr char kCellEndedText[] = "the source has ended";  // realtime/cell/cell_runner.cpp
constexpr int kPoseCount = 3;
constexpr int kProfileCount = 2;
constexpr char kFinalStatusText[] = "namespace test: all sent";
// Warm-up and flush messages go on a channel of their own, so the cell's channels in the
// log hold exactly the payload.
constexpr char kSyncChannel[] = "COSMOS_TEST_SYNC";

std::vector<PartPose> published_poses() {
  std::vector<PartPose> poses;
  for (int i = 0; i < kPoseCount; ++i) poses.push_back(testing::sample_pose(10 + i));
  return poses;
}

std::vector<Profile> published_profiles() {
  std::vector<Profile> profiles;
  for (int i = 0; i < kProfileCount; ++i) profiles.push_back(testing::sample_profile(100 + i));
  return profiles;
}

// Publishing over udpm is only allowed where it cannot reach a real network.
bool only_loopback_exists() {
  struct if_nameindex* interfaces = ::if_nameindex();
  if (interfaces == nullptr) return false;
  bool only_lo = true;
  for (const struct if_nameindex* i = interfaces; i->if_index != 0; ++i)
    only_lo = only_lo && std::string(i->if_name) == "lo";
  ::if_freenameindex(interfaces);
  return only_lo;
}

// Polls `done` every 20 ms for up to 10 s while `step` runs between polls.
template <class Done, class Step>
bool poll(Done done, Step step) {
  for (int attempt = 0; attempt < 500; ++attempt) {
    if (done()) return true;
    step();
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return done();
}

bool log_holds_everything(const fs::path& log) {
  try {
    const std::vector<CellStatus> statuses = read_logged_statuses(log);
    return !statuses.empty() && statuses.back().state_text == kFinalStatusText;
  } catch (const InputError&) {
    return false;  // lcm-logger has not flushed a whole event yet
  }
}

// The publisher mode: sync messages until lcm-logger has demonstrably subscribed (its log is
// no longer empty: it logs LCM's own self-test message once its subscription works), then the
// payload, then sync messages until the log holds it all so the script may stop the logger.
// lcm-logger flushes only when a message arrives after its flush interval, so without the
// trailing sync messages the payload would sit in its buffer.
bool logger_ready(const fs::path& log) {
  std::error_code error;
  return fs::file_size(log, error) > 0 && !error;
}

bool log_holds_cell_end(const fs::path& log) {
  try {
    for (const CellStatus& status : read_logged_statuses(log))
      if (status.state_text == kCellEndedText) return true;
  } catch (const InputError&) {
  }
  return false;
}

bool refuse_outside_namespace(const char* who) {
  if (only_loopback_exists()) return false;
  std::cerr << who
            << ": refusing to publish, interfaces other than lo exist (not in a private "
               "namespace)\n";
  return true;
}

int sync_in_namespace(const std::string& until, const fs::path& log) {
  if (refuse_outside_namespace("sync")) return 10;
  try {
    LcmPublisher publisher(kDefaultLcmUrl);
    const auto sync = [&] { publisher.lcm().publish(kSyncChannel, "sync", 4); };
    const bool done = until == "ready" ? poll([&] { return logger_ready(log); }, sync)
                                       : poll([&] { return log_holds_cell_end(log); }, sync);
    if (!done) std::cerr << "sync: the log never reached '" << until << "' within 10 s\n";
    return done ? 0 : 11;
  } catch (const InputError& error) {
    std::cerr << "sync: " << error.what() << "\n";
    return 14;
  }
}

int publish_in_namespace(const fs::path& log) {
  if (refuse_outside_namespace("publisher")) return 10;
  try {
    LcmPublisher publisher(kDefaultLcmUrl);
    const auto sync = [&] { publisher.lcm().publish(kSyncChannel, "sync", 4); };
    if (!poll([&] { return logger_ready(log); }, sync)) {
      std::cerr << "publisher: lcm-logger logged nothing within 10 s\n";
      return 11;
    }
    bool sent = true;
    for (const Profile& profile : published_profiles()) sent = publisher.publish(profile) && sent;
    for (const PartPose& pose : published_poses()) sent = publisher.publish(pose) && sent;
    sent = publisher.publish(testing::sample_status(kFinalStatusText)) && sent;
    if (!sent) {
      std::cerr << "publisher: LCM refused a message\n";
      return 12;
    }
    if (!poll([&] { return log_holds_everything(log); }, sync)) {
      std::cerr << "publisher: the final status never reached the log\n";
      return 13;
    }
  } catch (const InputError& error) {
    std::cerr << "publisher: " << error.what() << "\n";
    return 14;
  }
  return 0;
}

// Runs before main(): in publisher mode this process is the namespace's publisher, not a
// test run.
[[maybe_unused]] const bool publisher_mode_handled = [] {
  if (const char* log = std::getenv(kPublisherModeVariable)) std::exit(publish_in_namespace(log));
  if (const char* until = std::getenv(kSyncModeVariable))
    std::exit(sync_in_namespace(until, std::getenv(kSyncLogVariable)));
  return false;
}();

class LcmNetworkNamespace : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("cosmos_lcm_netns_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    ASSERT_EQ(std::system("command -v lcm-logger >/dev/null 2>&1"), 0)
        << "lcm-logger not found: install liblcm-bin (bash scripts/setup.sh)";
    ASSERT_TRUE(fs::exists(COSMOS_BINARY))
        << COSMOS_BINARY << " not built: build the `cosmos` target first";
  }
  void TearDown() override {
    if (!HasFailure()) fs::remove_all(dir_);
  }

  // Root makes the namespace directly; anyone else through a user namespace mapped to root.
  static std::string unshare_command() {
    return ::geteuid() == 0 ? "unshare --net" : "unshare --net --map-root-user";
  }

  // Runs `body` with sh inside a new network namespace, after marking the stages so that a
  // failure says which step did not happen.
  testing::ShellResult run_in_namespace(const std::string& body) {
    const fs::path script = dir_ / "in_namespace.sh";
    std::ofstream(script) << "set -u\n"
                          << "echo entered >> " << stages() << "\n"
                          << body;
    return testing::run_shell(unshare_command() + " sh " + testing::shell_quote(script.string()),
                              dir_);
  }

  std::string stages() const { return testing::shell_quote((dir_ / "stages").string()); }

  ::testing::AssertionResult namespace_entered(const testing::ShellResult& result) const {
    if (testing::read_text_file(dir_ / "stages").find("entered") != std::string::npos) {
      return ::testing::AssertionSuccess();
    }
    return ::testing::AssertionFailure()
           << "could not create a private network namespace with `" << unshare_command()
           << "` (needs root, or unprivileged user namespaces): " << result.err;
  }

  // A script that ran to the end in the namespace, with what to read when it did not.
  ::testing::AssertionResult script_succeeded(const testing::ShellResult& result) const {
    if (!namespace_entered(result)) return namespace_entered(result);
    if (result.exited && result.exit_code == 0) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure()
           << (result.exited ? "exit code " + std::to_string(result.exit_code) : "killed")
           << "; stages: " << testing::read_text_file(dir_ / "stages") << "stderr: " << result.err
           << "logger: " << testing::read_text_file(dir_ / "logger.err");
  }

  // Script lines: lo up with a multicast route, and lcm-logger recording the default URL into
  // `log` until the script exits.
  std::string loopback_with_logger(const fs::path& log) const {
    std::ostringstream lines;
    lines << "ip link set lo up || exit 20\n"
          << "ip route add 224.0.0.0/4 dev lo || exit 21\n"
          << "lcm-logger --quiet --force --flush-interval=10 --lcm-url="
          << testing::shell_quote(kDefaultLcmUrl) << " " << testing::shell_quote(log.string())
          << " 2>" << testing::shell_quote((dir_ / "logger.err").string()) << " &\n"
          << "logger=$!\n"
          << "trap 'kill -INT $logger 2>/dev/null; wait $logger' EXIT\n";
    return lines.str();
  }

  fs::path dir_;
};

TEST_F(LcmNetworkNamespace, LoggerAndListenerReceiveWhatAnotherProcessPublishes) {
  const auto quote = [](const fs::path& path) { return testing::shell_quote(path.string()); };
  const fs::path log = dir_ / "cell.lcmlog";
  const fs::path test_binary = fs::read_symlink("/proc/self/exe");
  std::ostringstream body;
  body << loopback_with_logger(log) << testing::shell_quote(COSMOS_BINARY)
       << " listen --channel COSMOS_POSE --count " << kPoseCount << " --timeout-s 20 >"
       << quote(dir_ / "listen.out") << " 2>" << quote(dir_ / "listen.err") << " &\n"
       << "listener=$!\n"
       // `cosmos listen` says so on stderr once it has subscribed.
       << "tries=0\n"
       << "until grep -q '^listen:' " << quote(dir_ / "listen.err") << "; do\n"
       << "  kill -0 $listener 2>/dev/null || { cat " << quote(dir_ / "listen.err")
       << " >&2; exit 22; }\n"
       << "  tries=$((tries + 1)); [ $tries -lt 400 ] || { echo 'cosmos listen never subscribed' "
          ">&2; exit 22; }\n"
       << "  sleep 0.05\n"
       << "done\n"
       << "echo listening >> " << stages() << "\n"
       << kPublisherModeVariable << "=" << quote(log) << " " << quote(test_binary)
       << " || exit 23\n"
       << "echo published >> " << stages() << "\n"
       << "wait $listener || { cat " << quote(dir_ / "listen.err") << " >&2; exit 24; }\n";
  const testing::ShellResult result = run_in_namespace(body.str());
  ASSERT_TRUE(script_succeeded(result));

  const std::vector<PartPose> poses = read_logged_poses(log);
  const std::vector<PartPose> expected_poses = published_poses();
  ASSERT_EQ(poses.size(), expected_poses.size());
  for (std::size_t i = 0; i < poses.size(); ++i)
    testing::expect_same_pose(expected_poses[i], poses[i]);

  const std::vector<Profile> profiles = read_logged_profiles(log);
  const std::vector<Profile> expected_profiles = published_profiles();
  ASSERT_EQ(profiles.size(), expected_profiles.size());
  for (std::size_t i = 0; i < profiles.size(); ++i)
    testing::expect_same_profile(expected_profiles[i], profiles[i]);

  const std::vector<CellStatus> statuses = read_logged_statuses(log);
  ASSERT_EQ(statuses.size(), 1U);
  testing::expect_same_status(testing::sample_status(kFinalStatusText), statuses[0]);

  // `cosmos listen`: one line per pose, in order, positions in metres (133.4 mm + 1 mm per part).
  const char* expected_positions_m[kPoseCount] = {
      "pos_m=[0.1334 -0.0567 0.03]", "pos_m=[0.1344 -0.0567 0.03]", "pos_m=[0.1354 -0.0567 0.03]"};
  std::istringstream lines(testing::read_text_file(dir_ / "listen.out"));
  std::string line;
  for (int i = 0; i < kPoseCount; ++i) {
    ASSERT_TRUE(std::getline(lines, line));
    const PartPose& pose = expected_poses[static_cast<std::size_t>(i)];
    const std::string head =
        "COSMOS_POSE seq=" + std::to_string(pose.part_seq) + " part=" + pose.part_name + " ";
    EXPECT_EQ(line.rfind(head, 0), 0U) << line;
    EXPECT_NE(line.find(expected_positions_m[i]), std::string::npos) << line;
  }
  EXPECT_FALSE(std::getline(lines, line)) << "extra line: " << line;
}

TEST_F(LcmNetworkNamespace, LoggerRecordsTheCellsPosesAndStatus) {
  const auto quote = [](const fs::path& path) { return testing::shell_quote(path.string()); };
  const fs::path log = dir_ / "cell.lcmlog";
  const fs::path config = dir_ / "cell.yaml";
  std::ofstream(config) << "cell:\n"
                        << "  catalog: " << COSMOS_SOURCE_DIR << "/config/parts-regression.yaml\n"
                        << "  model_base: " << testing::regression_model_base().string() << "\n"
                        << "sim_source:\n  seed: 7\n";
  const fs::path test_binary = fs::read_symlink("/proc/self/exe");
  const auto sync_until = [&](const char* until) {
    return std::string(kSyncModeVariable) + "=" + until + " " + kSyncLogVariable + "=" +
           quote(log) + " " + quote(test_binary);
  };
  std::ostringstream body;
  body << loopback_with_logger(log) << sync_until("ready") << " || exit 22\n"
       << "echo logging >> " << stages() << "\n"
       << testing::shell_quote(COSMOS_BINARY) << " cell --config " << quote(config)
       << " --parts 5 --unpaced >" << quote(dir_ / "cell.out") << " 2>" << quote(dir_ / "cell.err")
       << " || { cat " << quote(dir_ / "cell.err") << " >&2; exit 23; }\n"
       << "echo cell-ran >> " << stages() << "\n"
       << sync_until("cell-ended") << " || exit 24\n";
  const testing::ShellResult result = run_in_namespace(body.str());
  ASSERT_TRUE(script_succeeded(result));

  const std::vector<PartPose> poses = read_logged_poses(log);
  ASSERT_EQ(poses.size(), 5u) << testing::read_text_file(dir_ / "cell.out");
  int recognized = 0;
  for (std::size_t i = 0; i < poses.size(); ++i) {
    EXPECT_EQ(poses[i].part_seq, static_cast<std::int64_t>(i));
    recognized += poses[i].status == PoseStatus::kOk ? 1 : 0;
  }
  EXPECT_GE(recognized, 4) << testing::read_text_file(dir_ / "cell.out");
  const std::vector<CellStatus> statuses = read_logged_statuses(log);
  ASSERT_FALSE(statuses.empty());
  EXPECT_EQ(statuses.back().state_text, kCellEndedText);
  EXPECT_EQ(statuses.back().parts_seen, 5);
  EXPECT_EQ(statuses.back().parts_recognized + statuses.back().parts_rejected, 5);
  // The cell's summary says what a user reads at the end of a run.
  EXPECT_NE(testing::read_text_file(dir_ / "cell.out").find("5 poses published"), std::string::npos)
      << testing::read_text_file(dir_ / "cell.out");
}

TEST_F(LcmNetworkNamespace, NoMulticastRouteFailsInOneLine) {
  // lo is up but has no multicast route: LCM's dozen lines of advice become one.
  const testing::ShellResult result =
      run_in_namespace("ip link set lo up || exit 20\n" + testing::shell_quote(COSMOS_BINARY) +
                       " listen --timeout-s 1\n");
  ASSERT_TRUE(namespace_entered(result));
  EXPECT_TRUE(result.exited);
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_EQ(result.err, std::string("cosmos: LCM URL '") + kDefaultLcmUrl +
                            "': no route to the multicast group (on a machine without network: "
                            "ip link set lo up && ip route add 224.0.0.0/4 dev lo)\n");
}

}  // namespace
}  // namespace cosmos
