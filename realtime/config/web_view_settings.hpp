#pragma once
// The cell's live web view (realtime/web/): where it listens and how much of the belt it keeps
// (keys of the cell's `web:`). Off unless an address is given, here or by `cosmos cell --http`.
#include <optional>
#include <string>
#include <string_view>

#include "core/parameter_visitor.hpp"

namespace cosmos {

struct WebViewSettings {
  // "HOST:PORT" (e.g. 127.0.0.1:8080); empty: no web view. Port 0 takes any free port.
  std::string http_address;
  double belt_strip_m = 2.0;        // belt shown behind the laser sheet
  double strip_mm_per_pixel = 1.6;  // the strip's pixel, along and across the belt
  int recent_poses = 20;            // rows of the pose table
  double linger_s = 0.0;            // the page stays served this long after the source ends

  template <class Visitor>
  void visit(Visitor& v) {
    v("http_address", http_address, "HOST:PORT of the live view; empty: off; port 0: any free");
    v("belt_strip_m", belt_strip_m, "belt shown behind the laser sheet, m", Range::above(0, 100));
    v("strip_mm_per_pixel", strip_mm_per_pixel, "the strip's pixel along and across the belt, mm",
      Range::above(0, 100));
    v("recent_poses", recent_poses, "rows of the pose table", Range{1, 1000});
    v("linger_s", linger_s, "the page stays served this long after the source ends, s",
      Range{0, 86400});
  }
};

struct HttpAddress {
  std::string host;
  int port = 0;
};

// "HOST:PORT" with a port in [0, 65535]; nullopt with `reason` set otherwise.
std::optional<HttpAddress> parse_http_address(std::string_view text, std::string& reason);

}  // namespace cosmos
