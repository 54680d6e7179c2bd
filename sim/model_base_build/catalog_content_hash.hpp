#pragma once
// The content hash a model base records of the catalog it was built from: XXH64 over every
// part's name, size, symmetry flag and mesh file bytes, in catalog order, as 16 hex digits.
// What the catalog file looks like (comments, mesh folder, key order) does not enter, so moving
// the meshes keeps the hash and editing one vertex changes it.
#include <string>

#include "sim/part_catalog.hpp"

namespace cosmos {

// InputError naming the mesh file when one cannot be read.
std::string catalog_content_hash(const PartCatalog& catalog);

}  // namespace cosmos
