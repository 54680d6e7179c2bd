#pragma once
// Progress of the commands that run for minutes on stderr: the model-base build (`cosmos
// modelbase build`, and `cosmos cell` building its base on first run) and `cosmos eval`. On a
// terminal a bar is redrawn in place with the items done, the time elapsed and an estimate of
// the time remaining; in a log (stderr not a terminal) one line per finished step, so a log of
// a long build stays short and readable.
#include <chrono>
#include <functional>
#include <string>

#include "sim/model_base_build/model_base_builder.hpp"
#include "sim/part_catalog.hpp"

namespace cosmos {

class ProgressReporter {
 public:
  // What a log line says of item `done` (1-based) of `total`, e.g. "part 3/25 cup scanned".
  using LogText = std::function<std::string(int done, int total)>;

  // `label` starts every line ("modelbase"), `unit` names the items counted on the bar
  // ("parts"), `log_text` the finished item in a log line.
  ProgressReporter(std::string label, std::string unit, LogText log_text);

  // `fraction` of the whole work done in [0, 1] (finer than the items when an item is long),
  // `done` of `total` items finished, `item` what is being worked on (may be empty).
  // `line_every`: in a log, a line each time `done` reaches a multiple of it (or `total`).
  void update(double fraction, int done, int total, const std::string& item, int line_every = 1);

 private:
  std::string label_;
  std::string unit_;
  LogText log_text_;
  bool terminal_;
  bool finished_ = false;
  int logged_done_ = 0;
  std::chrono::steady_clock::time_point start_;
};

// "1:05" (minutes:seconds) or "1:02:05" for a duration in seconds.
std::string clock_text(double seconds);

ModelBaseProgress progress_printer(const PartCatalog& catalog);

}  // namespace cosmos
