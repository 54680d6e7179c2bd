#include "scanner/model_view_conditioning.hpp"

#include <cmath>
#include <string>

#include "core/io/recorded_parameters.hpp"

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
