// `hil_render`: records the simulated conveyor for the HIL guest, on the host (frame_tape.hpp):
// the conveyor of the cell config's sim_source section (--parts overriding its count), its
// camera-mode frames (the simulator's measuring range, in the hardware config's pixel
// format), its photo-eye beam and its parts' ground truth and model points.
//   hil_render --config CELL.yaml --hardware HW.yaml [--parts N] --out FILE
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>

#include "realtime/config/cell_config.hpp"
#include "realtime/config/hardware_config.hpp"
#include "scanner/triangulation_geometry.hpp"
#include "sim/mesh.hpp"
#include "sim/part_catalog.hpp"
#include "tests/hil/conveyor_frames.hpp"
#include "tests/hil/frame_tape.hpp"

namespace {

// The part as the conveyor placed it (load_mesh centres and scales it), for ADD-S.
cosmos::hil::TapeModel tape_model(const cosmos::PartCatalog& catalog, const std::string& name) {
  const cosmos::PartEntry& entry = catalog.at(name);
  const cosmos::TriangleMesh mesh = cosmos::load_mesh(entry.mesh_path, entry.size_mm);
  cosmos::hil::TapeModel model;
  model.name = name;
  for (const Eigen::Vector3f& vertex : mesh.vertices)
    model.points_mm.push_back(vertex.cast<double>());
  for (std::size_t i = 0; i < model.points_mm.size(); ++i)
    for (std::size_t j = i + 1; j < model.points_mm.size(); ++j)
      model.diameter_mm =
          std::max(model.diameter_mm, (model.points_mm[i] - model.points_mm[j]).norm());
  return model;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app("HIL: record the simulated conveyor's frames for the guest");
  std::string config_file, hardware_file, out;
  int parts = -1;
  app.add_option("--config", config_file, "cell YAML (scanner, catalog, sim_source)")->required();
  app.add_option("--hardware", hardware_file, "hardware YAML (camera ROI and format)")->required();
  app.add_option("--parts", parts, "parts on the conveyor (default: sim_source.parts)");
  app.add_option("--out", out, "the tape file")->required();
  CLI11_PARSE(app, argc, argv);
  try {
    const cosmos::CellConfig config = cosmos::load_cell_config(config_file);
    const cosmos::HardwareConfig hardware = cosmos::read_hardware_config(hardware_file);
    const cosmos::PartCatalog catalog = cosmos::read_part_catalog(config.cell.catalog);
    const auto conveyor = cosmos::hil::make_hil_conveyor(config, catalog, parts);
    // The simulator's whole camera-mode frame (every sensor column, its measuring range's
    // rows) in the camera's pixel format: the player writes it where it lies on the sensor,
    // and the camera crops its own band out of it.
    cosmos::HardwareConfig drawing = hardware;
    const cosmos::TriangulationGeometry geometry =
        cosmos::scanner_triangulation_geometry(config.scanner);
    drawing.camera.width_px = config.scanner.sensor_width_px;
    drawing.camera.roi_left_px = 0;
    drawing.camera.roi_top_px = geometry.roi_row_offset_px;
    drawing.camera.height_px = geometry.roi_height_px;
    cosmos::hil::ConveyorFrames frames(*conveyor, drawing);
    cosmos::hil::TapeHeader header;
    header.width_px = drawing.camera.width_px;
    header.height_px = drawing.camera.height_px;
    header.roi_top_px = drawing.camera.roi_top_px;
    header.bytes_per_pixel = cosmos::bytes_per_pixel(drawing.camera.pixel_format);
    header.last_profile = conveyor->last_profile();
    header.ticks_per_profile = frames.ticks_per_profile();
    header.beam = frames.beam_interruptions();
    for (const cosmos::PlacedSimPart& part : conveyor->placed_parts()) {
      header.parts.push_back({part.name, part.T_belt_part, part.first_profile, part.last_profile});
      if (header.model(part.name) == nullptr)
        header.models.push_back(tape_model(catalog, part.name));
    }
    cosmos::hil::FrameTapeWriter tape(out, header);
    cosmos::FrameView frame;
    while (frames.next(frame)) tape.add(frame);
    tape.finish();
    std::printf("hil: recorded %lld frames of %zu parts (%lld MiB) in %s\n",
                static_cast<long long>(conveyor->last_profile() + 1), header.parts.size(),
                static_cast<long long>(std::filesystem::file_size(out) >> 20), out.c_str());
  } catch (const std::exception& error) {
    std::printf("hil: FAIL render: %s\n", error.what());
    return 1;
  }
  return 0;
}
