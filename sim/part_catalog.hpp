#pragma once
// The part catalog: which CAD meshes the cell knows, at what physical size, and whether a
// part is rotationally symmetric (rotation-error metrics must not count an equivalent pose as
// an error). It is a YAML file (config/parts.yaml by default):
//
//   mesh_dir: /some/folder        # optional; default: the mesh cache (default_mesh_cache_dir)
//   parts:
//     - {name: cow, mesh: cow.off, size_mm: 120, symmetric: false}
//
// Per part: name (letters, digits, '.', '_', '-'; unique), mesh, size_mm (largest extent of the
// part, finite and > 0), symmetric (optional, default false). A mesh path resolves as:
//   - absolute, or starting with "~/" (home folder): as written;
//   - starting with "./" or "../": relative to the YAML file's folder;
//   - any other relative path: in mesh_dir if the file is there, else in the YAML file's
//     folder if it is there, else (missing) in mesh_dir, so the error names the expected place.
// mesh_dir itself may be absolute, "~/"-relative, or relative to the YAML file's folder.
//
// Every defect throws cosmos::InputError with one line `file:LINE: key: reason` (1-based line).
// Meshes are not opened here: a catalog lists parts whose mesh may be fetched later.
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace cosmos {

struct PartEntry {
  std::string name;
  std::filesystem::path mesh_path;  // absolute, resolved as above
  double size_mm = 0.0;             // largest bounding-box extent of the loaded part
  bool symmetric = false;           // rotationally symmetric (spool, rotor, pinion, ...)
};

struct PartCatalog {
  std::filesystem::path file;    // the YAML it was read from
  std::vector<PartEntry> parts;  // in file order

  const PartEntry* find(std::string_view name) const;  // nullptr when absent
  // InputError "unknown part 'x' in <file> (known: a, b, ...)" when absent.
  const PartEntry& at(std::string_view name) const;
};

// Reads and validates a catalog; relative mesh paths fall back to mesh_cache_dir.
PartCatalog read_part_catalog(const std::filesystem::path& yaml_path,
                              const std::filesystem::path& mesh_cache_dir);
PartCatalog read_part_catalog(const std::filesystem::path& yaml_path);  // default_mesh_cache_dir()

// Where scripts/fetch_catalog.sh puts the meshes of Debian's libcgal-demo:
// $COSMOS_CACHE_DIR/meshes when set, else $HOME/.cache/cosmos-cell/meshes.
std::filesystem::path default_mesh_cache_dir();

// The catalog to use: explicit_path when non-empty (the CLI's --catalog), else
// config/parts.yaml under the current directory, else ../../config/parts.yaml next to the
// running executable (build/apps/cosmos inside the source tree). The source directory is not
// known at run time, hence the search. InputError naming the places tried when none exists.
std::filesystem::path find_part_catalog(const std::filesystem::path& explicit_path = {});

}  // namespace cosmos
