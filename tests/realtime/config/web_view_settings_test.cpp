// The web view's address: HOST:PORT with a port in [0, 65535], anything else refused with the
// reason.
#include "realtime/config/web_view_settings.hpp"

#include <gtest/gtest.h>

namespace cosmos {
namespace {

TEST(HttpAddress, ReadsHostAndPort) {
  std::string reason;
  const auto address = parse_http_address("127.0.0.1:8080", reason);
  ASSERT_TRUE(address) << reason;
  EXPECT_EQ(address->host, "127.0.0.1");
  EXPECT_EQ(address->port, 8080);
  const auto any_port = parse_http_address("localhost:0", reason);
  ASSERT_TRUE(any_port);
  EXPECT_EQ(any_port->port, 0);
  EXPECT_EQ(parse_http_address("0.0.0.0:65535", reason)->port, 65535);
}

TEST(HttpAddress, RefusesWhatIsNotHostColonPort) {
  std::string reason;
  EXPECT_FALSE(parse_http_address("8080", reason));
  EXPECT_EQ(reason, "'8080' is not HOST:PORT (e.g. 127.0.0.1:8080)");
  EXPECT_FALSE(parse_http_address(":8080", reason));
  EXPECT_EQ(reason, "':8080' is not HOST:PORT (e.g. 127.0.0.1:8080)");
  EXPECT_FALSE(parse_http_address("127.0.0.1:http", reason));
  EXPECT_EQ(reason, "'http' is not a port in [0, 65535]");
  EXPECT_FALSE(parse_http_address("127.0.0.1:65536", reason));
  EXPECT_EQ(reason, "'65536' is not a port in [0, 65535]");
  EXPECT_FALSE(parse_http_address("127.0.0.1:", reason));
  EXPECT_EQ(reason, "'' is not a port in [0, 65535]");
}

TEST(WebViewSettings, IsOffByDefault) { EXPECT_TRUE(WebViewSettings{}.http_address.empty()); }

}  // namespace
}  // namespace cosmos
