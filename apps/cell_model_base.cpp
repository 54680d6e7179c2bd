#include "apps/cell_model_base.hpp"

#include "core/input_error.hpp"
#include "core/io/model_base_file.hpp"
#include "core/io/recorded_parameters.hpp"
#include "scanner/model_view_conditioning.hpp"

namespace cosmos {

CellModelBase read_cell_model_base(const std::filesystem::path& path, const CellConfig& config) {
  CellModelBase loaded{read_model_base(path), {}};
  if (const auto difference = conditioning_difference(
          model_base_view_conditioning(loaded.base, path), config.conditioning)) {
    throw InputError(path.string() + ": its views were taken with other conditioning: " +
                     difference->key + " is " + difference->actual + ", " + config.file.string() +
                     " gives " + difference->expected);
  }
  loaded.cosmos = model_base_cosmos_parameters(loaded.base, path);
  return loaded;
}

}  // namespace cosmos
