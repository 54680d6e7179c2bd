#include "realtime/config/hardware_config.hpp"

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "core/input_error.hpp"
#include "core/io/yaml_input_errors.hpp"
#include "core/io/yaml_section_reader.hpp"
#include "firmware_bridge/pixel_format.hpp"
#include "firmware_bridge/v4l2_camera.hpp"

namespace cosmos {
namespace {

namespace fs = std::filesystem;

constexpr int kMaxLineOffset = 65535;
constexpr std::int64_t kMaxMicroseconds = 10'000'000;
constexpr std::int64_t kNanosecondsPerMicrosecond = 1000;

// One of `choices` (text), stored as its index in the enum.
template <class Enum>
void read_choice(YamlSectionReader& section, const std::string& key,
                 const std::vector<std::string>& choices, Enum& field) {
  const YAML::Node node = section.value(key);
  if (!node.IsDefined()) return;
  for (std::size_t i = 0; i < choices.size(); ++i) {
    if (node.IsScalar() && node.Scalar() == choices[i]) {
      field = static_cast<Enum>(i);
      return;
    }
  }
  std::string list;
  for (const std::string& choice : choices) list += (list.empty() ? "" : " or ") + choice;
  section.fail(key, "expected " + list + ", got " + describe_yaml_node(node));
}

void read_microseconds_as_ns(YamlSectionReader& section, const std::string& key,
                             std::int64_t& field_ns) {
  std::int64_t value_us = field_ns / kNanosecondsPerMicrosecond;
  section.read(key, value_us, 0, kMaxMicroseconds);
  field_ns = value_us * kNanosecondsPerMicrosecond;
}

// A GPIO line: a name (`ENC_A`), an offset (`17`) or {name | offset, active_low}.
void read_line(const YamlInputErrors& errors, YamlSectionReader& section, const std::string& key,
               GpioLineRef& ref) {
  const YAML::Node node = section.value(key);
  if (!node.IsDefined()) return;
  if (node.IsScalar()) {
    int offset = 0;
    if (YAML::convert<int>::decode(node, offset)) {
      if (offset < 0 || offset > kMaxLineOffset) {
        section.fail(key, "a line offset must be in [0, " + std::to_string(kMaxLineOffset) +
                              "], got " + node.Scalar());
      }
      ref.offset = offset;
    } else {
      section.read(key, ref.name);
    }
    return;
  }
  YamlSectionReader line(errors, node, section.dotted(key));
  if (line.has("name") == line.has("offset")) section.fail(key, "give one of name and offset");
  line.read("name", ref.name);
  line.read("offset", ref.offset, 0, kMaxLineOffset);
  line.read("active_low", ref.active_low);
  line.reject_unknown_keys();
}

void read_camera(YamlSectionReader& section, HardwareConfig& config) {
  CameraConfig& camera = config.camera;
  section.read("device", camera.device);
  if (section.has("pixel_format")) {
    std::string name;
    section.read("pixel_format", name);
    const auto format = parse_pixel_format(name);
    if (!format) section.fail("pixel_format", "expected GREY, Y10, Y12 or Y16, got '" + name + "'");
    camera.pixel_format = *format;
  }
  section.read("width", camera.width_px, 16, 8192);
  section.read("height", camera.height_px, 1, 8192);
  section.read("roi_top", camera.roi_top_px, 0, 8191);
  section.read("roi_left", camera.roi_left_px, 0, 8191);
  section.read("exposure_us", camera.exposure_us, 0, static_cast<int>(kMaxMicroseconds));
  section.read("gain", camera.gain, 0, 1'000'000);
  section.read("buffer_count", camera.buffer_count, 2, V4l2Camera::kMaxBuffers);
  section.read("frame_timeout_us", config.frame_timeout_us, 100, kMaxMicroseconds);
  section.reject_unknown_keys();
}

constexpr const char* kLineKeys[] = {"encoder_a",    "encoder_b",      "photo_eye",
                                     "laser_enable", "camera_trigger", "result_ready"};

void read_gpio(const YamlInputErrors& errors, YamlSectionReader& section, GpioConfig& gpio) {
  section.read("chip", gpio.chip);
  section.read("consumer", gpio.consumer);
  const bool simulated = gpio.chip == kSimulatedDevice;
  if (simulated) {
    for (const char* key : kLineKeys) {
      if (section.has(key)) {
        section.fail(key,
                     "the simulated chip has every line (encoder A and B, photo eye, "
                     "laser_enable, camera_trigger, result_ready): remove the key");
      }
    }
  }
  read_line(errors, section, "encoder_a", gpio.encoder_a);
  read_line(errors, section, "encoder_b", gpio.encoder_b);
  read_line(errors, section, "photo_eye", gpio.photo_eye);
  read_line(errors, section, "laser_enable", gpio.laser_enable);
  read_line(errors, section, "camera_trigger", gpio.camera_trigger);
  read_line(errors, section, "result_ready", gpio.result_ready);
  read_choice(section, "encoder_mode", {"quadrature", "step"}, gpio.encoder_mode);
  read_microseconds_as_ns(section, "debounce_us", gpio.encoder_debounce_ns);
  read_microseconds_as_ns(section, "photo_eye_debounce_us", gpio.photo_eye_debounce_ns);
  read_microseconds_as_ns(section, "photo_eye_min_on_us", gpio.photo_eye_min_on_ns);
  read_microseconds_as_ns(section, "photo_eye_min_off_us", gpio.photo_eye_min_off_ns);
  section.reject_unknown_keys();
  if (simulated) return;
  if (!gpio.encoder_a.configured())
    section.fail("encoder_a", "missing: the conveyor encoder's line");
  if (gpio.encoder_mode == EncoderMode::kQuadrature && !gpio.encoder_b.configured()) {
    section.fail("encoder_b", "missing: quadrature decoding needs lines A and B");
  }
}

void read_stripe(YamlSectionReader& section, PixelFormat format,
                 StripeExtractionParameters& stripe) {
  const int full_scale = (1 << significant_bits(format)) - 1;
  // The defaults are 8-bit grey levels: the same fractions of a deeper format's full scale.
  const auto scaled = [full_scale](int level) {
    return static_cast<int>(std::lround(static_cast<double>(level) * full_scale / 255.0));
  };
  stripe.threshold = scaled(stripe.threshold);
  stripe.min_peak_intensity = scaled(stripe.min_peak_intensity);
  stripe.saturation_level = full_scale;
  read_choice(section, "method", {"centre_of_gravity", "gaussian_three_point"}, stripe.method);
  section.read("threshold", stripe.threshold, 0, full_scale - 1);
  section.read("min_peak_intensity", stripe.min_peak_intensity, 1, full_scale);
  section.read("window_half_width_px", stripe.window_half_width_px, 1, 64);
  section.reject_unknown_keys();
  if (stripe.min_peak_intensity <= stripe.threshold) {
    section.fail(section.has("min_peak_intensity") ? "min_peak_intensity" : "threshold",
                 "min_peak_intensity (" + std::to_string(stripe.min_peak_intensity) +
                     ") must exceed threshold (" + std::to_string(stripe.threshold) + ")");
  }
}

YAML::Node load_root(const YamlInputErrors& errors) {
  const YAML::Node root = errors.load_file("hardware config");
  if (!root.IsMap()) {
    errors.fail_line(root.Mark().line, "hardware", "expected the sections camera, gpio, stripe");
  }
  std::set<std::string> seen;
  for (const auto& item : root) {
    const std::string key = item.first.IsScalar() ? item.first.Scalar() : "?";
    if (key != "camera" && key != "gpio" && key != "stripe") {
      errors.fail(item.first, key, "unknown section (known: camera, gpio, stripe)");
    }
    if (!seen.insert(key).second) errors.fail(item.first, key, "section given twice");
  }
  if (!std::as_const(root)["gpio"].IsDefined()) {
    errors.fail_line(-1, "gpio", "missing section: the encoder's lines are required");
  }
  return root;
}

}  // namespace

HardwareConfig read_hardware_config(const fs::path& yaml_path) {
  const YamlInputErrors errors(yaml_path);
  const YAML::Node root = load_root(errors);
  HardwareConfig config;
  config.file = yaml_path;
  YamlSectionReader camera(errors, root["camera"], "camera");
  read_camera(camera, config);
  YamlSectionReader gpio(errors, root["gpio"], "gpio");
  read_gpio(errors, gpio, config.gpio);
  YamlSectionReader stripe(errors, root["stripe"], "stripe");
  read_stripe(stripe, config.camera.pixel_format, config.stripe);
  if (config.camera_simulated() && !config.gpio_simulated()) {
    gpio.fail("chip",
              "camera.device is simulated, so gpio.chip must be too: the simulated camera's "
              "conveyor moves no real encoder");
  }
  if (config.gpio_simulated() && !config.camera_simulated()) {
    camera.fail("device",
                "gpio.chip is simulated, so camera.device must be too: the simulated encoder "
                "follows the simulated camera's conveyor, not a real one");
  }
  return config;
}

}  // namespace cosmos
