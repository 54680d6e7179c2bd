#pragma once
// The `scanner:` section of the cell configuration (config/cell.yaml): overrides of the
// simulated scanner's parameters (scanner/scanner_model.hpp, where ScannerParameters::visit
// lists each key with its range). Absent keys keep their defaults. Inside the section, an
// unknown or retired key, a value of the wrong type or out of its range throws InputError
// `file:LINE: scanner.key: reason` (1-based line).
//
//   scanner:
//     points_per_profile: 640
//     z_noise_mm: 0.02
//     camera:
//       bit_depth: 8
#include <filesystem>

#include "core/io/yaml_section_reader.hpp"
#include "scanner/scanner_model.hpp"

namespace cosmos {

// The file's scanner: section; other top-level sections belong to other layers and are left
// alone.
ScannerParameters read_scanner_config(const std::filesystem::path& yaml_path,
                                      const ScannerParameters& defaults = {});

// The section itself, for a reader of the whole file (realtime/config/cell_config.hpp):
// every key, then the rules between keys.
void read_scanner_section(YamlSectionReader& section, ScannerParameters& parameters);

// The same ranges and rules for parameters set in code: std::invalid_argument naming the
// first field out of range (e.g. after a CLI override).
void check_scanner_parameters(const ScannerParameters& parameters);

}  // namespace cosmos
