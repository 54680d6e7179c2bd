// The web view's server on a free loopback port: the page and its files, /api/status and
// /api/poses as JSON, a 404 naming a missing page, and /events streaming the summary and
// the kept parts to a new reader, then a part handed in later; an address in use is refused
// in one line naming it.
#include "realtime/web/web_server.hpp"

#include <gtest/gtest.h>
#include <httplib.h>

#include <string>

#include "core/input_error.hpp"

namespace cosmos {
namespace {

PartRecognition recognized(std::int64_t seq, const std::string& name) {
  PartRecognition part;
  part.pose.part_seq = seq;
  part.pose.part_name = name;
  part.pose.status = PoseStatus::kOk;
  part.first_profile = 10 * seq;
  part.last_profile = 10 * seq + 5;
  return part;
}

class WebServerTest : public ::testing::Test {
 protected:
  WebServerTest() : store_(WebViewSettings{}), server_(store_) {}
  void SetUp() override {
    server_.start({"127.0.0.1", 0}, "test");
    ASSERT_GT(server_.port(), 0);
  }

  httplib::Client client() const { return httplib::Client("127.0.0.1", server_.port()); }

  WebSnapshotStore store_;
  WebServer server_;
};

TEST_F(WebServerTest, ServesThePageAndItsFiles) {
  httplib::Client http = client();
  const auto index = http.Get("/");
  ASSERT_TRUE(index);
  EXPECT_EQ(index->status, 200);
  EXPECT_EQ(index->get_header_value("Content-Type"), "text/html; charset=utf-8");
  EXPECT_NE(index->body.find("<title>COSMOS-Cell live view</title>"), std::string::npos);
  const auto script = http.Get("/app.js");
  ASSERT_TRUE(script);
  EXPECT_EQ(script->status, 200);
  EXPECT_NE(script->body.find("EventSource('/events')"), std::string::npos);
  const auto missing = http.Get("/nothing.html");
  ASSERT_TRUE(missing);
  EXPECT_EQ(missing->status, 404);
  EXPECT_EQ(missing->body, "no such page: /nothing.html\n");
}

TEST_F(WebServerTest, AnswersTheJsonApi) {
  CellStatus status;
  status.state = CellState::kScanning;
  status.parts_seen = 4;
  store_.update_status(status);
  store_.add_part(recognized(0, "cow"));
  store_.add_part(recognized(1, "elephant"));
  httplib::Client http = client();
  const auto status_reply = http.Get("/api/status");
  ASSERT_TRUE(status_reply);
  EXPECT_EQ(status_reply->get_header_value("Content-Type"), "application/json");
  const auto status_json = nlohmann::json::parse(status_reply->body);
  EXPECT_EQ(status_json.at("status").at("parts_seen"), 4);
  EXPECT_EQ(status_json.at("pose_latency_ms").at("count"), 2);
  const auto poses_reply = http.Get("/api/poses");
  ASSERT_TRUE(poses_reply);
  const auto poses = nlohmann::json::parse(poses_reply->body).at("poses");
  ASSERT_EQ(poses.size(), 2u);
  EXPECT_EQ(poses[0].at("part_name"), "elephant");
}

TEST_F(WebServerTest, StreamsTheSummaryAndThePartsAsServerSentEvents) {
  store_.add_part(recognized(0, "cow"));
  std::string stream;
  bool handed_in_later = false;
  httplib::Client http = client();
  http.set_read_timeout(30, 0);
  const auto reply = http.Get("/events", [&](const char* data, std::size_t length) {
    stream.append(data, length);
    if (!handed_in_later && stream.find("\"cow\"") != std::string::npos) {
      store_.add_part(recognized(1, "fandisk"));
      handed_in_later = true;
    }
    return stream.find("\"fandisk\"") == std::string::npos;  // stop once the new part came
  });
  EXPECT_EQ(reply.error(), httplib::Error::Canceled);
  const std::size_t summary = stream.find("event: summary\ndata: {\"status\"");
  const std::size_t cow = stream.find("event: part\ndata: {\"pose\":{\"part_seq\":0");
  const std::size_t fandisk = stream.find("event: part\ndata: {\"pose\":{\"part_seq\":1");
  ASSERT_NE(summary, std::string::npos) << stream;
  ASSERT_NE(cow, std::string::npos) << stream;
  ASSERT_NE(fandisk, std::string::npos) << stream;
  EXPECT_LT(summary, cow);
  EXPECT_LT(cow, fandisk);
}

TEST_F(WebServerTest, RefusesAnAddressInUseNamingIt) {
  WebSnapshotStore other_store{WebViewSettings{}};
  WebServer other(other_store);
  try {
    other.start({"127.0.0.1", server_.port()}, "web.http_address");
    FAIL() << "a second server listened on the same port";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what())
                  .rfind("web.http_address: cannot listen on 127.0.0.1:" +
                             std::to_string(server_.port()) + ": ",
                         0),
              0u)
        << error.what();
  }
}

}  // namespace
}  // namespace cosmos
