#include "tests/hil/loop_probe.hpp"

#include <cstdint>
#include <cstdio>
#include <exception>

#include "firmware_bridge/v4l2_camera.hpp"
#include "tests/hil/output_stream.hpp"

namespace cosmos::hil {
namespace {

// A pattern in which every row, column and frame differs, within the format's bits.
std::uint32_t pattern(int row, int column, int frame, int bits) {
  const auto value = static_cast<std::uint32_t>(row * 131 + column * 7 + frame * 29);
  return value & ((1u << bits) - 1u);
}

void write_pattern(std::uint8_t* data, const OutputFormat& format, PixelFormat pixel_format,
                   int frame) {
  const int bits = significant_bits(pixel_format);
  for (int r = 0; r < format.height_px; ++r) {
    std::uint8_t* row = data + static_cast<std::ptrdiff_t>(r) * format.bytes_per_line;
    for (int c = 0; c < format.width_px; ++c) {
      const std::uint32_t value = pattern(r, c, frame, bits);
      if (bytes_per_pixel(pixel_format) == 1) {
        row[c] = static_cast<std::uint8_t>(value);
      } else {
        row[2 * c] = static_cast<std::uint8_t>(value & 0xff);
        row[2 * c + 1] = static_cast<std::uint8_t>(value >> 8);
      }
    }
  }
}

std::int64_t differing_samples(const FrameView& frame, const std::uint8_t* written,
                               const OutputFormat& format) {
  std::int64_t differing = 0;
  const int bytes = frame.bytes_per_pixel();
  for (int r = 0; r < frame.height_px; ++r) {
    const std::uint8_t* got = frame.row(r);
    const std::uint8_t* want =
        written + static_cast<std::ptrdiff_t>(frame.roi_top_px + r) * format.bytes_per_line +
        static_cast<std::ptrdiff_t>(frame.roi_left_px) * bytes;
    for (int c = 0; c < frame.width_px * bytes; c += bytes) {
      bool same = got[c] == want[c];
      if (bytes == 2) same = same && got[c + 1] == want[c + 1];
      differing += same ? 0 : 1;
    }
  }
  return differing;
}

}  // namespace

LoopProbeResult probe_loop(const std::string& output_node, CameraConfig camera,
                           VividLoopSettings loop, PixelFormat format, int frames) {
  LoopProbeResult result;
  char line[512];
  const char* name = pixel_format_name(format);
  try {
    V4l2Node capture(camera.device);
    V4l2Node output(output_node);
    loop.pixel_format = format;
    const OutputFormat written = configure_vivid_loop(capture, output, loop);
    OutputStream stream(output, 2);
    write_pattern(stream.data(0), written, format, 0);
    stream.queue(0, written.size_bytes);
    stream.stream_on();

    camera.pixel_format = format;
    V4l2Camera cell_camera(camera);
    if (cell_camera.start() != CameraStatus::kOk) {
      std::snprintf(line, sizeof line, "loop %s: camera start failed: %.*s", name,
                    static_cast<int>(cell_camera.last_error().size()),
                    cell_camera.last_error().data());
      result.line = line;
      return result;
    }
    std::int64_t differing = 0;
    int compared = 0;
    while (compared < frames) {
      FrameView frame;
      const CameraStatus status = cell_camera.next_frame(1'000'000, frame);
      if (status == CameraStatus::kNoFrame) continue;
      if (status != CameraStatus::kOk) {
        std::snprintf(line, sizeof line, "loop %s: frame %d: %.*s", name, compared,
                      static_cast<int>(cell_camera.last_error().size()),
                      cell_camera.last_error().data());
        result.line = line;
        return result;
      }
      differing += differing_samples(frame, stream.data(0), written);
      cell_camera.release_frame(frame);
      ++compared;
    }
    cell_camera.stop();
    result.ok = differing == 0;
    std::snprintf(line, sizeof line,
                  "loop %s: %d frames of %dx%d at ROI (%d, %d) through V4l2Camera, %lld samples "
                  "differ from the output's (output %dx%d at %.1f Hz, capture %.1f Hz)",
                  name, compared, camera.width_px, camera.height_px, camera.roi_top_px,
                  camera.roi_left_px, static_cast<long long>(differing), written.width_px,
                  written.height_px, written.output_rate_hz, written.capture_rate_hz);
    result.line = line;
  } catch (const std::exception& error) {
    result.line = std::string("loop ") + name + ": " + error.what();
  }
  return result;
}

}  // namespace cosmos::hil
