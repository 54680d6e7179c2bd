#pragma once
// The web server's worker threads (an httplib::TaskQueue), each lowered to a nice value once
// started: on a machine without SCHED_FIFO (realtime.sched_fifo_priority 0, or no
// permission) the acquisition and recognizer threads then win the CPU from a browser's
// requests and streams under the normal scheduler, as the page can wait and the belt cannot.
// A stream holds its thread while it lasts: `threads` bounds the browsers served at once,
// more are queued. Include this after any Eigen header: httplib's <resolv.h> defines `_res`,
// which breaks Eigen's headers that come after it.
#include <httplib.h>

#include <condition_variable>
#include <deque>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace cosmos {

// Lowers the calling thread's priority to `nice` (0..19), never raises it; false when the
// system refused.
bool lower_this_thread_priority(int nice);

class BackgroundThreadPool final : public httplib::TaskQueue {
 public:
  static constexpr int kNice = 10;

  explicit BackgroundThreadPool(int threads);
  ~BackgroundThreadPool() override;

  void enqueue(std::function<void()> task) override;
  // Runs the queued tasks to their end, then joins the threads.
  void shutdown() override;

 private:
  void work();

  std::mutex mutex_;
  std::condition_variable ready_;
  std::deque<std::function<void()>> tasks_;
  bool shutting_down_ = false;
  std::vector<std::thread> threads_;
};

}  // namespace cosmos
