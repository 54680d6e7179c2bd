// A mesh file of one format, read by the project's readers (sim/mesh.hpp): built once per
// format, the extension given by COSMOS_FUZZ_MESH_EXTENSION.
#include <cstddef>
#include <cstdint>

#include "core/input_error.hpp"
#include "fuzz/fuzz_input_file.hpp"
#include "sim/mesh.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto path = cosmos::fuzz::write_input("mesh" COSMOS_FUZZ_MESH_EXTENSION, data, size);
  try {
    cosmos::read_mesh_file(path);
  } catch (const cosmos::InputError&) {
  }
  return 0;
}
