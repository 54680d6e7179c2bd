#include "core/io/cosmos_json.hpp"

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "core/input_error.hpp"

namespace cosmos {
namespace {

// Insertion order is kept so the file reads top-down like the header's key list.
using Json = nlohmann::ordered_json;

// JSON has no NaN or infinity; a value that is not a number is written as null.
Json number(double value) { return std::isfinite(value) ? Json(value) : Json(nullptr); }

Json vector3(const Eigen::Vector3d& v) {
  return Json::array({number(v.x()), number(v.y()), number(v.z())});
}

Json patch_json(const Csmp& patch) {
  Json neighbors = Json::array();
  for (const PatchNeighbor& neighbor : patch.neighbors) neighbors.push_back(neighbor.patch);
  return Json{
      {"id", patch.id},
      {"area_mm2", number(patch.area_mm2)},
      {"shape_index", number(patch.shape_index)},
      {"shape_index_min", number(patch.shape_index_min)},
      {"shape_index_max", number(patch.shape_index_max)},
      {"curvedness", number(patch.mean_curvedness_per_mm)},
      {"normal", vector3(patch.mean_normal)},
      {"centroid_mm", vector3(patch.centroid_mm)},
      {"pixels", patch.pixels},
      {"planar", patch.planar},
      {"neighbors", std::move(neighbors)},
  };
}

Json spectrum_json(const ShapeSpectrum& spectrum) {
  Json bins = Json::array();
  for (double bin : spectrum.bins) bins.push_back(number(bin));
  return Json{
      {"bin_width", number(spectrum.bin_width)},
      {"bins", std::move(bins)},
      {"planar_fraction", number(spectrum.planar_fraction)},
  };
}

}  // namespace

std::string cosmos_json_text(const ViewAnalysis& analysis) {
  Json patches = Json::array();
  for (const Csmp& patch : analysis.view.patches) patches.push_back(patch_json(patch));
  // The header's m1..m10: element 10 of MomentVector (the planar fraction) is in "spectrum".
  Json moments = Json::array();
  for (int k = 0; k < kSpectrumMoments; ++k)
    moments.push_back(number(analysis.moments[static_cast<std::size_t>(k)]));

  const Json document{
      {"valid_pixels", analysis.valid_pixels},
      {"visible_area_mm2", number(analysis.spectrum.visible_area_mm2)},
      {"shape_diameter_limit", number(analysis.segmentation.shape_diameter_limit)},
      {"patches", std::move(patches)},
      {"spectrum", spectrum_json(analysis.spectrum)},
      {"moments", std::move(moments)},
  };
  return document.dump(2) + "\n";
}

void write_cosmos_json(const ViewAnalysis& analysis, const std::filesystem::path& path) {
  const std::string text = cosmos_json_text(analysis);
  std::ofstream file(path, std::ios::binary);
  if (!file) throw InputError(path.string() + ": cannot open for writing");
  file << text;
  file.flush();
  if (!file) throw InputError(path.string() + ": write failed");
}

}  // namespace cosmos
