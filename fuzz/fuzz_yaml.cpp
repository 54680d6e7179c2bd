// The YAML files a user writes: the cell config (realtime/config/cell_config.hpp), the
// hardware YAML (realtime/config/hardware_config.hpp) and the part catalog
// (sim/part_catalog.hpp), one harness each, chosen by COSMOS_FUZZ_YAML (1, 2, 3).
#include <cstddef>
#include <cstdint>

#include "core/input_error.hpp"
#include "fuzz/fuzz_input_file.hpp"
#include "realtime/config/cell_config.hpp"
#include "realtime/config/hardware_config.hpp"
#include "sim/part_catalog.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto path = cosmos::fuzz::write_input("input.yaml", data, size);
  try {
#if COSMOS_FUZZ_YAML == 1
    cosmos::load_cell_config(path);
#elif COSMOS_FUZZ_YAML == 2
    cosmos::read_hardware_config(path);
#else
    // Mesh paths resolve against the fuzz directory, which holds no meshes: the catalog's
    // own checks run, no mesh is read.
    cosmos::read_part_catalog(path, cosmos::fuzz::fuzz_directory());
#endif
  } catch (const cosmos::InputError&) {
  }
  return 0;
}
