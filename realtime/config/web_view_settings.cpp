#include "realtime/config/web_view_settings.hpp"

#include <charconv>

namespace cosmos {
namespace {

// Built by appends: GCC 12 warns (-Wrestrict) about some chained string concatenations.
std::string quoted(std::string_view text) {
  std::string out(1, '\'');
  out.append(text);
  out.push_back('\'');
  return out;
}

}  // namespace

std::optional<HttpAddress> parse_http_address(std::string_view text, std::string& reason) {
  const std::size_t colon = text.rfind(':');
  if (colon == std::string_view::npos || colon == 0) {
    reason = quoted(text) + " is not HOST:PORT (e.g. 127.0.0.1:8080)";
    return std::nullopt;
  }
  HttpAddress address;
  address.host = std::string(text.substr(0, colon));
  const std::string_view port = text.substr(colon + 1);
  const char* const end = port.data() + port.size();
  const auto [stop, error] = std::from_chars(port.data(), end, address.port);
  if (port.empty() || error != std::errc{} || stop != end || address.port < 0 ||
      address.port > 65535) {
    reason = quoted(port) + " is not a port in [0, 65535]";
    return std::nullopt;
  }
  return address;
}

}  // namespace cosmos
