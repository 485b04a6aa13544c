// One client address cannot hold more than TransportOptions::max_client_connections connections: the next
// one from that address gets a 503 problem at once and is closed, while other addresses are served. The
// clients are real sockets bound to distinct loopback addresses (127.0.0.0/8 is all this machine).
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "test_server.h"

using softtune::http::testing::quick_options;
using softtune::http::testing::RawConnection;
using softtune::http::testing::status_of;
using softtune::http::testing::TestServer;

namespace {

constexpr const char* kClientLimitHealth = "GET /api/v1/health HTTP/1.1\r\nHost: t\r\n\r\n";
constexpr const char* kClientLimitHealthClose = "GET /api/v1/health HTTP/1.1\r\nHost: t\r\nConnection: close\r\n\r\n";

TestServer client_limit_server(std::size_t per_client) {
  auto options = quick_options();
  options.max_client_connections = per_client;
  return TestServer(options);
}

// `count` connections from `source`, each with half a request head sent (held in the gate, no worker).
std::vector<std::unique_ptr<RawConnection>> client_limit_open_slow(int port, const char* source, int count) {
  std::vector<std::unique_ptr<RawConnection>> out;
  for (int i = 0; i < count; ++i) {
    out.push_back(std::make_unique<RawConnection>(port, source));
    EXPECT_TRUE(out.back()->connected());
    out.back()->send("GET /api/v1/health HTTP/1.1\r\n");
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(100));  // admitted by the accept thread
  return out;
}

}  // namespace

TEST(ClientConnectionLimit, TheNextConnectionFromTheSameAddressIsRefusedWith503) {
  TestServer s = client_limit_server(3);
  auto held = client_limit_open_slow(s.port(), "127.0.0.2", 3);

  RawConnection over(s.port(), "127.0.0.2");
  ASSERT_TRUE(over.connected());
  over.send(kClientLimitHealth);
  const std::string answer = over.receive(std::chrono::milliseconds(2000));
  EXPECT_EQ(status_of(answer), 503) << answer;
  EXPECT_NE(answer.find("Retry-After: 1\r\n"), std::string::npos) << answer;
  EXPECT_NE(answer.find("Content-Type: application/problem+json"), std::string::npos) << answer;
  EXPECT_NE(answer.find("too many connections from your address: at most 3"), std::string::npos) << answer;
  EXPECT_TRUE(over.closed());

  // Another address is served, and so are the held connections from the first one.
  RawConnection other(s.port(), "127.0.0.3");
  other.send(kClientLimitHealthClose);
  EXPECT_EQ(status_of(other.receive()), 200);
  held[0]->send("Host: t\r\nConnection: close\r\n\r\n");
  EXPECT_EQ(status_of(held[0]->receive()), 200);
}

TEST(ClientConnectionLimit, AClosedConnectionGivesItsPlaceBack) {
  TestServer s = client_limit_server(2);
  auto held = client_limit_open_slow(s.port(), "127.0.0.4", 2);
  held[1].reset();  // the client closes it: the gate sees the end of the stream and forgets it
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  RawConnection again(s.port(), "127.0.0.4");
  again.send(kClientLimitHealthClose);
  EXPECT_EQ(status_of(again.receive()), 200);
}

// Idle keep-alive connections count too (a connection counts from accept to close, wherever it is): two
// clients that were served and keep their connections open leave no place for a third from that address.
TEST(ClientConnectionLimit, IdleKeepAliveConnectionsCount) {
  TestServer s = client_limit_server(2);
  std::vector<std::unique_ptr<RawConnection>> kept;
  for (int i = 0; i < 2; ++i) {
    kept.push_back(std::make_unique<RawConnection>(s.port(), "127.0.0.5"));
    kept.back()->send(kClientLimitHealth);
    EXPECT_EQ(status_of(kept.back()->receive_some()), 200);
  }
  RawConnection over(s.port(), "127.0.0.5");
  over.send(kClientLimitHealth);
  EXPECT_EQ(status_of(over.receive(std::chrono::milliseconds(2000))), 503);
  // The kept connections still serve their next requests.
  kept[0]->send(kClientLimitHealthClose);
  EXPECT_EQ(status_of(kept[0]->receive()), 200);
}
