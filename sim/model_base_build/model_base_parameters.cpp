#include "sim/model_base_build/model_base_parameters.hpp"

#include <cmath>

#include "core/input_error.hpp"
#include "sim/model_base_build/view_direction_subset.hpp"

namespace cosmos {
namespace {

double micrometre_rounded(double mm) { return std::round(mm * 1e6) / 1e6; }

std::string conditioning_text(const ModelViewConditioning& conditioning) {
  ParameterText text;
  text.set_parameters("conditioning", conditioning);
  return text.text();
}

}  // namespace

ModelViewConditioning model_view_conditioning(const ScannerParameters& scanner,
                                              const ConditioningParameters& conditioning) {
  return {micrometre_rounded(scanner.sample_spacing_mm(scanner.points_per_profile)),
          micrometre_rounded(scanner.profile_step_mm()), conditioning.height_threshold_mm};
}

ModelViewConditioning live_scan_conditioning(const ConditioningParameters& conditioning) {
  const double grid_mm = micrometre_rounded(conditioning.grid_mm);
  return {grid_mm, grid_mm, conditioning.height_threshold_mm};
}

std::string model_base_parameters_text(const ScannerParameters& scanner,
                                       const ModelBaseBuildSettings& settings) {
  ParameterText text;
  text.set_parameters("cosmos", settings.cosmos);
  text.set_parameters("registration", settings.registration);
  text.set_parameters("scanner", scanner, {"line_rate_hz", "camera"});
  text.set_parameters("conditioning", model_view_conditioning(scanner, settings.conditioning));
  text.set_parameters("grouping", settings.grouping);
  text.set_integer("views.count", settings.view_count);
  text.set_integer("views.sphere_subdivisions", kViewSphereSubdivisions);
  text.set_text("views.subset",
                "spread: face centres, then once-subdivided middles, then the rest");
  text.set_text("views.scan_mode", "profile");
  text.set_text("grouping.method", "complete-link, Eq. 4.3 on moments m1..m10");
  return text.text();
}

namespace {

// The parameters under `prefix` the base recorded, InputError naming the file and the first
// key it lacks.
template <class Parameters>
Parameters recorded_parameters(const ModelBase& base, const std::filesystem::path& file,
                               const std::string& prefix) {
  const auto values = ParameterValues::parse(base.parameters_text);
  if (!values) throw InputError(file.string() + ": its parameters text is not a JSON object");
  Parameters parameters;
  if (const auto missing = read_parameter_values(*values, prefix, parameters))
    throw InputError(file.string() + ": built without " + *missing +
                     " (a base older than that parameter): rebuild it");
  return parameters;
}

}  // namespace

CosmosParameters model_base_cosmos_parameters(const ModelBase& base,
                                              const std::filesystem::path& file) {
  return recorded_parameters<CosmosParameters>(base, file, "cosmos");
}

ModelViewConditioning model_base_view_conditioning(const ModelBase& base,
                                                   const std::filesystem::path& file) {
  return recorded_parameters<ModelViewConditioning>(base, file, "conditioning");
}

std::optional<ParameterDifference> conditioning_difference(
    const ModelViewConditioning& recorded, const ConditioningParameters& conditioning) {
  return first_parameter_difference(conditioning_text(live_scan_conditioning(conditioning)),
                                    conditioning_text(recorded));
}

}  // namespace cosmos
