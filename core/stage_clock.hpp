#pragma once
// The clock the recognition stages are timed with (RecognitionTimings): monotonic, so a
// stage's time never runs backwards when the wall clock is set.
#include <chrono>

namespace cosmos {

using StageClock = std::chrono::steady_clock;

inline double elapsed_ms(StageClock::time_point since) {
  return std::chrono::duration<double, std::milli>(StageClock::now() - since).count();
}

}  // namespace cosmos
