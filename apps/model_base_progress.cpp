#include "apps/model_base_progress.hpp"

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <memory>
#include <string>

namespace cosmos {

ModelBaseProgress progress_printer(const PartCatalog& catalog) {
  const bool terminal = ::isatty(::fileno(stderr)) != 0;
  auto printed_parts = std::make_shared<int>(0);
  const auto start = std::chrono::steady_clock::now();
  return [&catalog, terminal, printed_parts, start](const ModelBaseBuildProgress& p) {
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (terminal) {
      constexpr int kWidth = 30;
      const int filled = p.views_total > 0 ? kWidth * p.views_done / p.views_total : kWidth;
      const std::string bar = std::string(static_cast<std::size_t>(filled), '#') +
                              std::string(static_cast<std::size_t>(kWidth - filled), '.');
      const int current = std::min(p.parts_done, p.parts_total - 1);
      std::fprintf(
          stderr, "\rmodelbase: [%s] %d/%d views, part %d/%d %-20s %6.0f s", bar.c_str(),
          p.views_done, p.views_total, current + 1, p.parts_total,
          current >= 0 ? catalog.parts[static_cast<std::size_t>(current)].name.c_str() : "",
          seconds);
      if (p.views_done == p.views_total) std::fputc('\n', stderr);
    } else {
      for (; *printed_parts < p.parts_done; ++*printed_parts)
        std::fprintf(stderr, "modelbase: part %d/%d %s scanned (%.0f s)\n", *printed_parts + 1,
                     p.parts_total,
                     catalog.parts[static_cast<std::size_t>(*printed_parts)].name.c_str(), seconds);
    }
    std::fflush(stderr);
  };
}

}  // namespace cosmos
