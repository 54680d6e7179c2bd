#include "realtime/rt/realtime_settings.hpp"

#include <pthread.h>
#include <sched.h>
#include <string.h>
#include <sys/mman.h>

#include <cerrno>

namespace cosmos {
namespace {

// "EPERM" rather than the locale's sentence: short, greppable, the same on every machine.
std::string error_name(int error) {
  const char* name = strerrorname_np(error);
  return name != nullptr ? name : "error " + std::to_string(error);
}

std::string current_policy_name() {
  int policy = SCHED_OTHER;
  sched_param parameter{};
  if (pthread_getschedparam(pthread_self(), &policy, &parameter) != 0) return "unchanged";
  switch (policy) {
    case SCHED_FIFO:
      return "SCHED_FIFO " + std::to_string(parameter.sched_priority);
    case SCHED_RR:
      return "SCHED_RR " + std::to_string(parameter.sched_priority);
    case SCHED_BATCH:
      return "SCHED_BATCH";
    case SCHED_IDLE:
      return "SCHED_IDLE";
    default:
      return "SCHED_OTHER";
  }
}

// The CPUs the thread may run on now, as "0-3" or "0,2", for the warning.
std::string allowed_cpus() {
  cpu_set_t set;
  CPU_ZERO(&set);
  if (pthread_getaffinity_np(pthread_self(), sizeof(set), &set) != 0) return "any CPU";
  std::string text;
  for (int cpu = 0; cpu < CPU_SETSIZE; ++cpu) {
    if (!CPU_ISSET(cpu, &set)) continue;
    int last = cpu;
    while (last + 1 < CPU_SETSIZE && CPU_ISSET(last + 1, &set)) ++last;
    if (!text.empty()) text += ",";
    text += std::to_string(cpu);
    if (last > cpu) text.append(1, '-').append(std::to_string(last));
    cpu = last;
  }
  return text.empty() ? "any CPU" : "CPUs " + text;
}

void apply_affinity(int cpu, RealtimeReport& report) {
  const std::string request = "CPU affinity to cpu " + std::to_string(cpu);
  if (cpu < 0 || cpu >= CPU_SETSIZE) {
    report.warnings.push_back(request + " not possible (must be -1 or 0.." +
                              std::to_string(CPU_SETSIZE - 1) + "): running on " + allowed_cpus());
    return;
  }
  cpu_set_t set;
  CPU_ZERO(&set);
  CPU_SET(cpu, &set);
  const int error = pthread_setaffinity_np(pthread_self(), sizeof(set), &set);
  if (error != 0) {
    report.warnings.push_back(request + " failed (" + error_name(error) + "): running on " +
                              allowed_cpus());
    return;
  }
  report.affinity_applied = true;
  report.cpu = cpu;
}

void lock_memory(RealtimeReport& report) {
  if (mlockall(MCL_CURRENT | MCL_FUTURE) != 0) {
    const int error = errno;
    report.warnings.push_back("mlockall failed (" + error_name(error) +
                              (error == ENOMEM ? ", RLIMIT_MEMLOCK too low" : "") +
                              "): memory may be paged out");
    return;
  }
  report.memory_locked = true;
}

void apply_sched_fifo(int priority, RealtimeReport& report) {
  const std::string request = "SCHED_FIFO priority " + std::to_string(priority);
  const int low = sched_get_priority_min(SCHED_FIFO);
  const int high = sched_get_priority_max(SCHED_FIFO);
  if (priority < low || priority > high) {
    report.warnings.push_back(request + " out of range [" + std::to_string(low) + ", " +
                              std::to_string(high) + "]: running " + current_policy_name());
    return;
  }
  sched_param parameter{};
  parameter.sched_priority = priority;
  const int error = pthread_setschedparam(pthread_self(), SCHED_FIFO, &parameter);
  if (error != 0) {
    const std::string what = error == EPERM ? " not permitted (" : " failed (";
    report.warnings.push_back(request + what + error_name(error) + "): running " +
                              current_policy_name());
    return;
  }
  report.sched_fifo_applied = true;
  report.sched_fifo_priority = priority;
}

}  // namespace

RealtimeReport apply_realtime_settings(const RealtimeSettings& settings) noexcept {
  RealtimeReport report;
  // Affinity first, so the thread never runs real-time on a CPU it was not meant for; memory
  // before the priority, so faulting in the whole process does not run at SCHED_FIFO.
  if (settings.cpu != -1) apply_affinity(settings.cpu, report);
  if (settings.lock_memory) lock_memory(report);
  if (settings.sched_fifo_priority != 0) apply_sched_fifo(settings.sched_fifo_priority, report);
  return report;
}

std::string describe_realtime_report(const RealtimeReport& report) {
  std::string text;
  const auto add = [&text](const std::string& part) { text += (text.empty() ? "" : ", ") + part; };
  if (report.sched_fifo_applied) add("SCHED_FIFO " + std::to_string(report.sched_fifo_priority));
  if (report.affinity_applied) add("cpu " + std::to_string(report.cpu));
  if (report.memory_locked) add("memory locked");
  return text.empty() ? "no real-time settings" : text;
}

}  // namespace cosmos
