#pragma once
// The project's libgpiod lines against gpio-sim: the outputs the cell drives show on the
// chip's lines, and quadrature edges and photo-eye changes driven from outside reach the
// decoder through the kernel's edge events, with the kernel's time stamps.
#include <string>
#include <vector>

#include "firmware_bridge/gpio_config.hpp"
#include "tests/hil/check_line.hpp"

namespace cosmos::hil {

// `device_dir`: the live gpio-sim configfs device whose lines config names.
std::vector<ProbeCheck> probe_gpio(const GpioConfig& config, const std::string& device_dir);

}  // namespace cosmos::hil
