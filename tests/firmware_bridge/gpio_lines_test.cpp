// The libgpiod lines' set-up errors, against the real library. This machine has no GPIO
// chip, which is exactly the "missing chip" case; line decoding is tested through
// GpioInputDecoder, which poll_inputs feeds.
#include "firmware_bridge/gpio_lines.hpp"

#include <gtest/gtest.h>

namespace cosmos {
namespace {

GpioConfig quadrature_config(const char* chip) {
  GpioConfig config;
  config.chip = chip;
  config.encoder_a.name = "ENC_A";
  config.encoder_b.name = "ENC_B";
  config.photo_eye.offset = 4;
  config.laser_enable.offset = 5;
  return config;
}

TEST(LibgpiodLines, MissingChipGivesOneLineNamingIt) {
  LibgpiodLines lines(quadrature_config("gpiochip-cosmos-missing"));
  EXPECT_EQ(lines.start(), GpioStatus::kError);
  EXPECT_EQ(lines.last_error(),
            "gpiochip-cosmos-missing: cannot open GPIO chip: No such file or directory");
  EXPECT_FALSE(lines.started());
}

TEST(LibgpiodLines, QuadratureWithoutLineBIsRefusedBeforeTouchingTheChip) {
  GpioConfig config = quadrature_config("gpiochip-cosmos-missing");
  config.encoder_b = {};
  LibgpiodLines lines(config);
  EXPECT_EQ(lines.start(), GpioStatus::kError);
  EXPECT_EQ(lines.last_error(),
            "gpiochip-cosmos-missing: encoder_b: no line configured, quadrature decoding needs "
            "both A and B");
  config.encoder_mode =
      EncoderMode::kStep;  // a step line alone is fine: the chip is what fails now
  LibgpiodLines step_lines(config);
  EXPECT_EQ(step_lines.start(), GpioStatus::kError);
  EXPECT_NE(step_lines.last_error().find("cannot open GPIO chip"), std::string_view::npos);
}

TEST(LibgpiodLines, RealTimeCallsBeforeStartAreRefused) {
  LibgpiodLines lines(quadrature_config("gpiochip0"));
  EXPECT_EQ(lines.poll_inputs(1000), GpioStatus::kWrongState);
  EXPECT_EQ(lines.last_error(), "gpiochip0: poll_inputs: lines not started");
  EncoderAtTime at;
  EXPECT_EQ(lines.encoder_at(0, 1'000'000'000, at), GpioStatus::kWrongState);
  EXPECT_FALSE(at.settled);
  EXPECT_EQ(lines.set_output(GpioOutput::kLaserEnable, true), GpioStatus::kWrongState);
  EXPECT_EQ(lines.last_error(), "gpiochip0: laser_enable: lines not started");
  EXPECT_EQ(lines.stop(), GpioStatus::kOk);
}

}  // namespace
}  // namespace cosmos
