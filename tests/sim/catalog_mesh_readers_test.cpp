// The project's mesh readers on every mesh of the fetched catalog cache (libcgal-demo's OFF,
// PLY and STL files): each loads with the vertex and triangle counts and the bounding box assimp
// read it with when the project still read its meshes through assimp (recorded below), or is
// refused as assimp refused it, except the files assimp misreads, where the triangles are the
// ones the file declares.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

#include "core/input_error.hpp"
#include "sim/mesh.hpp"
#include "sim/part_catalog.hpp"

namespace cosmos {
namespace {

namespace fs = std::filesystem;

// A mesh as assimp read it: the vertices its triangles use, joined by position as
// read_mesh_file joins them, its triangles and its bounding box in the file's units.
struct AssimpReading {
  const char* file;
  std::size_t vertices;
  std::size_t triangles;
  double min[3];
  double max[3];
};
// clang-format off
const AssimpReading kAssimpReadings[] = {
    {"3torus.off", 19, 46, {-1.50976992, -1.09022999, -1.14707994}, {1.44104004, 0.904390991, 1.52815998}},
    {"ALSTOM_TEST4.off", 1138, 2033, {-344.987, 26.7523994, 192.673996}, {517.530029, 215.154007, 462.541992}},
    {"ChineseDragon-10kv.off", 10000, 19994, {-34.4333076, -52.6971169, -1036.63074}, {27.1646004, 60.1910858, -927.312439}},
    {"P.off", 26, 52, {0, 0, 0}, {3, 5, 1}},
    {"anchor.off", 519, 1050, {-0.5, -0.3125, -0.42829299}, {0.5, 0.3125, 0.42829299}},
    {"anchor_dense.off", 3793, 7598, {-0.5, -0.3125, -0.42829299}, {0.5, 0.3125, 0.42829299}},
    {"armadillo.off", 26002, 52000, {-63.5004005, -54.2018013, -57.7042999}, {63.517601, 97.1075974, 57.7187004}},
    {"b9_mesh.off", 5951, 10174, {-45.4480972, -55.9865036, -11.8421001}, {45.4395866, 56.0941658, 12.0854082}},
    {"beam.off", 8, 12, {2.29999995, 2.29999995, -1.29999995}, {2.70000005, 2.70000005, 2.29999995}},
    {"bear.off", 13826, 27648, {-0.671387017, -0.728133023, -0.329365999}, {0.678683996, 0.942906976, 0.326736987}},
    {"bear_bis.off", 10096, 20188, {-0.618126988, -0.892338991, -0.373052001}, {0.412346989, 0.977392972, 0.565397978}},
    {"blade.off", 8231, 16222, {-5.98992014, 12.9959002, 1.43743002}, {4.00829983, 142.182007, 2.08566999}},
    {"blob-closed.off", 140, 276, {-1.20348763, -0.884869277, -0.970323086}, {0.899971366, 0.492755234, 0.893711329}},
    {"blob.off", 138, 270, {-1.20348763, -0.884869277, -0.970323086}, {0.899971366, 0.492755234, 0.893711329}},
    {"blobby.off", 2027, 4050, {-0.490859985, -0.225033998, -0.198566005}, {0.320684999, 0.234913006, 0.200094998}},
    {"blobby_3cc.off", 1820, 3417, {-0.490859985, -0.225033998, -0.198566005}, {0.320684999, 0.234913006, 0.200094998}},
    {"boeing.off", 1264, 2564, {-6, -12, -2.5}, {6, 12, 2.5}},
    {"bones.off", 2154, 4204, {-5.63323975, -1.86044002, -2.12503004}, {5.63321018, 1.86044002, 2.12565994}},
    {"bull.off", 6200, 12396, {-0.5, -0.340505004, -0.400676012}, {0.5, 0.340505004, 0.400676012}},
    {"bunny00.off", 37706, 75408, {-0.498959005, -0.493434012, -0.386489987}, {0.499220014, 0.493766993, 0.386085987}},
    {"cactus.off", 620, 1236, {-0.363294989, -0.728686988, -0.109691001}, {0.378295004, 0.519797981, 0.110141002}},
    {"camel.off", 9770, 19536, {-0.152856007, -0.489255995, -0.5}, {0.152856007, 0.489255995, 0.5}},
    {"cheese-box.off", 8, 12, {-0.0665500015, -0.0665500015, -0.0665500015}, {0.0665500015, 0.0665500015, 0.0665500015}},
    {"cheese.off", 8629, 17786, {-0.0500000007, -0.0500000007, -0.0500000007}, {0.0500000007, 0.0500000007, 0.0500000007}},
    {"colored_tetra.ply", 4, 4, {0, 0, 0}, {1, 1, 1}},
    {"corner.off", 16, 28, {0, 0, 0}, {2, 1, 2}},
    {"corner_poly.off", 12, 20, {0, 0, -1}, {2, 2, 1}},
    {"corner_tris_with_hole.off", 29, 52, {0, 0, 0}, {2, 1, 2}},
    {"corner_with_hole.off", 16, 26, {0, 0, 0}, {2, 1, 2}},
    {"corner_with_sharp_edge.off", 17, 30, {0, 0, 0}, {2, 1, 2}},
    {"couplingdown.off", 1841, 3714, {-0.5, -0.5, -0.182390004}, {0.5, 0.5, 0.182390004}},
    {"cow.off", 2903, 5804, {-0.5, -0.306243002, -0.162908003}, {0.5, 0.306243002, 0.162908003}},
    {"cross.off", 40, 76, {-0.5, -0.5, -0.100000001}, {0.5, 0.5, 0.100000001}},
    {"cross_quad.off", 40, 76, {0, 0, 0}, {5, 5, 1}},
    {"cube-meshed.off", 866, 1728, {-1, -1, -1}, {1, 1, 1}},
    {"cube-ouvert.off", 8, 10, {-1, -1, -1}, {1, 1, 1}},
    {"cube.off", 8, 12, {-1, -1, -1}, {1, 1, 1}},
    {"cube_quad.off", 8, 12, {-1, -1, -1}, {1, 1, 1}},
    {"cylinder.off", 1200, 2262, {0, -1, -4.64101966e-08}, {3, 1, 0.999189019}},
    {"cylinder_locally_refined.off", 8285, 16442, {-0.5, -0.333332986, -0.166531995}, {0.5, 0.333332986, 0.166531995}},
    {"degtri_sliding.off", 8, 8, {1, -2, 0}, {6, 2, 0}},
    {"dino.off", 3916, 7828, {-1.00222003, -1.15922999, -2.04527998}, {0.991926014, 2.54518008, 2.01822996}},
    {"diplodocus.off", 23980, 47960, {-0.5, -0.467168987, -0.170986995}, {0.5, 0.467168987, 0.170986995}},
    {"double-torus-3-holes.off", 228, 428, {-5.84826994, -3.78424001, -1.58630002}, {3.41971993, 4.06987, 3.24548006}},
    {"double-torus-example.off", 231, 466, {-5.84826994, -3.78424001, -1.58630002}, {3.41971993, 4.06987, 3.24548006}},
    {"dragknob.off", 161, 318, {-0.222222, -0.499630004, -0.5}, {0.222222, 0.499630004, 0.5}},
    {"eight.off", 315, 634, {-0.243695006, -0.103765003, -0.49931401}, {0.243695006, 0.103827998, 0.49931401}},
    {"elephant-with-holes.off", 2733, 4463, {-0.360217005, -0.5, -0.301481009}, {0.360217005, 0.5, 0.301481009}},
    {"elephant.off", 2775, 5558, {-0.360217005, -0.5, -0.301481009}, {0.360217005, 0.5, 0.301481009}},
    {"elk.off", 1645, 3290, {-51.4455986, -80.7326965, -101.538002}, {99.2269974, 78.8944016, 54.8494987}},
    {"ellipe0.003.off", 1556, 3108, {-0.998520017, -0.707772017, -0.498667985}, {1.00022995, 0.706117988, 0.500744998}},
    {"ellipsoid.off", 162, 320, {-0.200000003, -0.300000012, -0.5}, {0.200000003, 0.300000012, 0.5}},
    {"fandisk-box.off", 8, 12, {-0.612659276, -0.340137064, -0.665499985}, {0.612659276, 0.340137064, 0.665499985}},
    {"fandisk.off", 6475, 12946, {-0.460299999, -0.255549997, -0.5}, {0.460299999, 0.255549997, 0.5}},
    {"fandisk_large.off", 15843, 31682, {-4.67051003e-15, 12.606143, -2.67981577}, {4.82790136, 17.8491154, 3.19818736e-14}},
    {"femur.off", 3897, 7798, {-0.199343994, -0.168865994, -0.5}, {0.199343994, 0.168865994, 0.5}},
    {"fold.off", 12, 12, {42.8619995, 34.4822044, 10.8167953}, {43.2588997, 34.8402405, 10.8602982}},
    {"geosphere.off", 162, 320, {-1, -1, -1}, {1, 1, 1}},
    {"hand.off", 1197, 2390, {-0.438612014, -0.399102002, -0.5}, {0.438612014, 0.399102002, 0.5}},
    {"handle.off", 1165, 2326, {-0.5, -0.193092003, -0.396744013}, {0.5, 0.193092003, 0.396744013}},
    {"head.off", 1487, 2918, {-7.28679991, -0.0540000014, -4.55872107}, {6.70847988, 17.3600006, 4.57025099}},
    {"hedra.off", 6, 8, {-1.19200003, -1.68599999, -1.19200003}, {1.19200003, 1.68599999, 1.19200003}},
    {"hedra_open.off", 6, 6, {-1.19200003, -1.68599999, -1.19200003}, {1.19200003, 1.68599999, 1.19200003}},
    {"helmet.off", 496, 1000, {-0.5, -0.341165006, -0.343755007}, {0.5, 0.341165006, 0.343755007}},
    {"hole.off", 20, 40, {-10.0988998, -10.2040997, -10.2040997}, {10.1030998, 10.2040997, 10.2040997}},
    {"holes.off", 4291, 8288, {-1.90383005, -1.79464006, -2.28131008}, {1.95989001, 0.47933501, 2.46462011}},
    {"homer.off", 4930, 9856, {-0.282016009, -0.5, -0.163643003}, {0.282088995, 0.5, 0.163457006}},
    {"horizons-domain.off", 8, 12, {-1.18555009, -0.0761638954, -0.801340401}, {0.797043204, 0.475970745, 1.09531343}},
    {"horizons.off", 1682, 3200, {-1.01350689, -0.0282513816, -0.636754751}, {0.625, 0.428058237, 0.93072778}},
    {"icosahedron.off", 12, 20, {-0.850651026, -0.850651026, -0.850651026}, {0.850651026, 0.850651026, 0.850651026}},
    {"in.off", 4, 2, {0, 0, 0}, {1, 1, 0}},
    {"itemb.off", 162, 320, {-1.4825809, -0.515896499, -0.467387348}, {-0.482580841, 0.484103471, 0.532612681}},
    {"joint.off", 221, 446, {-0.375039011, -0.5, -0.477109998}, {0.375039011, 0.5, 0.477109998}},
    {"knot.off", 2080, 4160, {-0.5, -0.499128014, -0.241632998}, {0.5, 0.499128014, 0.241632998}},
    {"knot1.off", 3200, 6400, {-0.480100989, -0.5, -0.232322007}, {0.480100989, 0.5, 0.232322007}},
    {"knot2.off", 5760, 11520, {-0.375312001, -0.5, -0.229651004}, {0.375312001, 0.5, 0.229651004}},
    {"larger_sphere.off", 812, 1620, {-0.997860372, -0.997860372, -0.997860372}, {0.997860372, 0.997860372, 0.997860372}},
    {"lion-head.off", 8356, 16674, {-0.371179014, -0.475511998, -0.5}, {0.371179014, 0.475511998, 0.5}},
    {"lion.off", 7529, 14859, {-0.371179014, -0.475511998, -0.5}, {0.371179014, 0.475511998, 0.5}},
    {"man.off", 17495, 34986, {-0.210929006, -0.148182005, -0.5}, {0.210929006, 0.148182005, 0.5}},
    {"mannequin-devil.off", 12977, 25888, {-12.5141363, -16.7368431, -20}, {12.5141363, 16.7368431, 20}},
    {"mask_cone.off", 1200, 2332, {-0.626414001, -0.787959993, -0.688318014}, {0.631134987, 0.778285027, 0.230665997}},
    {"mech-holes-shark.off", 5246, 10192, {-0.5, -0.488164008, -0.489217997}, {0.5, 0.5, 0.48911801}},
    {"mesh_with_border.off", 548, 1014, {77.0937653, 72.786644, -1.91683269}, {92.3169174, 96.2155838, 16.4780464}},
    {"mushroom.off", 2337, 4608, {-0.499875993, -0.5, -0.232019007}, {0.499875993, 0.5, 0.232019007}},
    {"nefertiti.off", 299, 562, {-1.92177999, -2.49028993, -1.85165}, {1.98044991, 2.36983991, 0.526929975}},
    {"negative.off", 7, 6, {-255.988007, -24.8992996, 123.733002}, {-207.932007, 70.3187027, 148.723007}},
    {"oblong.off", 422, 840, {0, 0, 0}, {78, 58, 58}},
    {"octahedron.off", 6, 8, {-2, -2, -2}, {2, 2, 2}},
    {"open_cube.off", 8, 10, {0, 0, 0}, {100, 100, 100}},
    {"part.off", 175, 346, {-0.170840994, -0.326178014, -0.5}, {0.170840994, 0.326178014, 0.5}},
    {"patch-01.off", 735, 1396, {-0.0755384043, -0.0758664832, -0.0838530213}, {100.078529, 100.080711, 66.6600037}},
    {"patch-13.off", 144, 232, {0, 0, 50}, {100, 50, 66.6600037}},
    {"patch-20.off", 353, 638, {-0.0762080252, 50, 50}, {100.046997, 100.065231, 100.08226}},
    {"patch-21.off", 145, 234, {0, 50, 50}, {100, 100, 66.6600037}},
    {"patch-23.off", 109, 168, {0, 49.9217262, 66.6600037}, {100, 50.0635185, 100}},
    {"patch-30.off", 355, 642, {-0.050878007, -0.0692268237, 50}, {100.078583, 50, 100.081108}},
    {"pig.off", 468, 891, {-0.285400003, -0.238116995, -0.501667023}, {0.284810007, 0.238836005, 0.501598001}},
    {"pig.stl", 8642, 16848, {-0.00039999999, -0.00039999999, 5}, {49.7144012, 91.3384018, 52.9608994}},
    {"pinion.off", 650, 1300, {-0.831737995, -0.847176015, -0.886404991}, {0.831737995, 0.847176015, 0.886404991}},
    {"pinion_small.off", 650, 1300, {-0.469164014, -0.477872014, -0.5}, {0.469164014, 0.477872014, 0.5}},
    {"pipe.off", 160, 320, {-0.311022013, -0.5, -0.311022013}, {0.311022013, 0.5, 0.311022013}},
    {"plane.off", 841, 1600, {-0.625, 0, -0.625}, {0.625, 0, 0.625}},
    {"poly2x^2+y^2-0.062500.off", 1089, 2048, {-1, -1, 0}, {1, 1, 3}},
    {"polygon_mesh.off", 16344, 32245, {-344.389313, -150.785507, 35.9661293}, {-208.688507, -15.7581701, 48.0643082}},
    {"pyramid.off", 5, 6, {-1, -0.5, -0.5}, {1, 0.5, 0.5}},
    {"quad.off", 4, 2, {0, 0, 1}, {1, 1, 1}},
    {"quads_to_stitch.off", 15, 16, {0, 0, 0}, {1, 2, 0}},
    {"quint_tris.off", 12, 20, {-0.989992023, -0.756802022, -0.5}, {1, 0.909296989, 1}},
    {"reference_tetrahedron.off", 4, 4, {0, 0, 0}, {1, 1, 1}},
    {"refined_elephant.off", 44460, 88928, {-0.358822465, -0.49940449, -0.300132871}, {0.358436227, 0.497471899, 0.299583346}},
    {"retinal.off", 3643, 7282, {-0.5, -0.465546995, -0.358945996}, {0.5, 0.465546995, 0.358945996}},
    {"rotor.off", 600, 1200, {-0.225805998, -0.443221003, -0.5}, {0.225805998, 0.443221003, 0.5}},
    {"rotor_small.off", 2400, 4800, {0, -0.274796993, -0.310000002}, {0.280000001, 0.274796993, 0.310000002}},
    {"small_cube.off", 8, 12, {-0.274877995, -0.274877995, -0.274877995}, {0.274877995, 0.274877995, 0.274877995}},
    {"sphere.off", 162, 320, {-0.5, -0.5, -0.5}, {0.5, 0.5, 0.5}},
    {"sphere.ply", 162, 320, {-0.5, -0.5, -0.5}, {0.5, 0.5, 0.5}},
    {"sphere.stl", 162, 320, {-0.5, -0.5, -0.5}, {0.5, 0.5, 0.5}},
    {"spool.off", 649, 1294, {-0.259959012, -0.5, -0.499505997}, {0.259959012, 0.5, 0.499505997}},
    {"star.off", 14, 24, {-0.5, -0.5, -0.5}, {0.5, 0.5, 0.5}},
    {"tet-shuffled.off", 4, 4, {0, 0, 0}, {1, 1, 1}},
    {"tetra_intersected_by_triangle.off", 7, 5, {0, 0, 0}, {1, 1, 0.707107008}},
    {"tetrahedron.off", 4, 4, {0, 0, 0}, {1, 1, 1}},
    {"three_peaks.off", 1907, 3671, {-10, -7.16374779, 1.42857099}, {10, 7.16374779, 18.5714283}},
    {"torus_quad.off", 25, 50, {-0.791866004, -0.331395, -0.930894971}, {0.978801012, 0.331395, 0.930894971}},
    {"translated-cube.off", 8, 12, {1, 1, -1}, {3, 3, 1}},
    {"triangle.off", 3, 1, {0, 0, 0}, {1, 1, 0}},
    {"triangular_hole.off", 6, 6, {0, 0, 0}, {4, 3, 0}},
    {"triceratops.off", 2832, 5660, {-10.299778, -3.69169402, -2.91280293}, {7.41632795, 4.06365108, 2.94422793}},
    {"tripod.off", 24, 44, {-0.5, -0.433293015, -0.163699001}, {0.5, 0.433293015, 0.163699001}},
    {"turbine.off", 9210, 18460, {-0.115139, -0.5, -0.5}, {0.115139, 0.5, 0.5}},
    {"u.off", 86, 168, {-0.5, -0.275301009, -0.0804051012}, {0.5, 0.275301009, 0.0804051012}},
};
// clang-format on

// Files with no surface, which assimp refused too.
const char* const kRefused[] = {"b9.ply"};

// Files assimp reads otherwise than the format says, and their triangles counted by hand from
// the file (a face of n corners is n - 2 triangles).
struct AssimpMisreading {
  const char* file;
  std::size_t triangles;
  const char* why;
};
constexpr const char* kBlankLines =
    "blank or comment lines between the data lines, which assimp reads as a vertex or a face";
const AssimpMisreading kAssimpMisreadings[] = {
    {"blobby-shuffled.off", 4050, kBlankLines},
    {"cube-shuffled.off", 12, kBlankLines},
    {"cube4-shuffled.off", 12, kBlankLines},
    {"cube_poly.off", 12, kBlankLines},
    {"mpi_triang.off", 180, kBlankLines},
    {"oblong-shuffled.off", 840, kBlankLines},
    {"prim.off", 12, kBlankLines},
    {"sphere966.off", 1848, kBlankLines},
    {"mpi.off", 180, "faces of 10 corners, which assimp drops (it takes at most 9)"},
    {"mesh_with_colors.off", 6, "a pentagon among triangles with colours, which assimp refuses"},
};

const AssimpMisreading* misreading_of(const fs::path& path) {
  for (const AssimpMisreading& misreading : kAssimpMisreadings)
    if (path.filename() == misreading.file) return &misreading;
  return nullptr;
}

const AssimpReading* reading_of(const fs::path& path) {
  for (const AssimpReading& reading : kAssimpReadings)
    if (path.filename() == reading.file) return &reading;
  return nullptr;
}

// Assimp's number parser is not correctly rounded: its coordinates may be a float step off.
bool same_box(const Eigen::AlignedBox3f& ours, const AssimpReading& theirs) {
  const Eigen::Vector3f min(static_cast<float>(theirs.min[0]), static_cast<float>(theirs.min[1]),
                            static_cast<float>(theirs.min[2]));
  const Eigen::Vector3f max(static_cast<float>(theirs.max[0]), static_cast<float>(theirs.max[1]),
                            static_cast<float>(theirs.max[2]));
  const float step = 2e-7f * std::max((max - min).maxCoeff(), 1.0f);
  return (ours.min() - min).cwiseAbs().maxCoeff() <= step &&
         (ours.max() - max).cwiseAbs().maxCoeff() <= step;
}

TEST(CatalogMeshReaders, EveryMeshLoadsAsAssimpReadIt) {
  const fs::path cache = default_mesh_cache_dir();
  ASSERT_TRUE(fs::is_directory(cache))
      << "the mesh cache " << cache
      << " is missing: run scripts/fetch_catalog.sh (or scripts/setup.sh)";
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(cache)) {
    const std::string extension = entry.path().extension().string();
    if (extension == ".off" || extension == ".ply" || extension == ".stl" || extension == ".obj")
      files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  ASSERT_GE(files.size(), 100u);
  int compared = 0, misread = 0, refused = 0;
  for (const fs::path& path : files) {
    SCOPED_TRACE(path.filename().string());
    if (const AssimpMisreading* misreading = misreading_of(path)) {
      EXPECT_EQ(read_mesh_file(path).triangles.size(), misreading->triangles) << misreading->why;
      ++misread;
      continue;
    }
    std::string error;
    TriangleMesh ours;
    try {
      ours = read_mesh_file(path);
    } catch (const InputError& refusal) {
      error = refusal.what();
    }
    if (std::find(std::begin(kRefused), std::end(kRefused), path.filename()) !=
        std::end(kRefused)) {
      EXPECT_FALSE(error.empty()) << "assimp refused it";
      std::cout << "[ refused  ] " << path.filename().string() << ": " << error << "\n";
      ++refused;
      continue;
    }
    const AssimpReading* theirs = reading_of(path);
    ASSERT_NE(theirs, nullptr) << "a mesh assimp never read (another libcgal-demo version?)";
    ASSERT_EQ(error, "");
    ++compared;
    EXPECT_EQ(ours.vertices.size(), theirs->vertices);
    EXPECT_EQ(ours.triangles.size(), theirs->triangles);
    const Eigen::AlignedBox3f box = bounding_box(ours);
    EXPECT_TRUE(same_box(box, *theirs))
        << "ours " << box.min().transpose() << " .. " << box.max().transpose();
  }
  std::cout << "[ compared ] " << compared << " of " << files.size() << " files; " << misread
            << " that assimp misreads, " << refused << " refused\n";
  EXPECT_EQ(compared, static_cast<int>(std::size(kAssimpReadings)));
  EXPECT_EQ(misread, static_cast<int>(std::size(kAssimpMisreadings)));
  EXPECT_EQ(refused, static_cast<int>(std::size(kRefused)));
}

}  // namespace
}  // namespace cosmos
