#include "apps/model_base_progress.hpp"

#include <sys/ioctl.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <memory>

namespace cosmos {

std::string clock_text(double seconds) {
  const long total = std::max(0L, static_cast<long>(seconds + 0.5));
  char text[32];
  if (total >= 3600)
    std::snprintf(text, sizeof text, "%ld:%02ld:%02ld", total / 3600, total / 60 % 60, total % 60);
  else
    std::snprintf(text, sizeof text, "%ld:%02ld", total / 60, total % 60);
  return text;
}

ProgressReporter::ProgressReporter(std::string label, std::string unit, LogText log_text)
    : label_(std::move(label)),
      unit_(std::move(unit)),
      log_text_(std::move(log_text)),
      terminal_(::isatty(::fileno(stderr)) != 0),
      start_(std::chrono::steady_clock::now()) {}

void ProgressReporter::update(double fraction, int done, int total, const std::string& item,
                              int line_every) {
  if (finished_) return;
  fraction = std::clamp(fraction, 0.0, 1.0);
  const double elapsed_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  // The rate so far predicts the rest; nothing is predicted before the first few percent.
  const std::string remaining =
      fraction >= 0.02 && fraction < 1.0
          ? "about " + clock_text(elapsed_s * (1.0 - fraction) / fraction) + " remaining"
          : "";
  const bool complete = done >= total;
  if (terminal_) {
    constexpr int kWidth = 20;
    const int filled = static_cast<int>(kWidth * fraction);
    std::string line = label_ + ": [" + std::string(static_cast<std::size_t>(filled), '#') +
                       std::string(static_cast<std::size_t>(kWidth - filled), '.') + "] " +
                       std::to_string(done) + "/" + std::to_string(total) + " " + unit_ + ", " +
                       clock_text(elapsed_s) + " elapsed";
    if (!remaining.empty()) line += ", " + remaining;
    if (!item.empty() && !complete) line += ", " + item;
    // A line longer than the terminal would wrap, and \r would then redraw only its last row.
    struct winsize size {};
    if (::ioctl(::fileno(stderr), TIOCGWINSZ, &size) == 0 && size.ws_col > 1 &&
        line.size() >= size.ws_col)
      line.resize(size.ws_col - 1U);
    // \033[K clears what a longer previous line left behind.
    std::fprintf(stderr, "\r%s\033[K", line.c_str());
    if (complete) std::fputc('\n', stderr);
  } else {
    for (int item_done = logged_done_ + 1; item_done <= done; ++item_done) {
      if (item_done % line_every != 0 && item_done != total) continue;
      std::fprintf(stderr, "%s: %s (%s elapsed%s%s)\n", label_.c_str(),
                   log_text_(item_done, total).c_str(), clock_text(elapsed_s).c_str(),
                   remaining.empty() ? "" : ", ", remaining.c_str());
    }
    logged_done_ = std::max(logged_done_, done);
  }
  finished_ = complete;
  std::fflush(stderr);
}

ModelBaseProgress progress_printer(const PartCatalog& catalog) {
  auto reporter =
      std::make_shared<ProgressReporter>("modelbase", "parts", [&catalog](int done, int total) {
        return "part " + std::to_string(done) + "/" + std::to_string(total) + " " +
               catalog.parts[static_cast<std::size_t>(done - 1)].name + " scanned";
      });
  return [&catalog, reporter](const ModelBaseBuildProgress& p) {
    const double fraction =
        p.views_total > 0 ? static_cast<double>(p.views_done) / p.views_total : 1.0;
    const int current = std::min(p.parts_done, p.parts_total - 1);
    const std::string item =
        current >= 0 ? "scanning " + catalog.parts[static_cast<std::size_t>(current)].name : "";
    reporter->update(fraction, p.parts_done, p.parts_total, item);
  };
}

}  // namespace cosmos
