#include "tests/hil/lifecycle_probe.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "firmware_bridge/v4l2_camera.hpp"
#include "tests/hil/v4l2_node.hpp"

namespace cosmos::hil {
namespace {

namespace fs = std::filesystem;

int open_fds() {
  int count = 0;
  for ([[maybe_unused]] const fs::directory_entry& entry : fs::directory_iterator("/proc/self/fd"))
    ++count;
  return count;
}

// The process's mappings of the device node (its mmap'ed buffers).
int device_mappings(const std::string& device) {
  std::ifstream maps("/proc/self/maps");
  std::string line;
  int count = 0;
  while (std::getline(maps, line)) count += line.find(device) != std::string::npos ? 1 : 0;
  return count;
}

std::string status_text(const V4l2Camera& camera) {
  return std::string(camera.last_error().empty() ? "ok" : camera.last_error());
}

// One run of the lifecycle, `frames` frames dequeued and requeued; "" or what went wrong.
std::string run_once(V4l2Camera& camera, const std::string& device, int frames,
                     int& mappings_streaming, int& buffers) {
  const struct {
    CameraStatus (V4l2Camera::*step)();
    const char* name;
  } steps[] = {{&V4l2Camera::open, "open"},
               {&V4l2Camera::set_format, "set_format"},
               {&V4l2Camera::allocate_buffers, "allocate_buffers"},
               {&V4l2Camera::stream_on, "stream_on"}};
  for (const auto& step : steps) {
    if ((camera.*step.step)() != CameraStatus::kOk)
      return std::string(step.name) + ": " + status_text(camera);
  }
  mappings_streaming = device_mappings(device);
  buffers = camera.buffer_count();
  for (int got = 0; got < frames;) {
    FrameView frame;
    const CameraStatus status = camera.next_frame(1'000'000, frame);
    if (status == CameraStatus::kNoFrame) continue;
    if (status != CameraStatus::kOk) return "next_frame: " + status_text(camera);
    if (camera.release_frame(frame) != CameraStatus::kOk)
      return "release_frame: " + status_text(camera);
    ++got;
  }
  if (camera.stream_off() != CameraStatus::kOk) return "stream_off: " + status_text(camera);
  // A restart without closing: the buffers are queued again and frames come.
  if (camera.stream_on() != CameraStatus::kOk) return "stream_on again: " + status_text(camera);
  FrameView frame;
  CameraStatus status = CameraStatus::kNoFrame;
  while (status == CameraStatus::kNoFrame) status = camera.next_frame(1'000'000, frame);
  if (status != CameraStatus::kOk) return "next_frame after restart: " + status_text(camera);
  camera.release_frame(frame);
  if (camera.stream_off() != CameraStatus::kOk) return "stream_off: " + status_text(camera);
  if (camera.release_buffers() != CameraStatus::kOk)
    return "release_buffers: " + status_text(camera);
  if (camera.close() != CameraStatus::kOk) return "close: " + status_text(camera);
  return "";
}

}  // namespace

std::vector<ProbeCheck> probe_lifecycle(const CameraConfig& config) {
  std::vector<ProbeCheck> checks;
  V4l2Camera camera(config);
  const int fds_before = open_fds();
  const int maps_before = device_mappings(config.device);
  int fds_after[2] = {0, 0}, maps_after[2] = {0, 0}, maps_streaming[2] = {0, 0}, buffers = 0;
  std::string failure;
  for (int run = 0; run < 2 && failure.empty(); ++run) {
    failure = run_once(camera, config.device, 10, maps_streaming[run], buffers);
    fds_after[run] = open_fds();
    maps_after[run] = device_mappings(config.device);
  }
  const CameraStats stats = camera.stats();
  const bool ok = failure.empty() && fds_after[0] == fds_before && fds_after[1] == fds_before &&
                  maps_after[0] == maps_before && maps_after[1] == maps_before &&
                  maps_streaming[0] == buffers && buffers > 0 &&
                  maps_streaming[1] == maps_streaming[0] &&
                  camera.state() == V4l2Camera::State::kClosed;
  checks.push_back(check_line(
      ok,
      "lifecycle twice on %s: open, format, %d buffers, stream on, 10 frames dequeued and "
      "requeued, stream off, on again, off, release, close%s%s; file descriptors %d before, %d "
      "and %d after; buffer mappings %d while streaming, %d and %d after; %llu frames",
      config.device.c_str(), maps_streaming[0], failure.empty() ? "" : ": failed at ",
      failure.c_str(), fds_before, fds_after[0], fds_after[1], maps_streaming[0], maps_after[0],
      maps_after[1], static_cast<unsigned long long>(stats.frames)));
  return checks;
}

std::vector<ProbeCheck> probe_formats(const CameraConfig& config) {
  std::vector<ProbeCheck> checks;
  std::string offered;
  {
    V4l2Node node(config.device);
    offered = node.enumerated_formats(V4L2_BUF_TYPE_VIDEO_CAPTURE);
  }
  checks.push_back(info_line("formats: %s offers %s", config.device.c_str(), offered.c_str()));
  std::string taken, refused;
  for (const PixelFormat format :
       {PixelFormat::kGrey8, PixelFormat::kY10, PixelFormat::kY12, PixelFormat::kY16}) {
    CameraConfig wanted = config;
    wanted.pixel_format = format;
    V4l2Camera camera(wanted);
    const bool ok = camera.open() == CameraStatus::kOk && camera.set_format() == CameraStatus::kOk;
    (ok ? taken : refused) +=
        std::string(taken.empty() || !ok ? "" : " ") + pixel_format_name(format);
    if (!ok) refused += " (" + status_text(camera) + ") ";
  }
  checks.push_back(check_line(refused.empty(),
                              "formats: the camera's pixel formats taken "
                              "unchanged: %s%s%s",
                              taken.c_str(),
                              refused.empty() ? "" : "; refused: ", refused.c_str()));
  // What the driver cannot give: a frame wider than its input, a ROI below the last row.
  CameraConfig too_wide = config;
  too_wide.width_px = 1296;
  too_wide.roi_left_px = 0;
  CameraConfig too_low = config;
  too_low.roi_top_px = 400;
  for (const auto& [wanted, what] : {std::pair{too_wide, "1296 columns of a 1280-column input"},
                                     std::pair{too_low, "512 rows from row 400 of 720"}}) {
    V4l2Camera camera(wanted);
    const bool opened = camera.open() == CameraStatus::kOk;
    const bool refused_it = opened && camera.set_format() == CameraStatus::kError;
    const std::string line = status_text(camera);
    const bool one_line =
        line.find('\n') == std::string::npos && line.rfind(wanted.device + ": ", 0) == 0;
    checks.push_back(
        check_line(refused_it && one_line, "formats: %s refused: %s", what, line.c_str()));
  }
  return checks;
}

}  // namespace cosmos::hil
