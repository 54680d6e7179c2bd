// The part catalog: the default config/parts.yaml loads every part at its size from the fetched
// mesh cache, mesh paths resolve as documented, and each bad YAML is one exact
// `file:LINE: key: reason` line.
#include "sim/part_catalog.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <fstream>
#include <iostream>
#include <set>

#include "core/input_error.hpp"
#include "sim/mesh.hpp"

namespace cosmos {
namespace {

namespace fs = std::filesystem;

TEST(DefaultCatalog, EveryPartLoadsAtItsSize) {
  const fs::path cache = default_mesh_cache_dir();
  // Never skipped: a missing cache is a broken setup, and the message says how to fix it.
  ASSERT_TRUE(fs::is_directory(cache))
      << "the mesh cache " << cache
      << " is missing: run scripts/fetch_catalog.sh (or scripts/setup.sh)";
  const PartCatalog catalog =
      read_part_catalog(fs::path(COSMOS_SOURCE_DIR) / "config" / "parts.yaml");
  EXPECT_GE(catalog.parts.size(), 20u);
  std::set<std::string> names;
  for (const PartEntry& part : catalog.parts) {
    SCOPED_TRACE(part.name);
    names.insert(part.name);
    EXPECT_TRUE(part.mesh_path.is_absolute()) << part.mesh_path;
    EXPECT_GE(part.size_mm, 50.0);
    EXPECT_LE(part.size_mm, 150.0);
    ASSERT_TRUE(fs::is_regular_file(part.mesh_path))
        << part.mesh_path << " is missing: run scripts/fetch_catalog.sh";
    const TriangleMesh mesh = load_mesh(part.mesh_path, part.size_mm);
    const Eigen::AlignedBox3f box = bounding_box(mesh);
    EXPECT_NEAR(box.sizes().maxCoeff(), part.size_mm, 1e-3 * part.size_mm);
    EXPECT_LT(box.center().norm(), 1e-3 * part.size_mm);
    EXPECT_GT(mesh.triangles.size(), 100u);
    std::cout << "[ part     ] " << part.name << ": " << mesh.vertices.size() << " vertices, "
              << mesh.triangles.size() << " faces, " << part.size_mm << " mm"
              << (part.symmetric ? ", symmetric" : "") << "\n";
  }
  EXPECT_EQ(names.size(), catalog.parts.size());
  for (const char* symmetric : {"spool", "rotor", "pinion", "turbine"}) {
    ASSERT_NE(catalog.find(symmetric), nullptr) << symmetric;
    EXPECT_TRUE(catalog.find(symmetric)->symmetric) << symmetric;
  }
  for (const char* free_form : {"cow", "armadillo", "fandisk"}) {
    ASSERT_NE(catalog.find(free_form), nullptr) << free_form;
    EXPECT_FALSE(catalog.find(free_form)->symmetric) << free_form;
  }
}

// The catalog-scale test catalog: at least 250 parts, the default catalog's among them as they
// are, and each size family three sizes 10 % apart of one mesh. Its meshes are not loaded here
// (the procedural ones exist once `cosmos catalog procedural` wrote them).
TEST(ScaleCatalog, HoldsTheDefaultPartsAndSizeFamiliesTenPercentApart) {
  const PartCatalog defaults =
      read_part_catalog(fs::path(COSMOS_SOURCE_DIR) / "config" / "parts.yaml");
  const PartCatalog scale =
      read_part_catalog(fs::path(COSMOS_SOURCE_DIR) / "config" / "parts-250.yaml");
  EXPECT_GE(scale.parts.size(), 250u);
  std::set<std::string> names;
  for (const PartEntry& part : scale.parts) names.insert(part.name);
  EXPECT_EQ(names.size(), scale.parts.size());
  for (const PartEntry& part : defaults.parts) {
    const PartEntry* same = scale.find(part.name);
    ASSERT_NE(same, nullptr) << part.name;
    EXPECT_EQ(same->mesh_path, part.mesh_path) << part.name;
    EXPECT_EQ(same->size_mm, part.size_mm) << part.name;
  }
  int families = 0;
  for (const PartEntry& part : scale.parts) {
    const PartEntry* larger = scale.find(part.name + "-110");
    if (larger == nullptr) continue;
    const PartEntry* largest = scale.find(part.name + "-121");
    ASSERT_NE(largest, nullptr) << part.name;
    EXPECT_EQ(larger->mesh_path, part.mesh_path) << part.name;
    EXPECT_EQ(largest->mesh_path, part.mesh_path) << part.name;
    EXPECT_NEAR(larger->size_mm, 1.10 * part.size_mm, 0.051) << part.name;
    EXPECT_NEAR(largest->size_mm, 1.21 * part.size_mm, 0.051) << part.name;
    EXPECT_EQ(larger->symmetric, part.symmetric) << part.name;
    ++families;
  }
  EXPECT_GE(families, 70);
}

class CatalogFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string pattern = (fs::temp_directory_path() / "cosmos-catalog-test-XXXXXX").string();
    ASSERT_NE(mkdtemp(pattern.data()), nullptr);
    dir_ = pattern;
    fs::create_directories(dir_ / "cache");
    fs::create_directories(dir_ / "config");
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path write(const fs::path& relative, const std::string& text) const {
    const fs::path path = dir_ / relative;
    std::ofstream(path) << text;
    return path;
  }

