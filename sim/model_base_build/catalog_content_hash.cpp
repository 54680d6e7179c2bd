#include "sim/model_base_build/catalog_content_hash.hpp"

#include <cstdio>
#include <fstream>
#include <vector>

#include "core/input_error.hpp"
#include "core/io/xxh64.hpp"

namespace cosmos {

std::string catalog_content_hash(const PartCatalog& catalog) {
  Xxh64Stream stream;
  const auto field = [&stream](const std::string& text) {
    stream.update(text);
    stream.update("\0", 1);  // separator: ("ab", "c") and ("a", "bc") hash differently
  };
  std::vector<char> buffer(1 << 20);
  for (const PartEntry& part : catalog.parts) {
    char size[32];
    std::snprintf(size, sizeof size, "%.17g", part.size_mm);
    field(part.name);
    field(size);
    field(part.symmetric ? "symmetric" : "asymmetric");
    std::ifstream mesh(part.mesh_path, std::ios::binary);
    if (!mesh)
      throw InputError(part.mesh_path.string() + ": cannot read the mesh to hash the catalog");
    std::uint64_t mesh_bytes = 0;
    while (mesh) {
      mesh.read(buffer.data(), static_cast<std::streamsize>(buffer.size()));
      const auto got = static_cast<std::size_t>(mesh.gcount());
      stream.update(buffer.data(), got);
      mesh_bytes += got;
    }
    field(std::to_string(mesh_bytes));
  }
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(stream.digest()));
  return hex;
}

}  // namespace cosmos
