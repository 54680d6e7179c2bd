// A robot-side subscriber in C++: receives the cell's part_pose_t messages on COSMOS_POSE and
// prints one line per part with every field, as the robot's pick logic would read them.
// Built as a standalone project against the installed kit (see CMakeLists.txt beside it).
//
// Options: --url URL (default: $LCM_DEFAULT_URL, else LCM's udpm default, which the cell
// publishes on), --count N (exit after N poses), --timeout-s S (exit 1 when S seconds pass first).
// The pose is T_cell_part: x_cell = R(orientation_wxyz) * x_part + position_m; it holds at
// encoder_ticks, so a robot tracking the conveyor moves it by the belt travel since then.
#include <chrono>
#include <cosmos_lcm/part_pose_t.hpp>
#include <cstdio>
#include <cstdlib>
#include <lcm/lcm-cpp.hpp>
#include <string>

namespace {

constexpr char kPoseChannel[] = "COSMOS_POSE";

const char* status_name(int8_t status) {
  switch (status) {
    case cosmos_lcm::part_pose_t::OK:
      return "OK";
    case cosmos_lcm::part_pose_t::REJECTED:
      return "REJECTED";
    case cosmos_lcm::part_pose_t::ERROR:
      return "ERROR";
    default:
      return "UNKNOWN";
  }
}

struct PosePrinter {
  long received = 0;

  // One line per pose; %.17g keeps every double exact; the reason (free text) comes last.
  void on_pose(const lcm::ReceiveBuffer*, const std::string&, const cosmos_lcm::part_pose_t* pose) {
    const double* p = pose->position_m;
    const double* q = pose->orientation_wxyz;
    std::printf(
        "pose seq=%lld part=%s status=%s part_index=%d view_index=%d utime=%lld "
        "encoder_ticks=%lld position_m=%.17g,%.17g,%.17g orientation_wxyz=%.17g,%.17g,%.17g,%.17g "
        "score=%.17g registration_rms_mm=%.17g latency_ms=%.17g reason=%s\n",
        static_cast<long long>(pose->part_seq),
        pose->part_name.empty() ? "-" : pose->part_name.c_str(), status_name(pose->status),
        pose->part_index, pose->view_index, static_cast<long long>(pose->utime),
        static_cast<long long>(pose->encoder_ticks), p[0], p[1], p[2], q[0], q[1], q[2], q[3],
        pose->score, pose->registration_rms_mm, pose->latency_ms, pose->reason.c_str());
    std::fflush(stdout);
    ++received;
  }
};

[[noreturn]] void usage(const std::string& reason) {
  std::fprintf(stderr, "pose_subscriber: %s (options: --url URL, --count N, --timeout-s S)\n",
               reason.c_str());
  std::exit(2);
}

}  // namespace

int main(int argc, char** argv) {
  std::string url;
  long count = -1;
  double timeout_s = -1;
  for (int i = 1; i < argc; i += 2) {
    const std::string option = argv[i];
    if (i + 1 >= argc) usage(option + " needs a value");
    const std::string value = argv[i + 1];
    char* end = nullptr;
    if (option == "--url") {
      url = value;
    } else if (option == "--count") {
      count = std::strtol(value.c_str(), &end, 10);
    } else if (option == "--timeout-s") {
      timeout_s = std::strtod(value.c_str(), &end);
    } else {
      usage("unknown option " + option);
    }
    if (end != nullptr && (*end != '\0' || end == value.c_str()))
      usage(option + " '" + value + "': not a number");
  }

  lcm::LCM lcm(url);
  if (!lcm.good()) {
    std::fprintf(stderr, "pose_subscriber: LCM URL '%s': cannot open\n",
                 url.empty() ? "(default)" : url.c_str());
    return 1;
  }
  PosePrinter printer;
  lcm.subscribe(kPoseChannel, &PosePrinter::on_pose, &printer);
  std::fprintf(stderr, "pose_subscriber: listening on %s\n", kPoseChannel);

  const auto deadline = std::chrono::steady_clock::now() +
                        std::chrono::duration<double>(timeout_s < 0 ? 1e9 : timeout_s);
  while (count < 0 || printer.received < count) {
    if (std::chrono::steady_clock::now() >= deadline) {
      std::fprintf(stderr, "pose_subscriber: %ld of %ld poses within %g s\n", printer.received,
                   count, timeout_s);
      return 1;
    }
    if (lcm.handleTimeout(100) < 0) {
      std::fprintf(stderr, "pose_subscriber: LCM receive failed\n");
      return 1;
    }
  }
  return 0;
}
