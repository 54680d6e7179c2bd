#include "tests/hil/realtime_threads.hpp"

#include <pthread.h>
#include <sched.h>

namespace cosmos::hil {

bool run_this_thread_fifo(int priority) {
  sched_param parameters{};
  parameters.sched_priority = priority;
  return pthread_setschedparam(pthread_self(), SCHED_FIFO, &parameters) == 0;
}

}  // namespace cosmos::hil
