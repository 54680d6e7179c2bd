// An lcm-logger log (realtime/lcm/lcm_log_reader.hpp), as `cosmos cell --replay` and the
// tests read it: every profile, pose and status event on the default channels.
#include <cstddef>
#include <cstdint>

#include "core/input_error.hpp"
#include "fuzz/fuzz_input_file.hpp"
#include "realtime/lcm/lcm_log_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto path = cosmos::fuzz::write_input("input.lcmlog", data, size);
  try {
    cosmos::LcmLogReader profiles(path);
    cosmos::Profile profile;
    while (profiles.next_profile(profile)) {
    }
  } catch (const cosmos::InputError&) {
  }
  try {
    cosmos::read_logged_poses(path);
  } catch (const cosmos::InputError&) {
  }
  try {
    cosmos::read_logged_statuses(path);
  } catch (const cosmos::InputError&) {
  }
  return 0;
}
