// Writes the seed corpus of every harness: small valid inputs made by the project's own
// writers (a range image and its sidecar, meshes of each format, the repository's YAML files,
// a model base, an LCM log, one message of each type), so the fuzzers start inside each
// format rather than at random bytes. Usage: fuzz_seeds SOURCE_DIR CORPUS_DIR.
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "core/io/model_base_file.hpp"
#include "core/io/range_image_file.hpp"
#include "core/modelbase/part_surface_summary.hpp"
#include "core/representation/cosmos_pipeline.hpp"
#include "realtime/lcm/lcm_codec.hpp"
#include "realtime/lcm/lcm_message_conversion.hpp"
#include "realtime/lcm/profile_log_writer.hpp"

namespace fs = std::filesystem;

namespace {

std::string read_bytes(const fs::path& path) {
  std::ifstream file(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
}

void write_seed(const fs::path& corpus, const std::string& harness, const std::string& name,
                const std::string& bytes) {
  fs::create_directories(corpus / harness);
  std::ofstream(corpus / harness / name, std::ios::binary | std::ios::trunc) << bytes;
}

template <class Message>
std::string encoded(const Message& message) {
  std::vector<std::uint8_t> bytes;
  cosmos::encode_message(message, bytes);
  return {bytes.begin(), bytes.end()};
}

// A quadric relief with a hole: curved patches and a grid with gaps.
cosmos::RangeImage relief(int width, int height, double tilt) {
  cosmos::RangeImage image(width, height, 0.5, 0.5);
  image.origin_x_mm = -5.0;
  image.origin_y_mm = 2.0;
  for (int row = 0; row < height; ++row)
    for (int column = 0; column < width; ++column) {
      const double x = image.x_mm(column), y = image.y_mm(row);
      const bool hole = std::hypot(column - width / 2, row - height / 3) < 3;
      image.z_mm(column, row) =
          hole ? std::nanf("") : static_cast<float>(40 + tilt * x + 0.02 * x * x - 0.01 * x * y);
    }
  return image;
}

// The range-image harness's input: format byte, sidecar length (2 bytes), sidecar, image.
void range_image_seeds(const fs::path& corpus, const fs::path& scratch) {
  int k = 0;
  for (const char* extension : {".tiff", ".pfm"}) {
    const fs::path image = scratch / (std::string("seed") + extension);
    cosmos::write_range_image(relief(24, 16, 0.1), image);
    const std::string sidecar = read_bytes(cosmos::sidecar_path(image));
    std::string input(1, static_cast<char>(k));
    input.push_back(static_cast<char>(sidecar.size() & 0xff));
    input.push_back(static_cast<char>(sidecar.size() >> 8));
    write_seed(corpus, "range_image", std::string("seed") + extension,
               input + sidecar + read_bytes(image));
    ++k;
  }
}

void mesh_seeds(const fs::path& corpus) {
  write_seed(corpus, "mesh_off", "box.off",
             "OFF\n8 6 0\n0 0 0\n2 0 0\n2 3 0\n0 3 0\n0 0 4\n2 0 4\n2 3 4\n0 3 4\n"
             "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n");
  const std::string ply_header =
      "element vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 4\nproperty list uchar int vertex_indices\nend_header\n";
  write_seed(corpus, "mesh_ply", "tetra_ascii.ply",
             "ply\nformat ascii 1.0\n" + ply_header +
                 "0 0 0\n1 0 0\n0 2 0\n0 0 4\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n");
  std::string binary = "ply\nformat binary_little_endian 1.0\n" + ply_header;
  const float vertices[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 2, 0}, {0, 0, 4}};
  for (const auto& vertex : vertices) binary.append(reinterpret_cast<const char*>(vertex), 12);
  const int faces[4][3] = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  for (const auto& face : faces) {
    binary.push_back(3);
    binary.append(reinterpret_cast<const char*>(face), 12);
  }
  write_seed(corpus, "mesh_ply", "tetra_binary.ply", binary);
  const auto facet = [](const char* a, const char* b, const char* c) {
    return std::string("facet normal 0 0 0\nouter loop\nvertex ") + a + "\nvertex " + b +
           "\nvertex " + c + "\nendloop\nendfacet\n";
  };
  write_seed(corpus, "mesh_stl", "tetra.stl",
             "solid t\n" + facet("0 0 0", "0 2 0", "1 0 0") + facet("0 0 0", "1 0 0", "0 0 4") +
                 facet("1 0 0", "0 2 0", "0 0 4") + facet("0 0 0", "0 0 4", "0 2 0") +
                 "endsolid t\n");
  std::string stl_binary(80, ' ');
  const std::uint32_t triangles = 1;
  stl_binary.append(reinterpret_cast<const char*>(&triangles), 4);
  const float triangle[12] = {0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0};
  stl_binary.append(reinterpret_cast<const char*>(triangle), 48);
  stl_binary.append(2, '\0');
  write_seed(corpus, "mesh_stl", "triangle_binary.stl", stl_binary);
  write_seed(corpus, "mesh_obj", "box.obj",
             "v 0 0 0\nv 2 0 0\nv 2 3 0\nv 0 3 0\nv 0 0 4\nv 2 0 4\nv 2 3 4\nv 0 3 4\n"
             "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n");
  // Every corner form, relative indices and the statements the reader skips.
  write_seed(corpus, "mesh_obj", "pyramid.obj",
             "# pyramid\nmtllib p.mtl\no p\ng base\ns 1\nusemtl m\nv 0 0 0\nv 2 0 0 1\n"
             "v 2 2 0 0.5 0.5 0.5\nv 0 2 0\nvt 0 0\nvt 1 0\nvn 0 0 -1\n"
             "f -4/1/1 -1/2/1 -2/1/1 -3/2/1\nv 1 1 3\nl 1 5\np 5\n"
             "f 1/1 2/2 5/1\nf 2//1 3//1 5//1\nf -3 -2 -1\nf 4 1 -1\n");
}

void yaml_seeds(const fs::path& corpus, const fs::path& source) {
  for (const auto& entry : fs::directory_iterator(source / "config")) {
    const std::string name = entry.path().filename().string();
    const std::string harness = name.rfind("cell", 0) == 0       ? "cell_config"
                                : name.rfind("hardware", 0) == 0 ? "hardware_config"
                                : name.rfind("parts", 0) == 0    ? "part_catalog"
                                                                 : "";
    if (!harness.empty()) write_seed(corpus, harness, name, read_bytes(entry.path()));
  }
}

// A base of two parts and three views analysed by the pipeline; the harness takes the
// payload after the file's header.
void model_base_seeds(const fs::path& corpus, const fs::path& scratch) {
  cosmos::ModelBase base;
  base.catalog_hash = "fuzz";
  base.parameters_text = "cosmos.fit.window_size: 5\n";
  base.parts = {{"relief", "relief.off", 30, 32, false, {}, {}, {}, {}, {}},
                {"tilted", "tilted.off", 30, 33, true, {}, {}, {}, {}, {}}};
  base.parts[0].resting_poses = {{Eigen::Matrix3d::Identity(), 4, 0.75}};
  base.parts[0].hull_vertices_mm = {{-15, -15, -4}, {15, -15, -4}, {0, 15, 6}};
  const cosmos::CosmosParameters parameters;
  for (int k = 0; k < 3; ++k) {
    const cosmos::RangeImage image = relief(28, 20, 0.2 * k);
    const cosmos::ViewAnalysis analysis = cosmos::analyze_view(image, parameters);
    cosmos::ModelBaseView view;
    view.part_index = k < 2 ? 0 : 1;
    view.view_index = 4 * k + 3;
    view.T_scanner_part.translation_mm = {0.5 * k, -1.0, 20.0};
    view.cosmos = analysis.view;
    view.moments = analysis.moments;
    cosmos::RegistrationPointParameters registration;
    registration.stride_px = 2;
    view.registration = cosmos::build_registration_points(image, registration).points;
    base.views.push_back(std::move(view));
  }
  base.clusters = {{0, {0, 1}, {}}, {1, {2}, {}}};
  cosmos::summarize_part_surfaces(base, {});
  const fs::path file = scratch / "seed.cmb";
  cosmos::write_model_base(base, file);
  write_seed(corpus, "model_base", "relief.payload",
             read_bytes(file).substr(cosmos::kModelBaseHeaderBytes));
}

std::vector<cosmos::Profile> profiles() {
  std::vector<cosmos::Profile> out;
  for (int k = 0; k < 4; ++k) {
    cosmos::Profile profile;
    profile.seq = static_cast<std::uint64_t>(k);
    profile.encoder_ticks = 10 * k;
    profile.t_us = 1000 * k;
    profile.x0_mm = -8.0;
    profile.dx_mm = 0.5;
    profile.z_mm = {1.0f, 2.0f, cosmos::Profile::kNoData, 3.0f + static_cast<float>(k)};
    out.push_back(profile);
  }
  return out;
}

void lcm_seeds(const fs::path& corpus, const fs::path& scratch) {
  const std::vector<cosmos::Profile> stream = profiles();
  const fs::path log = scratch / "seed.lcmlog";
  cosmos::write_profile_log(log, stream);
  write_seed(corpus, "lcm_log", "profiles.lcmlog", read_bytes(log));

  cosmos_lcm::range_profile_t profile;
  cosmos::to_message(stream[1], profile);
  write_seed(corpus, "lcm_range_profile", "profile", encoded(profile));
  cosmos::PartPose pose;
  pose.part_name = "relief";
  pose.part_index = 0;
  pose.view_index = 3;
  pose.status = cosmos::PoseStatus::kOk;
  pose.translation_cell_part_mm = {10, -20, 30};
  pose.score = 0.8;
  cosmos_lcm::part_pose_t pose_message;
  cosmos::to_message(pose, pose_message);
  write_seed(corpus, "lcm_part_pose", "pose", encoded(pose_message));
  cosmos_lcm::cell_status_t status_message;
  cosmos::to_message(cosmos::CellStatus{}, status_message);
  write_seed(corpus, "lcm_cell_status", "status", encoded(status_message));
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: fuzz_seeds SOURCE_DIR CORPUS_DIR\n");
    return 2;
  }
  const fs::path source = argv[1], corpus = argv[2];
  const fs::path scratch = corpus / ".scratch";
  fs::create_directories(scratch);
  range_image_seeds(corpus, scratch);
  mesh_seeds(corpus);
  yaml_seeds(corpus, source);
  model_base_seeds(corpus, scratch);
  lcm_seeds(corpus, scratch);
  fs::remove_all(scratch);
  return 0;
}
