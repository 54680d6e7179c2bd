// `cosmos catalog list [--catalog FILE]`: the parts of the catalog, and whether each mesh
// loads, so a user adding a mesh sees at once what the cell will make of it.
// `cosmos catalog procedural [--out DIR] [--per-family N] [--seed S]`: the mechanical parts
// built in code (sim/procedural_parts.hpp) written as OFF files, by default into the mesh
// cache's procedural/ folder where config/parts-250.yaml looks for them; prints the catalog
// line of each.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "apps/command_registry.hpp"
#include "core/input_error.hpp"
#include "sim/mesh.hpp"
#include "sim/part_catalog.hpp"
#include "sim/procedural_parts.hpp"

namespace cosmos::cli {
namespace {

struct CatalogRow {
  std::vector<std::string> cells;  // name, mesh, size_mm, vertices, faces, status
  bool loads = false;
};

// Meshes from the cache print relative to it: the long cache prefix adds nothing.
std::string display_mesh(const std::filesystem::path& mesh, const std::filesystem::path& cache) {
  const std::filesystem::path relative = mesh.lexically_relative(cache);
  if (!relative.empty() && *relative.begin() != "..") return relative.string();
  return mesh.string();
}

CatalogRow row_for(const PartEntry& part, const std::filesystem::path& cache) {
  std::ostringstream size;
  size << part.size_mm;
  CatalogRow row;
  row.cells = {part.name, display_mesh(part.mesh_path, cache), size.str(), "-", "-", ""};
  try {
    const TriangleMesh mesh = load_mesh(part.mesh_path, part.size_mm);
    row.cells[3] = std::to_string(mesh.vertices.size());
    row.cells[4] = std::to_string(mesh.triangles.size());
    row.cells[5] = part.symmetric ? "ok (symmetric)" : "ok";
    row.loads = true;
  } catch (const InputError& error) {
    row.cells[5] = std::string("FAILS: ") + error.what();
  }
  return row;
}

void print_table(const std::vector<CatalogRow>& rows) {
  const std::vector<std::string> header = {"name", "mesh", "size_mm", "vertices", "faces", "loads"};
  std::vector<std::size_t> width(header.size());
  for (std::size_t c = 0; c < header.size(); ++c) width[c] = header[c].size();
  for (const CatalogRow& row : rows) {
    for (std::size_t c = 0; c < row.cells.size(); ++c)
      width[c] = std::max(width[c], row.cells[c].size());
  }
  const auto print_line = [&](const std::vector<std::string>& cells) {
    for (std::size_t c = 0; c < cells.size(); ++c) {
      const bool numeric = c >= 2 && c <= 4;
      const bool last = c + 1 == cells.size();
      std::cout << (numeric ? std::right : std::left)
                << std::setw(last ? 0 : static_cast<int>(width[c])) << cells[c]
                << (last ? "\n" : "  ");
    }
  };
  print_line(header);
  for (const CatalogRow& row : rows) print_line(row.cells);
}

void run_list(const std::string& catalog_option) {
  const std::filesystem::path cache = default_mesh_cache_dir();
  const PartCatalog catalog = read_part_catalog(find_part_catalog(catalog_option), cache);
  std::cout << "catalog: " << catalog.file.string() << "\nmesh cache: " << cache.string() << "\n";
  std::vector<CatalogRow> rows;
  for (const PartEntry& part : catalog.parts) rows.push_back(row_for(part, cache));
  print_table(rows);
  const auto failing =
      std::count_if(rows.begin(), rows.end(), [](const CatalogRow& row) { return !row.loads; });
  if (failing > 0) {
    throw InputError(
        catalog.file.string() + ": " + std::to_string(failing) + " of " +
        std::to_string(rows.size()) +
        " parts do not load (see the table; scripts/fetch_catalog.sh fetches the default meshes)");
  }
}

struct ProceduralOptions {
  std::string out;
  int per_family = 5;
  std::uint64_t seed = 1;
};

void run_procedural(const ProceduralOptions& options) {
  const std::filesystem::path out = options.out.empty() ? default_mesh_cache_dir() / "procedural"
                                                        : std::filesystem::path(options.out);
  std::error_code error;
  std::filesystem::create_directories(out, error);
  if (error) throw InputError(out.string() + ": cannot create directory (" + error.message() + ")");
  for (const ProceduralPart& part : procedural_parts(options.per_family, options.seed)) {
    write_off_file(part.mesh, out / (part.name + ".off"));
    const Eigen::Vector3f extent = bounding_box(part.mesh).sizes();
    std::printf("  - {name: %s, mesh: procedural/%s.off, size_mm: %.0f, symmetric: %s}\n",
                part.name.c_str(), part.name.c_str(), std::ceil(extent.maxCoeff()),
                part.symmetric ? "true" : "false");
  }
  std::fprintf(stderr, "catalog: procedural meshes in %s\n", out.string().c_str());
}

void install(CLI::App& root) {
  CLI::App* catalog =
      root.add_subcommand("catalog", "The part catalog (config/parts.yaml) and its meshes");
  catalog->require_subcommand(1);
  CLI::App* list =
      catalog->add_subcommand("list", "Table of the catalog's parts and whether each mesh loads");
  auto catalog_option = std::make_shared<std::string>();
  list->add_option("--catalog", *catalog_option,
                   "Part catalog YAML (default: ./config/parts.yaml, else ../../config/parts.yaml "
                   "beside the executable)");
  list->callback([catalog_option] { run_list(*catalog_option); });
  auto procedural_options = std::make_shared<ProceduralOptions>();
  CLI::App* procedural = catalog->add_subcommand(
      "procedural", "Write the mechanical parts built in code as OFF files (the mesh cache)");
  procedural
      ->add_option("--out", procedural_options->out, "folder (default: MESH_CACHE/procedural)")
      ->type_name("DIR");
  procedural->add_option("--per-family", procedural_options->per_family, "parts of each family")
      ->check(CLI::Range(1, 1000))
      ->capture_default_str();
  procedural->add_option("--seed", procedural_options->seed, "seed of the families' proportions")
      ->capture_default_str();
  procedural->callback([procedural_options] { run_procedural(*procedural_options); });
}

const CommandRegistration registration("catalog", install);

}  // namespace
}  // namespace cosmos::cli
