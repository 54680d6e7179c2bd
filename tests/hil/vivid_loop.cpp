#include "tests/hil/vivid_loop.hpp"

#include <linux/v4l2-dv-timings.h>

#include <array>
#include <stdexcept>

#include "firmware_bridge/v4l2_fourcc.hpp"

namespace cosmos::hil {
namespace {

// The kernel's preset macros leave their trailing fields to zero-initialization.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
const std::array<DvTimingsPreset, 7> kPresets = {{
    {"1280x720p24", V4L2_DV_BT_CEA_1280X720P24},
    {"1280x720p25", V4L2_DV_BT_CEA_1280X720P25},
    {"1280x720p30", V4L2_DV_BT_CEA_1280X720P30},
    {"1280x720p50", V4L2_DV_BT_CEA_1280X720P50},
    {"1280x720p60", V4L2_DV_BT_CEA_1280X720P60},
    {"1280x768p60", V4L2_DV_BT_DMT_1280X768P60},
    {"1280x768p120rb", V4L2_DV_BT_DMT_1280X768P120_RB},
}};
#pragma GCC diagnostic pop

}  // namespace

v4l2_dv_timings dv_timings_preset(const std::string& name) {
  std::string known;
  for (const DvTimingsPreset& preset : kPresets) {
    if (name == preset.name) return preset.timings;
    known += known.empty() ? "" : ", ";
    known += preset.name;
  }
  throw std::runtime_error("unknown DV timings \"" + name + "\" (known: " + known + ")");
}

double frame_rate_hz(const v4l2_dv_timings& timings) {
  const v4l2_bt_timings& bt = timings.bt;
  const double total = static_cast<double>(V4L2_DV_BT_FRAME_WIDTH(&bt)) *
                       static_cast<double>(V4L2_DV_BT_FRAME_HEIGHT(&bt));
  return static_cast<double>(bt.pixelclock) / total;
}

OutputFormat configure_vivid_loop(const V4l2Node& capture, const V4l2Node& output,
                                  const VividLoopSettings& settings) {
  v4l2_dv_timings capture_timings = dv_timings_preset(settings.capture_timings);
  v4l2_dv_timings output_timings = dv_timings_preset(settings.output_timings);
  if (capture_timings.bt.width != output_timings.bt.width ||
      capture_timings.bt.height != output_timings.bt.height) {
    throw std::runtime_error("vivid loops only equal frame sizes: capture " +
                             settings.capture_timings + ", output " + settings.output_timings);
  }
  capture.call(VIDIOC_S_DV_TIMINGS, &capture_timings, "VIDIOC_S_DV_TIMINGS (capture)");
  output.call(VIDIOC_S_DV_TIMINGS, &output_timings, "VIDIOC_S_DV_TIMINGS (output)");
  capture.set_control("Loop Video", 1);
  capture.set_control("OSD Text Mode", 2);  // 2: no text drawn into the frames

  v4l2_format format{};
  format.type = V4L2_BUF_TYPE_VIDEO_OUTPUT;
  format.fmt.pix.width = output_timings.bt.width;
  format.fmt.pix.height = output_timings.bt.height;
  format.fmt.pix.pixelformat = fourcc_of(settings.pixel_format);
  format.fmt.pix.field = V4L2_FIELD_NONE;
  output.call(VIDIOC_S_FMT, &format, "VIDIOC_S_FMT (output)");
  if (format.fmt.pix.pixelformat != fourcc_of(settings.pixel_format) ||
      format.fmt.pix.width != output_timings.bt.width ||
      format.fmt.pix.height != output_timings.bt.height) {
    throw std::runtime_error(output.path() + ": VIDIOC_S_FMT: the output took " +
                             fourcc_text(format.fmt.pix.pixelformat) + " " +
                             std::to_string(format.fmt.pix.width) + "x" +
                             std::to_string(format.fmt.pix.height));
  }
  OutputFormat result;
  result.width_px = static_cast<int>(format.fmt.pix.width);
  result.height_px = static_cast<int>(format.fmt.pix.height);
  result.bytes_per_line = static_cast<int>(format.fmt.pix.bytesperline);
  result.size_bytes = format.fmt.pix.sizeimage;
  result.capture_rate_hz = frame_rate_hz(capture_timings);
  result.output_rate_hz = frame_rate_hz(output_timings);
  return result;
}

}  // namespace cosmos::hil
