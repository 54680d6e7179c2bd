#include "apps/cell_model_base.hpp"

#include <sys/stat.h>

#include <cstdio>
#include <ctime>
#include <string>

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
  // A cached base is reused silently otherwise: the line says which file the run recognizes
  // against and since when it exists, so a stale or unexpected base is visible.
  std::string written_text = "?";
  struct stat file_status {};
  if (::stat(path.c_str(), &file_status) == 0) {
    char text[32];
    std::strftime(text, sizeof text, "%Y-%m-%d %H:%M", std::localtime(&file_status.st_mtime));
    written_text = text;
  }
  std::fprintf(stderr, "cell: model base %s (%zu parts, %zu views, written %s)\n",
               path.string().c_str(), loaded.base.parts.size(), loaded.base.views.size(),
               written_text.c_str());
  return loaded;
}

}  // namespace cosmos