  // The InputError message of reading the catalog `text` ("" when none is thrown).
  std::string catalog_error(const std::string& text) const {
    try {
      read_part_catalog(write("config/parts.yaml", text), dir_ / "cache");
    } catch (const InputError& error) {
      return error.what();
    }
    return "";
  }

  std::string at_line(int line) const {
    return (dir_ / "config/parts.yaml").string() + ":" + std::to_string(line);
  }

  fs::path dir_;
};

TEST_F(CatalogFiles, UnknownKeyNamesItsLine) {
  EXPECT_EQ(catalog_error(
                "parts:\n  - name: cow\n    mesh: cow.off\n    size_mm: 100\n    colour: red\n"),
            at_line(5) + ": colour: unknown key (expected name, mesh, size_mm, symmetric)");
  EXPECT_EQ(catalog_error(
                "mesh_dir: here\nmeshes: []\nparts:\n  - {name: cow, mesh: cow.off, size_mm: 1}\n"),
            at_line(2) + ": meshes: unknown key (expected mesh_dir, parts)");
}

TEST_F(CatalogFiles, WrongTypeNamesItsLine) {
  EXPECT_EQ(catalog_error("parts:\n  - name: cow\n    mesh: cow.off\n    size_mm: big\n"),
            at_line(4) + ": size_mm: expected a number (mm), got 'big'");
  EXPECT_EQ(
      catalog_error("parts:\n  - {name: cow, mesh: cow.off, size_mm: 100, symmetric: maybe}\n"),
      at_line(2) + ": symmetric: expected true or false, got 'maybe'");
  EXPECT_EQ(catalog_error("parts:\n  - name: cow\n    mesh: [a.off, b.off]\n    size_mm: 100\n"),
            at_line(3) + ": mesh: expected a non-empty text, got a list");
  EXPECT_EQ(catalog_error("parts: cow\n"),
            at_line(1) + ": parts: expected a non-empty list of parts, got 'cow'");
}

TEST_F(CatalogFiles, NonPositiveSizeNamesItsLine) {
  EXPECT_EQ(catalog_error("parts:\n  - name: cow\n    mesh: cow.off\n    size_mm: 0\n"),
            at_line(4) + ": size_mm: must be a finite size > 0 mm, got 0");
  EXPECT_EQ(catalog_error("parts:\n\n  - {name: cow, mesh: cow.off, size_mm: -12.5}\n"),
            at_line(3) + ": size_mm: must be a finite size > 0 mm, got -12.5");
  EXPECT_EQ(catalog_error("parts:\n  - {name: cow, mesh: cow.off, size_mm: .nan}\n"),
            at_line(2) + ": size_mm: must be a finite size > 0 mm, got .nan");
}

TEST_F(CatalogFiles, DuplicateNameNamesItsLine) {
  EXPECT_EQ(catalog_error("parts:\n  - {name: cow, mesh: cow.off, size_mm: 100}\n"
                          "  - {name: pig, mesh: pig.off, size_mm: 90}\n"
                          "  - {name: cow, mesh: bull.off, size_mm: 120}\n"),
            at_line(4) + ": name: duplicate part 'cow' (first at line 2)");
}

TEST_F(CatalogFiles, MissingKeysAndBadNamesNameTheirLine) {
  EXPECT_EQ(catalog_error("parts:\n  - name: cow\n    size_mm: 100\n"),
            at_line(2) + ": mesh: missing key");
  EXPECT_EQ(catalog_error("mesh_dir: x\n"), at_line(1) + ": parts: missing key");
  EXPECT_EQ(catalog_error("parts:\n  - {name: my cow, mesh: cow.off, size_mm: 100}\n"),
            at_line(2) + ": name: 'my cow' may only use letters, digits, '.', '_' or '-'");
  EXPECT_EQ(catalog_error("parts:\n  - {name: cow, mesh: cow.off, size_mm: 1, size_mm: 2}\n"),
            at_line(2) + ": size_mm: key given twice");
}

TEST_F(CatalogFiles, SyntaxErrorNamesItsLine) {
  const std::string message = catalog_error("parts:\n  - {name: cow, mesh: cow.off\n");
  EXPECT_EQ(message.rfind(at_line(3) + ": yaml: ", 0), 0u) << message;
}

TEST_F(CatalogFiles, MissingFileIsNamed) {
  const fs::path path = dir_ / "nowhere.yaml";
  EXPECT_THROW(
      {
        try {
          read_part_catalog(path, dir_ / "cache");
        } catch (const InputError& error) {
          EXPECT_EQ(std::string(error.what()), path.string() + ": part catalog not found");
          throw;
        }
      },
      InputError);
}

TEST_F(CatalogFiles, MeshPathsResolveAsDocumented) {
  write("cache/in_cache.off", "OFF\n");
  write("config/beside.off", "OFF\n");
  write("config/both.off", "OFF\n");
  write("cache/both.off", "OFF\n");
  const fs::path absolute = write("elsewhere.off", "OFF\n");
  const PartCatalog catalog =
      read_part_catalog(write("config/parts.yaml",
                              "parts:\n"
                              "  - {name: a, mesh: in_cache.off, size_mm: 1}\n"
                              "  - {name: b, mesh: beside.off, size_mm: 2, symmetric: true}\n"
                              "  - {name: c, mesh: both.off, size_mm: 3}\n"
                              "  - {name: d, mesh: ./both.off, size_mm: 4}\n"
                              "  - {name: e, mesh: ../elsewhere.off, size_mm: 5}\n"
                              "  - {name: f, mesh: " +
                                  absolute.string() +
                                  ", size_mm: 6}\n"
                                  "  - {name: g, mesh: not_fetched.off, size_mm: 7}\n"),
                        dir_ / "cache");
  ASSERT_EQ(catalog.parts.size(), 7u);
  EXPECT_EQ(catalog.at("a").mesh_path, dir_ / "cache/in_cache.off");
  EXPECT_EQ(catalog.at("b").mesh_path, dir_ / "config/beside.off");
  EXPECT_TRUE(catalog.at("b").symmetric);
  EXPECT_FALSE(catalog.at("a").symmetric);
  EXPECT_EQ(catalog.at("c").mesh_path, dir_ / "cache/both.off");  // the mesh cache wins
  EXPECT_EQ(catalog.at("d").mesh_path, dir_ / "config/both.off");
  EXPECT_EQ(catalog.at("e").mesh_path, absolute);
  EXPECT_EQ(catalog.at("f").mesh_path, absolute);
  EXPECT_EQ(catalog.at("g").mesh_path, dir_ / "cache/not_fetched.off");
  EXPECT_DOUBLE_EQ(catalog.at("f").size_mm, 6.0);
}

TEST_F(CatalogFiles, MeshDirKeyReplacesTheCache) {
  fs::create_directories(dir_ / "config/meshes");
  write("config/meshes/m.off", "OFF\n");
  const PartCatalog catalog = read_part_catalog(
      write("config/parts.yaml",
            "mesh_dir: meshes\nparts:\n  - {name: m, mesh: m.off, size_mm: 10}\n"),
      dir_ / "cache");
  EXPECT_EQ(catalog.at("m").mesh_path, dir_ / "config/meshes/m.off");
}

TEST_F(CatalogFiles, LookupByName) {
  const PartCatalog catalog = read_part_catalog(
      write("config/parts.yaml", "parts:\n  - {name: cow, mesh: cow.off, size_mm: 100}\n"),
      dir_ / "cache");
  EXPECT_EQ(catalog.find("pig"), nullptr);
  ASSERT_NE(catalog.find("cow"), nullptr);
  EXPECT_EQ(catalog.find("cow")->name, "cow");
  try {
    catalog.at("pig");
    ADD_FAILURE() << "no InputError for an unknown part";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()),
              "unknown part 'pig' in " + (dir_ / "config/parts.yaml").string() + " (known: cow)");
  }
}

TEST_F(CatalogFiles, CatalogSearchPrefersExplicitThenCurrentDirectory) {
  EXPECT_EQ(find_part_catalog("/some/explicit.yaml"), fs::path("/some/explicit.yaml"));
  write("config/parts.yaml", "parts: []\n");
  const fs::path previous = fs::current_path();
  fs::current_path(dir_);
  const fs::path found = find_part_catalog();
  fs::current_path(previous);
  EXPECT_EQ(found, dir_ / "config/parts.yaml");
}

TEST(MeshCache, FollowsCosmosCacheDir) {
  const char* previous = std::getenv("COSMOS_CACHE_DIR");
  const std::string saved = previous != nullptr ? previous : "";
  setenv("COSMOS_CACHE_DIR", "/tmp/cosmos-cache-test", 1);
  EXPECT_EQ(default_mesh_cache_dir(), fs::path("/tmp/cosmos-cache-test/meshes"));
  if (previous != nullptr) {
    setenv("COSMOS_CACHE_DIR", saved.c_str(), 1);
  } else {
    unsetenv("COSMOS_CACHE_DIR");
  }
}

}  // namespace
}  // namespace cosmos
