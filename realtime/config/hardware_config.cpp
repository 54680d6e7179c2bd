#include "realtime/config/hardware_config.hpp"

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <set>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "core/input_error.hpp"
#include "core/io/yaml_input_errors.hpp"
#include "core/io/yaml_parameter_reader.hpp"
#include "core/io/yaml_section_reader.hpp"
#include "firmware_bridge/pixel_format.hpp"
#include "firmware_bridge/v4l2_camera.hpp"

namespace cosmos {
namespace {

namespace fs = std::filesystem;

constexpr int kMaxLineOffset = 65535;
static_assert(kMaxCameraBuffers == V4l2Camera::kMaxBuffers);

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

// read_yaml_parameters with one more field type, the GPIO line (a name, an offset or a map),
// which a simulated chip refuses: it has every line.
class GpioSectionReader {
 public:
  GpioSectionReader(const YamlInputErrors& errors, YamlSectionReader& section,
                    const GpioConfig& gpio)
      : errors_(errors), section_(section), gpio_(gpio), fields_(section) {}

  template <class T>
  void operator()(const char* key, T& field, const char* description, const Range& range = {}) {
    if constexpr (std::is_same_v<T, GpioLineRef>) {
      if (gpio_.chip == kSimulatedDevice && section_.has(key)) {
        section_.fail(key,
                      "the simulated chip has every line (encoder A and B, photo eye, "
                      "laser_enable, result_ready): remove the key");
      }
      read_line(errors_, section_, key, field);
    } else {
      fields_(key, field, description, range);
    }
  }
  template <class T>
  void fields(T& nested) {
    visit_parameters(*this, nested);
  }
  void retired(const char* key, const char* replacement) { fields_.retired(key, replacement); }

 private:
  const YamlInputErrors& errors_;
  YamlSectionReader& section_;
  const GpioConfig& gpio_;  // its chip is read before its lines
  YamlParameterReader fields_;
};

void read_gpio(const YamlInputErrors& errors, YamlSectionReader& section, GpioConfig& gpio) {
  GpioSectionReader reader(errors, section, gpio);
  visit_parameters(reader, gpio);
  section.reject_unknown_keys();
  if (gpio.chip == kSimulatedDevice) return;
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
  read_yaml_parameters(section, stripe);
  // The declared ranges are a 16-bit frame's; this format's full scale bounds them further.
  const auto within_full_scale = [&](const char* key, int value, int low, int high) {
    if (value < low || value > high)
      section.fail(key, "must be in [" + std::to_string(low) + ", " + std::to_string(high) +
                            "] for " + std::string(pixel_format_name(format)) + ", got " +
                            std::to_string(value));
  };
  within_full_scale("threshold", stripe.threshold, 0, full_scale - 1);
  within_full_scale("min_peak_intensity", stripe.min_peak_intensity, 1, full_scale);
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
    if (key != "camera" && key != "gpio" && key != "stripe" && key != "calibration") {
      errors.fail(item.first, key, "unknown section (known: camera, gpio, stripe, calibration)");
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
  HardwareCameraSection camera_keys = camera_section(config);
  read_yaml_parameters(camera, camera_keys);
  YamlSectionReader gpio(errors, root["gpio"], "gpio");
  read_gpio(errors, gpio, config.gpio);
  YamlSectionReader stripe(errors, root["stripe"], "stripe");
  read_stripe(stripe, config.camera.pixel_format, config.stripe);
  YamlSectionReader calibration(errors, root["calibration"], "calibration");
  read_yaml_parameters(calibration, config.calibration);
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
