// A bad LCM URL ends in one line naming the URL and the reason, from the library and from
// `cosmos listen`, and none of LCM's own multi-line complaints reach the user.
#include "realtime/lcm/lcm_connection.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <lcm/lcm-cpp.hpp>
#include <string>

#include "core/input_error.hpp"
#include "realtime/lcm/pose_publisher.hpp"
#include "tests/realtime/shell_command.hpp"

namespace cosmos {
namespace {

namespace fs = std::filesystem;

// The InputError's text, with whatever reached stderr meanwhile.
struct OpenFailure {
  std::string message;
  std::string stderr_text;
};

OpenFailure failure_of(const std::string& url) {
  OpenFailure failure;
  ::testing::internal::CaptureStderr();
  try {
    open_lcm(url);
    failure.message = "(no error)";
  } catch (const InputError& error) {
    failure.message = error.what();
  }
  failure.stderr_text = ::testing::internal::GetCapturedStderr();
  return failure;
}

void expect_one_line_naming(const std::string& url, const std::string& reason) {
  SCOPED_TRACE(url);
  const OpenFailure failure = failure_of(url);
  EXPECT_EQ(failure.message.find('\n'), std::string::npos) << failure.message;
  EXPECT_NE(failure.message.find("'" + url + "'"), std::string::npos) << failure.message;
  EXPECT_NE(failure.message.find(reason), std::string::npos) << failure.message;
  EXPECT_EQ(failure.stderr_text, "");
}

TEST(LcmConnection, BadUrlsFailInOneLineNamingUrlAndReason) {
  expect_one_line_naming("bogus://somewhere", "provider \"bogus\" not found");
  expect_one_line_naming("239.255.76.67:7667", "not of the form provider://");
  expect_one_line_naming("udpm://10.1.2.3:7667", "10.1.2.3 is not a multicast group");
  expect_one_line_naming("udpm://239.255.76.67:port", "Bad multicast port \"port\"");
  expect_one_line_naming("file:///nonexistent_dir/cell.lcmlog?mode=r", "No such file or directory");
}

TEST(LcmConnection, PublisherOnABadUrlThrowsTheSameLine) {
  try {
    LcmPublisher publisher("bogus://x");
    FAIL() << "no error for bogus://x";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()), "LCM URL 'bogus://x': LCM provider \"bogus\" not found");
  }
}

TEST(LcmConnection, GoodUrlOpensAndLeavesStderrAlone) {
  ::testing::internal::CaptureStderr();
  const auto lcm = open_lcm("memq://");
  const std::string stderr_text = ::testing::internal::GetCapturedStderr();
  ASSERT_NE(lcm, nullptr);
  EXPECT_TRUE(lcm->good());
  EXPECT_EQ(stderr_text, "");
}

TEST(LcmConnection, ListenWithABadUrlPrintsOneLineAndFails) {
  ASSERT_TRUE(fs::exists(COSMOS_BINARY))
      << COSMOS_BINARY << " not built: build the `cosmos` target first";
  const fs::path dir = fs::temp_directory_path() / ("cosmos_lcm_url_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const testing::ShellResult result = testing::run_shell(
      testing::shell_quote(COSMOS_BINARY) + " listen --url 'bogus://x' --timeout-s 1", dir);
  fs::remove_all(dir);
  EXPECT_TRUE(result.exited);
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_EQ(result.out, "");
  EXPECT_EQ(result.err, "cosmos: LCM URL 'bogus://x': LCM provider \"bogus\" not found\n");
}

}  // namespace
}  // namespace cosmos
