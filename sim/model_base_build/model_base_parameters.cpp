#include "sim/model_base_build/model_base_parameters.hpp"

#include "sim/model_base_build/view_direction_subset.hpp"

namespace cosmos {

std::string model_base_parameters_text(const ScannerParameters& scanner,
                                       const ModelBaseBuildSettings& settings) {
  ParameterText text;
  text.set_parameters("cosmos", settings.cosmos);
  text.set_parameters("registration", settings.registration);
  text.set_parameters("scanner", scanner, {"line_rate_hz", "camera"});
  text.set_parameters("conditioning", model_view_conditioning(scanner, settings.conditioning));
  text.set_parameters("grouping", settings.grouping);
  text.set_parameters("resting", settings.resting);
  text.set_parameters("field", settings.field);
  text.set_parameters("confusion", settings.confusion);
  text.set_integer("views.count", settings.view_count);
  text.set_integer("views.sphere_subdivisions", kViewSphereSubdivisions);
  text.set_text("views.subset",
                "spread: face centres, then once-subdivided middles, then the rest");
  text.set_text("views.scan_mode", "profile");
  text.set_text("grouping.method", "complete-link, Eq. 4.3 on moments m1..m10");
  return text.text();
}

}  // namespace cosmos
