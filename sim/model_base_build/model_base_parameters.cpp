#include "sim/model_base_build/model_base_parameters.hpp"

#include <nlohmann/json.hpp>

#include "core/input_error.hpp"
#include "core/io/model_base_file.hpp"
#include "core/io/parameters_text.hpp"
#include "sim/model_base_build/view_direction_subset.hpp"

namespace cosmos {
namespace {

void add_cosmos(ParameterText& t, const CosmosParameters& p) {
  t.set_integer("cosmos.fit.window_size", p.fit.window_size);
  t.set_flag("cosmos.fit.bicubic", p.fit.bicubic);
  t.set_number("cosmos.fit.depth_jump_mm", p.fit.depth_jump_mm);
  t.set_integer("cosmos.fit.min_samples", p.fit.min_samples);
  t.set_number("cosmos.fit.crease_residual_mm", p.fit.crease_residual_mm);
  t.set_integer("cosmos.smoothing.iterations", p.smoothing.iterations);
  t.set_number("cosmos.smoothing.normal_scale_deg", p.smoothing.normal_scale_deg);
  t.set_number("cosmos.smoothing.curvature_scale", p.smoothing.curvature_scale);
  t.set_number("cosmos.smoothing.self_weight", p.smoothing.self_weight);
  t.set_number("cosmos.smoothing.curvature_floor_per_mm", p.smoothing.curvature_floor_per_mm);
  t.set_number("cosmos.shape_index.planar_sensitivity_mm", p.shape_index.planar_sensitivity_mm);
  t.set_number("cosmos.shape_index.max_tilt_deg", p.shape_index.max_tilt_deg);
  t.set_number("cosmos.segmentation.shape_diameter_limit", p.segmentation.shape_diameter_limit);
  t.set_integer("cosmos.segmentation.max_patches", p.segmentation.max_patches);
  t.set_number("cosmos.segmentation.adaptive_start_limit", p.segmentation.adaptive_start_limit);
  t.set_number("cosmos.segmentation.adaptive_limit_step", p.segmentation.adaptive_limit_step);
  t.set_number("cosmos.segmentation.adaptive_max_limit", p.segmentation.adaptive_max_limit);
  t.set_integer("cosmos.segmentation.boundary_refinement_passes",
                p.segmentation.boundary_refinement_passes);
  t.set_number("cosmos.segmentation.min_patch_area_fraction",
               p.segmentation.min_patch_area_fraction);
  t.set_number("cosmos.segmentation.planar_crease_deg", p.segmentation.planar_crease_deg);
  t.set_number("cosmos.segmentation.seed_shape_index_quantum",
               p.segmentation.seed_shape_index_quantum);
  t.set_number("cosmos.spectrum.bin_width", p.spectrum.bin_width);
}

void add_registration(ParameterText& t, const RegistrationPointParameters& p) {
  t.set_integer("registration.stride_px", p.stride_px);
  t.set_integer("registration.window_size", p.window_size);
  t.set_number("registration.depth_jump_mm", p.depth_jump_mm);
  t.set_flag("registration.quadric_fit", p.quadric_fit);
  t.set_number("registration.max_residual_noise_ratio", p.max_residual_noise_ratio);
  t.set_number("registration.max_tilt_deg", p.max_tilt_deg);
  t.set_number("registration.z_noise_sigma_mm", p.z_noise_sigma_mm);
}

void add_scanner(ParameterText& t, const ScannerParameters& p) {
  t.set_number("scanner.encoder_mm_per_tick", p.encoder_mm_per_tick);
  t.set_integer("scanner.encoder_ticks_per_profile", p.encoder_ticks_per_profile);
  t.set_number("scanner.triangulation_angle_deg", p.triangulation_angle_deg);
  t.set_number("scanner.camera_height_mm", p.camera_height_mm);
  t.set_number("scanner.laser_height_mm", p.laser_height_mm);
  t.set_text("scanner.laser_model", p.laser_model == LaserModel::kFan ? "fan" : "parallel");
  t.set_number("scanner.field_of_view_mm", p.field_of_view_mm);
  t.set_integer("scanner.points_per_profile", p.points_per_profile);
  t.set_integer("scanner.sensor_width_px", p.sensor_width_px);
  t.set_integer("scanner.sensor_height_px", p.sensor_height_px);
  t.set_integer("scanner.roi_height_px", p.roi_height_px);
  t.set_number("scanner.belt_row_fraction_of_roi", p.belt_row_fraction_of_roi);
  t.set_number("scanner.max_incidence_deg", p.max_incidence_deg);
  t.set_number("scanner.min_reflected_intensity", p.min_reflected_intensity);
  t.set_number("scanner.reflectivity", p.reflectivity);
  t.set_number("scanner.z_noise_mm", p.z_noise_mm);
  t.set_unsigned("scanner.seed", p.seed);
  t.set_number("scanner.background_height_mm", p.background_height_mm);
}

}  // namespace

std::string model_base_parameters_text(const CosmosParameters& cosmos,
                                       const ScannerParameters& scanner,
                                       const RegistrationPointParameters& registration,
                                       int view_count, const ViewGroupingParameters& grouping) {
  ParameterText text;
  add_cosmos(text, cosmos);
  add_registration(text, registration);
  add_scanner(text, scanner);
  text.set_integer("views.count", view_count);
  text.set_integer("views.sphere_subdivisions", kViewSphereSubdivisions);
  text.set_text("views.subset",
                "spread: face centres, then once-subdivided middles, then the rest");
  text.set_text("views.scan_mode", "profile");
  if (grouping.cluster_count > 0) {
    text.set_integer("grouping.cluster_count", grouping.cluster_count);
  } else {
    text.set_number("grouping.cut_level", grouping.cut_level);
  }
  text.set_text("grouping.method", "complete-link, Eq. 4.3 on moments m1..m10");
  return text.text();
}

ModelBase read_model_base_for(const std::filesystem::path& path, const CosmosParameters& cosmos) {
  ModelBase base = read_model_base(path);
  ParameterText expected;
  add_cosmos(expected, cosmos);
  const nlohmann::json recorded = nlohmann::json::parse(base.parameters_text, nullptr, false);
  const std::string recorded_cosmos = recorded.is_object() && recorded.contains("cosmos")
                                          ? nlohmann::json{{"cosmos", recorded["cosmos"]}}.dump(2)
                                          : std::string("{}");
  if (const auto difference = first_parameter_difference(expected.text(), recorded_cosmos))
    throw InputError(path.string() + ": built with other parameters: " + difference->key + " is " +
                     difference->actual + ", this recognizer uses " + difference->expected);
  return base;
}

}  // namespace cosmos
