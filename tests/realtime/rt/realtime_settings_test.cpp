// Best-effort real-time settings: nothing requested, nothing done; impossible requests give
// one-line warnings; permitted requests are really in effect (checked through the OS), and a
// refused one leaves the thread as it was. Each case runs on its own thread so the test
// process never keeps a real-time policy or a pinned CPU.
#include "realtime/rt/realtime_settings.hpp"

#include <gtest/gtest.h>
#include <pthread.h>
#include <sched.h>
#include <sys/mman.h>

#include <string>
#include <thread>

namespace cosmos {
namespace {

RealtimeReport apply_on_own_thread(const RealtimeSettings& settings,
                                   void (*check)(const RealtimeReport&) = nullptr) {
  RealtimeReport report;
  std::thread thread([&] {
    report = apply_realtime_settings(settings);
    if (check != nullptr) check(report);
  });
  thread.join();
  return report;
}

int first_allowed_cpu() {
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof(set), &set) != 0) return 0;
  for (int cpu = 0; cpu < CPU_SETSIZE; ++cpu) {
    if (CPU_ISSET(cpu, &set)) return cpu;
  }
  return 0;
}

TEST(RealtimeSettings, DefaultsApplyNothing) {
  const RealtimeReport report = apply_on_own_thread(RealtimeSettings{});
  EXPECT_FALSE(report.sched_fifo_applied);
  EXPECT_FALSE(report.affinity_applied);
  EXPECT_FALSE(report.memory_locked);
  EXPECT_EQ(report.cpu, -1);
  EXPECT_EQ(report.sched_fifo_priority, 0);
  EXPECT_TRUE(report.warnings.empty());
  EXPECT_EQ(describe_realtime_report(report), "no real-time settings");
}

TEST(RealtimeSettings, ImpossibleRequestsWarnOnceEach) {
  RealtimeSettings settings;
  settings.cpu = 4096;
  settings.sched_fifo_priority = 150;
  const RealtimeReport report = apply_on_own_thread(settings);
  EXPECT_FALSE(report.affinity_applied);
  EXPECT_FALSE(report.sched_fifo_applied);
  ASSERT_EQ(report.warnings.size(), 2u);
  EXPECT_NE(report.warnings[0].find("cpu 4096"), std::string::npos) << report.warnings[0];
  EXPECT_NE(report.warnings[1].find("SCHED_FIFO priority 150 out of range [1, 99]"),
            std::string::npos)
      << report.warnings[1];
  for (const std::string& warning : report.warnings) {
    EXPECT_EQ(warning.find('\n'), std::string::npos);
  }
}

TEST(RealtimeSettings, CpuAffinityIsInEffectWhenApplied) {
  RealtimeSettings settings;
  settings.cpu = first_allowed_cpu();
  const RealtimeReport report = apply_on_own_thread(settings, [](const RealtimeReport& r) {
    if (!r.affinity_applied) return;
    cpu_set_t set;
    CPU_ZERO(&set);
    ASSERT_EQ(pthread_getaffinity_np(pthread_self(), sizeof(set), &set), 0);
    EXPECT_EQ(CPU_COUNT(&set), 1);
    EXPECT_TRUE(CPU_ISSET(r.cpu, &set));
  });
  // A CPU this process may use: pinning to it is always permitted.
  EXPECT_TRUE(report.affinity_applied);
  EXPECT_EQ(report.cpu, settings.cpu);
  EXPECT_TRUE(report.warnings.empty());
}

TEST(RealtimeSettings, SchedFifoIsAppliedOrWarned) {
  RealtimeSettings settings;
  settings.sched_fifo_priority = 10;
  const RealtimeReport report = apply_on_own_thread(settings, [](const RealtimeReport& r) {
    int policy = -1;
    sched_param parameter{};
    ASSERT_EQ(pthread_getschedparam(pthread_self(), &policy, &parameter), 0);
    if (r.sched_fifo_applied) {
      EXPECT_EQ(policy, SCHED_FIFO);
      EXPECT_EQ(parameter.sched_priority, 10);
    } else {
      EXPECT_NE(policy, SCHED_FIFO);  // a refused request leaves the policy alone
    }
  });
  // Root or CAP_SYS_NICE usually succeeds; anyone else gets exactly one warning.
  if (report.sched_fifo_applied) {
    EXPECT_EQ(report.sched_fifo_priority, 10);
    EXPECT_TRUE(report.warnings.empty());
    EXPECT_EQ(describe_realtime_report(report), "SCHED_FIFO 10");
  } else {
    ASSERT_EQ(report.warnings.size(), 1u);
    EXPECT_EQ(report.warnings[0].rfind("SCHED_FIFO priority 10 ", 0), 0u) << report.warnings[0];
    EXPECT_EQ(report.sched_fifo_priority, 0);
  }
}

TEST(RealtimeSettings, MemoryIsLockedOrWarned) {
  RealtimeSettings settings;
  settings.lock_memory = true;
  const RealtimeReport report = apply_on_own_thread(settings);
  if (report.memory_locked) {
    EXPECT_TRUE(report.warnings.empty());
    munlockall();  // the rest of the test process need not stay locked
  } else {
    ASSERT_EQ(report.warnings.size(), 1u);
    EXPECT_EQ(report.warnings[0].rfind("mlockall failed (", 0), 0u) << report.warnings[0];
  }
}

}  // namespace
}  // namespace cosmos
