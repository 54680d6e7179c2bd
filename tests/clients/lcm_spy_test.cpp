// lcm-spy with the client kit's jar decodes the cell's COSMOS_POSE as part_pose_t: under a
// virtual X server (Xvfb) in a private network namespace, lcm-spy (LcmSpyProbe.java runs its
// class and reads its channel table) watches while `cosmos cell --parts 2` publishes. The
// screenshot of its window is kept as build/test-artifacts/lcm-spy.png.
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>
#include <string>

#include "tests/clients/client_kit_namespace.hpp"

namespace cosmos {
namespace {

namespace fs = std::filesystem;

class LcmSpy : public testing::ClientKitNamespace {};

TEST_F(LcmSpy, ShowsTheCellsPosesDecodedAsPartPoseT) {
  ASSERT_EQ(std::system("command -v Xvfb >/dev/null 2>&1"), 0)
      << "Xvfb not found: bash scripts/setup.sh --client-kit-checks";
  const fs::path artifacts = COSMOS_ARTIFACT_DIR;
  fs::create_directories(artifacts);
  const fs::path screenshot = artifacts / "lcm-spy.png";
  fs::remove(screenshot);
  const auto out = [&](const char* name) { return dir_ / name; };
  std::ostringstream body;
  // -displayfd: Xvfb picks a free display and writes its number once it accepts clients.
  body << "Xvfb -displayfd 3 -screen 0 1024x768x24 -nolisten tcp 3>" << quote(out("display"))
       << " 2>" << quote(out("xvfb.err")) << " &\nxvfb_pid=$!\n"
       << "trap 'kill $xvfb_pid 2>/dev/null' EXIT\n"
       << wait_for(out("display"), "[0-9]", "xvfb_pid", 22) << "DISPLAY=:$(cat "
       << quote(out("display")) << ")\nexport DISPLAY\n"
       << java(COSMOS_SPY_PROBE_CLASSES) << " LcmSpyProbe " << quote(screenshot)
       << " 60 COSMOS_POSE >" << quote(out("spy.out")) << " 2>" << quote(out("spy.err"))
       << " &\nspy_pid=$!\n"
       << wait_for(out("spy.out"), "lcm-spy: started", "spy_pid", 23) << quote(COSMOS_BINARY)
       << " cell --config " << quote(cell_config()) << " --parts 2 --unpaced >"
       << quote(out("cell.out")) << " 2>" << quote(out("cell.err")) << " || { cat "
       << quote(out("cell.err")) << " >&2; exit 24; }\n"
       << "wait $spy_pid || { cat " << quote(out("spy.out")) << " >&2; exit 25; }\n";
  const testing::ShellResult result = run_in_namespace(body.str());
  ASSERT_TRUE(script_succeeded(result)) << testing::read_text_file(out("spy.err"));

  const std::string spy = testing::read_text_file(out("spy.out"));
  EXPECT_NE(spy.find("lcm-spy: COSMOS_POSE decoded as part_pose_t ("), std::string::npos) << spy;
  EXPECT_NE(spy.find(", 0 undecodable)"), std::string::npos) << spy;
  EXPECT_NE(spy.find("lcm-spy: window 'LCM Spy'"), std::string::npos) << spy;
  ASSERT_TRUE(fs::exists(screenshot));
  EXPECT_GT(fs::file_size(screenshot), 2000U);  // a PNG of a drawn window, not an empty file
}

}  // namespace
}  // namespace cosmos
