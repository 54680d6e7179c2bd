#include "apps/cell_model_base.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>
#include <ctime>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "core/input_error.hpp"
#include "core/io/model_base_file.hpp"
#include "core/io/recorded_parameters.hpp"
#include "scanner/model_view_conditioning.hpp"

namespace cosmos {
namespace {

// faults.corrupt_model_base: the base as a damaged disk would hand it over, one seeded byte of
// its payload flipped, read through the very checks a real file gets. It must be refused; if it
// were not, the cell would run on a base it cannot trust.
[[noreturn]] void refuse_corrupted_copy(const std::filesystem::path& path, std::uint64_t seed) {
  std::ifstream in(path, std::ios::binary);
  std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (!in.eof() && !in.good()) throw InputError(path.string() + ": cannot read");
  if (bytes.size() <= kModelBaseHeaderBytes)
    throw InputError(path.string() + ": truncated (" + std::to_string(bytes.size()) + " bytes)");
  const std::size_t payload = bytes.size() - kModelBaseHeaderBytes;
  const std::size_t offset = kModelBaseHeaderBytes + static_cast<std::size_t>(seed % payload);
  bytes[offset] = static_cast<char>(bytes[offset] ^ 0x5A);
  const std::filesystem::path copy = std::filesystem::temp_directory_path() /
                                     ("cosmos-corrupt-" + std::to_string(::getpid()) + ".cmb");
  {
    std::ofstream out(copy, std::ios::binary);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  }
  std::string reason = "the corruption went unnoticed";
  try {
    read_model_base(copy);
  } catch (const InputError& error) {
    reason = error.what();
    const std::string prefix = copy.string() + ": ";
    if (reason.rfind(prefix, 0) == 0) reason.erase(0, prefix.size());
  }
  std::filesystem::remove(copy);
  throw InputError(path.string() + ": " + reason + " (faults.corrupt_model_base flipped byte " +
                   std::to_string(offset) + ")");
}

}  // namespace

CellModelBase read_cell_model_base(const std::filesystem::path& path, const CellConfig& config) {
  if (config.faults.corrupt_model_base) refuse_corrupted_copy(path, config.faults.seed);
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
