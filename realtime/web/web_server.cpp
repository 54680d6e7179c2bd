#include "realtime/web/web_server.hpp"

#include <httplib.h>
#include <sys/socket.h>

#include <cerrno>
#include <chrono>
#include <cstring>

#include "core/input_error.hpp"
#include "realtime/web/background_thread_pool.hpp"
#include "realtime/web/web_assets.hpp"

namespace cosmos {
namespace {

// A stream wakes at least this often, to notice the server stopping.
constexpr auto kStreamPoll = std::chrono::milliseconds(250);
// An idle stream sends a comment this often, so a browser that went away is noticed (the
// write fails) and its thread freed.
constexpr auto kKeepAlive = std::chrono::seconds(10);

bool write_event(httplib::DataSink& sink, const char* name, const std::string& json) {
  std::string text = "event: ";
  text.append(name).append("\ndata: ").append(json).append("\n\n");
  return sink.write(text.data(), text.size());
}

}  // namespace

WebServer::WebServer(WebSnapshotStore& store)
    : store_(store), server_(std::make_unique<httplib::Server>()) {
  server_->new_task_queue = [] { return new BackgroundThreadPool(kStreamThreads); };
  // A finished stream's connection waits this long for another request: short, so that
  // stopping never waits long for the server's threads.
  server_->set_keep_alive_timeout(1);
  // SO_REUSEADDR only: a restarted cell rebinds its port at once, but a second cell on the
  // same port is refused (httplib's default, SO_REUSEPORT, would let both listen and split
  // the browsers between them).
  server_->set_socket_options([](int socket) {
    const int yes = 1;
    ::setsockopt(socket, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
  });
  add_routes();
}

WebServer::~WebServer() { stop(); }

void WebServer::add_routes() {
  server_->Get("/api/status", [this](const httplib::Request&, httplib::Response& res) {
    res.set_content(store_.status_document(), "application/json");
  });
  server_->Get("/api/poses", [this](const httplib::Request&, httplib::Response& res) {
    res.set_content(store_.poses_document(), "application/json");
  });
  server_->Get("/events", [this](const httplib::Request&, httplib::Response& res) {
    res.set_header("Cache-Control", "no-cache");
    auto cursor = std::make_shared<WebCursor>();
    auto last_write =
        std::make_shared<std::chrono::steady_clock::time_point>(std::chrono::steady_clock::now());
    res.set_chunked_content_provider(
        "text/event-stream", [this, cursor, last_write](std::size_t, httplib::DataSink& sink) {
          const WebUpdate update = store_.wait_for_update(*cursor, kStreamPoll);
          if (update.closed) {
            sink.done();
            return true;
          }
          *cursor = update.cursor;
          bool ok = true;
          if (!update.summary_json.empty()) ok = write_event(sink, "summary", update.summary_json);
          for (const auto& part : update.parts)
            if (ok) ok = write_event(sink, "part", part->event_json);
          const auto now = std::chrono::steady_clock::now();
          if (!update.summary_json.empty() || !update.parts.empty()) {
            *last_write = now;
          } else if (now - *last_write >= kKeepAlive) {
            ok = sink.write(": keep-alive\n\n", 14);
            *last_write = now;
          }
          return ok;
        });
  });
  server_->Get(R"(/[A-Za-z0-9_.\-]*)", [](const httplib::Request& req, httplib::Response& res) {
    const WebAsset* asset = find_web_asset(req.path);
    if (asset == nullptr) {
      res.status = 404;
      res.set_content("no such page: " + req.path + "\n", "text/plain");
      return;
    }
    res.set_content(std::string(asset->content), std::string(asset->content_type).c_str());
  });
}

void WebServer::start(const HttpAddress& address, const std::string& what) {
  errno = 0;
  const bool bound = address.port == 0 ? (port_ = server_->bind_to_any_port(address.host)) > 0
                                       : server_->bind_to_port(address.host, address.port);
  if (!bound) {
    const char* reason = errno != 0 ? std::strerror(errno) : "no such local address";
    throw InputError(what + ": cannot listen on " + address.host + ":" +
                     std::to_string(address.port) + ": " + reason);
  }
  if (address.port != 0) port_ = address.port;
  thread_ = std::thread([this] {
    lower_this_thread_priority(BackgroundThreadPool::kNice);
    server_->listen_after_bind();
    listening_done_ = true;
  });
}

void WebServer::stop() {
  store_.close();
  if (!thread_.joinable()) return;
  // httplib's stop() does nothing before its loop runs: repeat until the loop has ended.
  while (!listening_done_) {
    server_->stop();
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  thread_.join();
}

}  // namespace cosmos
