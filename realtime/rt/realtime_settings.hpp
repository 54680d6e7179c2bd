#pragma once
// Best-effort real-time setup of the calling thread, so that other processes and page faults
// cannot delay a profile: SCHED_FIFO priority, CPU affinity and locked memory when the
// process is permitted. A development machine or an unprivileged container usually is not;
// then each setting that could not be applied becomes a one-line warning and the cell runs
// without it.
#include <string>
#include <vector>

#include "core/parameter_visitor.hpp"

namespace cosmos {

struct RealtimeSettings {
  int sched_fifo_priority = 0;  // 1..99: SCHED_FIFO at that priority; 0: leave the policy
  int cpu = -1;                 // >= 0: pin the thread to that CPU; -1: no affinity
  bool lock_memory = false;     // mlockall(MCL_CURRENT | MCL_FUTURE): no page faults later

  template <class Visitor>
  void visit(Visitor& v) {
    v("sched_fifo_priority", sched_fifo_priority,
      "1..99: SCHED_FIFO at that priority; 0: leave the policy", Range{0, 99});
    v("cpu", cpu, ">= 0: pin the acquisition thread to that CPU; -1: no affinity",
      Range{-1, 1023});  // CPU_SETSIZE - 1
    v("lock_memory", lock_memory, "mlockall: no page faults once running");
  }
};

struct RealtimeReport {
  bool sched_fifo_applied = false;
  int sched_fifo_priority = 0;  // the priority applied, 0 when none
  bool affinity_applied = false;
  int cpu = -1;  // the CPU pinned to, -1 when none
  bool memory_locked = false;
  // One line per requested setting that was not applied, e.g.
  // "SCHED_FIFO priority 80 not permitted (EPERM): running SCHED_OTHER".
  std::vector<std::string> warnings;
};

// Applies the settings to the calling thread (mlockall is per process: it covers every
// thread). Never throws; settings that fail are reported and left as they were.
RealtimeReport apply_realtime_settings(const RealtimeSettings& settings) noexcept;

// One line for logs: "SCHED_FIFO 80, cpu 2, memory locked" or "no real-time settings".
std::string describe_realtime_report(const RealtimeReport& report);

}  // namespace cosmos
