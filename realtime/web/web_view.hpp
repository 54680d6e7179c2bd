#pragma once
// The cell's live web view (`cosmos cell --http HOST:PORT`, or the config's web.http_address):
// a snapshot store fed from the publisher thread and the HTTP server that shows it
// (web_server.hpp). The cell wires it in at two points the publisher thread already passes:
//   publisher(next)  a Publisher in front of the cell's own that also keeps each CellStatus;
//   observe(part)    called from the cell's PoseObserver after each pose went out, with the
//                    part's view image (PartRecognitionContext::keep_part_image) for the belt.
// The acquisition thread never reaches either.
#include <memory>
#include <string>

#include "realtime/cell/part_recognition.hpp"
#include "realtime/config/web_view_settings.hpp"
#include "realtime/lcm/pose_publisher.hpp"
#include "realtime/web/belt_tile.hpp"
#include "realtime/web/status_tee_publisher.hpp"
#include "realtime/web/web_server.hpp"
#include "realtime/web/web_snapshot_store.hpp"

namespace cosmos {

class WebView {
 public:
  // Starts serving at once (the page shows the cell starting up); throws InputError
  // "<what>: cannot listen on HOST:PORT: reason" when the address cannot be listened on
  // (`what` names where the address came from: the config key or the option).
  WebView(const WebViewSettings& settings, const HttpAddress& address,
          const std::string& what = "web.http_address");

  // "http://HOST:PORT/" with the port actually bound.
  std::string url() const;
  int port() const { return server_.port(); }
  // The loop's row geometry, for the belt strip: before the run.
  void set_belt(double grid_mm, int belt_columns, double x0_loop_mm);
  // Before the run: what the cell does meanwhile (e.g. loading the model base).
  void show_state(const std::string& state_text);

  Publisher& publisher(Publisher& next);
  void observe(const PartRecognition& part) { store_.add_part(part); }
  // Closes the page's streams and stops the server.
  void stop() { server_.stop(); }

  const WebSnapshotStore& store() const { return store_; }

 private:
  WebViewSettings settings_;
  HttpAddress address_;
  WebSnapshotStore store_;
  WebServer server_;
  std::unique_ptr<StatusTeePublisher> tee_;
};

}  // namespace cosmos
