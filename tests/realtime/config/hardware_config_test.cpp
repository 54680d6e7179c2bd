// The hardware YAML: the shipped example reads into the camera, GPIO and stripe settings it
// shows, and every bad key, type and range is one line `file:LINE: section.key: reason`.
#include "realtime/config/hardware_config.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/input_error.hpp"
#include "tests/common/config_file_test.hpp"

namespace cosmos {
namespace {

namespace fs = std::filesystem;

class HardwareConfigTest : public testing::ConfigFileTest {
 protected:
  HardwareConfigTest() : ConfigFileTest("hw.yaml") {}
  std::string error_of(const std::string& text) const {
    return error_when_loading(text, [](const fs::path& file) { read_hardware_config(file); });
  }

  std::string at(int line) const { return path().string() + ":" + std::to_string(line); }
};

constexpr char kMinimalGpio[] = "gpio:\n  encoder_a: ENC_A\n  encoder_b: 5\n";

TEST_F(HardwareConfigTest, TheExampleFileReadsAsItReads) {
  const fs::path example = fs::path(COSMOS_SOURCE_DIR) / "config" / "hardware-example.yaml";
  const HardwareConfig config = read_hardware_config(example);
  EXPECT_EQ(config.file, example);
  EXPECT_EQ(config.camera.device, "/dev/video0");
  EXPECT_EQ(config.camera.pixel_format, PixelFormat::kGrey8);
  EXPECT_EQ(config.camera.width_px, 1280);
  EXPECT_EQ(config.camera.height_px, 256);
  EXPECT_EQ(config.camera.roi_top_px, 384);
  EXPECT_EQ(config.camera.roi_left_px, 0);
  EXPECT_EQ(config.camera.exposure_us, 400);
  EXPECT_EQ(config.camera.gain, 4);
  EXPECT_EQ(config.camera.buffer_count, 4);
  EXPECT_EQ(config.frame_timeout_us, 100'000);
  EXPECT_EQ(config.gpio.chip, "gpiochip0");
  EXPECT_EQ(config.gpio.encoder_a.name, "ENC_A");
  EXPECT_EQ(config.gpio.encoder_b.name, "ENC_B");
  EXPECT_EQ(config.gpio.encoder_mode, EncoderMode::kQuadrature);
  EXPECT_TRUE(config.gpio.photo_eye.name.empty());
  EXPECT_EQ(config.gpio.photo_eye.offset, 17);
  EXPECT_EQ(config.gpio.laser_enable.name, "LASER_EN");
  EXPECT_EQ(config.gpio.result_ready.name, "RESULT_RDY");
  EXPECT_EQ(config.gpio.encoder_debounce_ns(), 2000);
  EXPECT_EQ(config.gpio.photo_eye_debounce_ns(), 1'000'000);
  EXPECT_EQ(config.stripe.threshold, 20);
  EXPECT_EQ(config.stripe.min_peak_intensity, 40);
  EXPECT_EQ(config.stripe.saturation_level, 255);
}

TEST_F(HardwareConfigTest, LinesStripeAndDeepPixelFormats) {
  const HardwareConfig config = read_hardware_config(
      write("camera:\n  pixel_format: Y12\n  frame_timeout_us: 5000\n"
            "gpio:\n  encoder_a: {offset: 3, active_low: true}\n  encoder_mode: step\n"
            "  photo_eye: {name: EYE}\n  photo_eye_min_off_us: 7\n"
            "stripe:\n  method: gaussian_three_point\n  window_half_width_px: 5\n"));
  EXPECT_EQ(config.camera.pixel_format, PixelFormat::kY12);
  EXPECT_EQ(config.frame_timeout_us, 5000);
  EXPECT_EQ(config.gpio.encoder_a.offset, 3);
  EXPECT_TRUE(config.gpio.encoder_a.active_low);
  EXPECT_FALSE(config.gpio.encoder_b.configured());  // step mode needs no B line
  EXPECT_EQ(config.gpio.encoder_mode, EncoderMode::kStep);
  EXPECT_EQ(config.gpio.photo_eye.name, "EYE");
  EXPECT_FALSE(config.gpio.photo_eye.active_low);
  EXPECT_EQ(config.gpio.photo_eye_min_off_ns(), 7000);
  EXPECT_EQ(config.stripe.method, StripePeakMethod::kGaussianThreePoint);
  EXPECT_EQ(config.stripe.window_half_width_px, 5);
  // 8-bit defaults 20 and 40 of 255, as the same fractions of 4095.
  EXPECT_EQ(config.stripe.threshold, 321);
  EXPECT_EQ(config.stripe.min_peak_intensity, 642);
  EXPECT_EQ(config.stripe.saturation_level, 4095);
}

TEST_F(HardwareConfigTest, TheSimulatedTwinsFileReadsAsItReads) {
  const fs::path file = fs::path(COSMOS_SOURCE_DIR) / "config" / "hardware-sim.yaml";
  const HardwareConfig config = read_hardware_config(file);
  EXPECT_TRUE(config.camera_simulated());
  EXPECT_TRUE(config.gpio_simulated());
  EXPECT_EQ(config.camera.pixel_format, PixelFormat::kGrey8);
  EXPECT_EQ(config.camera.width_px, 1280);
  EXPECT_EQ(config.camera.height_px, 512);
  EXPECT_EQ(config.camera.roi_top_px, 51);
  EXPECT_EQ(config.camera.roi_left_px, 0);
  EXPECT_EQ(config.gpio.encoder_mode, EncoderMode::kQuadrature);
  EXPECT_FALSE(config.gpio.encoder_a.configured());  // the simulated chip names no lines
  EXPECT_EQ(config.gpio.encoder_debounce_ns(), 2000);
  EXPECT_EQ(config.stripe.method, StripePeakMethod::kCentreOfGravity);
  EXPECT_EQ(config.stripe.threshold, 20);
  EXPECT_EQ(config.stripe.min_peak_intensity, 43);
  EXPECT_EQ(config.stripe.window_half_width_px, 7);
}

TEST_F(HardwareConfigTest, HalfSimulatedFilesAndLinesOfTheSimulatedChipAreRefused) {
  EXPECT_EQ(error_of("camera:\n  device: simulated\n" + std::string(kMinimalGpio)),
            at(4) +
                ": gpio.chip: camera.device is simulated, so gpio.chip must be too: the "
                "simulated camera's conveyor moves no real encoder");
  EXPECT_EQ(error_of("camera:\n  device: /dev/video0\ngpio:\n  chip: simulated\n"),
            at(2) +
                ": camera.device: gpio.chip is simulated, so camera.device must be too: the "
                "simulated encoder follows the simulated camera's conveyor, not a real one");
  EXPECT_EQ(error_of("camera:\n  device: simulated\ngpio:\n  chip: simulated\n"
                     "  photo_eye: 17\n"),
            at(5) +
                ": gpio.photo_eye: the simulated chip has every line (encoder A and B, photo "
                "eye, laser_enable, result_ready): remove the key");
  const HardwareConfig both = read_hardware_config(
      write("camera:\n  device: simulated\ngpio:\n  chip: simulated\n  encoder_mode: step\n"));
  EXPECT_TRUE(both.camera_simulated());
  EXPECT_EQ(both.gpio.encoder_mode, EncoderMode::kStep);
}

TEST_F(HardwareConfigTest, BadKeysTypesAndRangesNameFileLineAndKey) {
  const std::string gpio = kMinimalGpio;
  EXPECT_EQ(error_of("camera:\n  widht: 640\n" + gpio),
            at(2) +
                ": camera.widht: unknown key (known: buffer_count, device, exposure_us, "
                "frame_timeout_us, gain, height, pixel_format, roi_left, roi_top, width)");
  EXPECT_EQ(error_of("camera:\n  width: wide\n" + gpio),
            at(2) + ": camera.width: expected an integer, got 'wide'");
  EXPECT_EQ(error_of("camera:\n  height: 0\n" + gpio),
            at(2) + ": camera.height: must be in [1, 8192], got 0");
  EXPECT_EQ(error_of("camera:\n  buffer_count: 40\n" + gpio),
            at(2) + ": camera.buffer_count: must be in [2, 16], got 40");
  EXPECT_EQ(error_of("camera:\n  pixel_format: RGB3\n" + gpio),
            at(2) + ": camera.pixel_format: expected GREY, Y10, Y12 or Y16, got 'RGB3'");
  EXPECT_EQ(error_of(gpio + "  encoder_mode: gray\n"),
            at(4) + ": gpio.encoder_mode: expected quadrature or step, got 'gray'");
  EXPECT_EQ(error_of(gpio + "  photo_eye: -2\n"),
            at(4) + ": gpio.photo_eye: a line offset must be in [0, 65535], got -2");
  EXPECT_EQ(error_of(gpio + "  photo_eye: {name: EYE, offset: 4}\n"),
            at(4) + ": gpio.photo_eye: give one of name and offset");
  EXPECT_EQ(error_of(gpio + "  photo_eye: {name: EYE, active_low: maybe}\n"),
            at(4) + ": gpio.photo_eye.active_low: expected true or false, got 'maybe'");
  EXPECT_EQ(error_of("gpio:\n  encoder_a: ENC_A\n"),
            at(2) + ": gpio.encoder_b: missing: quadrature decoding needs lines A and B");
  EXPECT_EQ(
      error_of("camera:\n  device: /dev/video2\n"),
      (dir_ / "hw.yaml").string() + ": gpio: missing section: the encoder's lines are required");
  EXPECT_EQ(error_of(gpio + "stripe:\n  threshold: 60\n"),
            at(5) + ": stripe.threshold: min_peak_intensity (40) must exceed threshold (60)");
  EXPECT_EQ(error_of(gpio + "stripe:\n  threshold: 255\n"),
            at(5) + ": stripe.threshold: must be in [0, 254] for GREY, got 255");
  // The camera runs free: an old file's trigger line is a key the section does not have.
  EXPECT_EQ(error_of(gpio + "  camera_trigger: CAM_TRIG\n"),
            at(4) +
                ": gpio.camera_trigger: unknown key (known: chip, consumer, debounce_us, "
                "encoder_a, encoder_b, encoder_mode, frame_edges_wait_us, laser_enable, "
                "photo_eye, photo_eye_debounce_us, photo_eye_min_off_us, photo_eye_min_on_us, "
                "result_ready)");
  EXPECT_EQ(error_of(gpio + "lights: on\n"),
            at(4) + ": lights: unknown section (known: camera, gpio, stripe, calibration)");
  EXPECT_EQ(error_of("camera: [1, 2]\n" + gpio), at(1) + ": camera: expected a map, got a list");
  EXPECT_EQ(error_of("camera:\n  gain: 1\n  gain: 2\n" + gpio),
            at(3) + ": camera.gain: key given twice");
  EXPECT_EQ(error_of("camera: {device: /dev/video0\n"),
            at(2) + ": yaml: end of map flow not found");
  const fs::path missing = dir_ / "absent.yaml";
  try {
    read_hardware_config(missing);
    FAIL() << "no error for a missing file";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()), missing.string() + ": hardware config not found");
  }
}

}  // namespace
}  // namespace cosmos
