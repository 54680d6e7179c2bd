#pragma once
// The web view's HTTP server (cpp-httplib, Debian's libcpp-httplib-dev) on threads of its
// own: the page's files (web_assets.hpp), /api/status and /api/poses as JSON, and /events, a
// server-sent event stream that pushes every status period and every part as it comes:
//   event: summary  data: WebSnapshotStore::status_document()'s JSON
//   event: part     data: {"pose": pose_json, "tile": belt tile or null}
// A new stream first gets the summary and every part the store still keeps. Each stream holds
// one of the server's threads (kStreamThreads of them, at a lowered priority:
// background_thread_pool.hpp) and reads the store through wait_for_update, so a stalled
// browser stalls only its own stream.
#include <atomic>
#include <memory>
#include <string>
#include <thread>

#include "realtime/config/web_view_settings.hpp"
#include "realtime/web/web_snapshot_store.hpp"

namespace httplib {
class Server;
}

namespace cosmos {

class WebServer {
 public:
  static constexpr int kStreamThreads = 6;

  explicit WebServer(WebSnapshotStore& store);
  ~WebServer();  // stops
  WebServer(const WebServer&) = delete;
  WebServer& operator=(const WebServer&) = delete;

  // Binds and starts serving; throws InputError "<what>: cannot listen on HOST:PORT: reason".
  // Port 0 takes a free port (port() tells which).
  void start(const HttpAddress& address, const std::string& what);
  int port() const { return port_; }
  // Closes every stream and joins the server's threads.
  void stop();

 private:
  void add_routes();

  WebSnapshotStore& store_;
  std::unique_ptr<httplib::Server> server_;
  std::thread thread_;
  std::atomic<bool> listening_done_{false};
  int port_ = 0;
};

}  // namespace cosmos
