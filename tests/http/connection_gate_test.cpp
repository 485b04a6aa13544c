// The connection gate on its own: where a request head ends, and how many connections it can hold
// under the process's file-descriptor limit (checked in child processes, which may lower the limit).
#include "http/connection_gate.h"

#include <gtest/gtest.h>
#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cstdlib>
#include <cstring>
#include <string>

using softtune::http::AfterServe;
using softtune::http::ConnectionGate;
using softtune::http::GateOptions;
using softtune::http::head_complete;
using softtune::http::ReadyConnection;
using softtune::http::Refusal;

namespace {

ConnectionGate make_gate(std::size_t max_open) {
  GateOptions o;
  o.threads = 2;
  o.max_open = max_open;
  return ConnectionGate(
      o, [](ReadyConnection&) { return AfterServe::close; }, [](Refusal, std::string_view) { return std::string(); });
}

// Runs in a child: sets the descriptor limits, then exits 0 when the gate's capacity is `expected` and
// the soft limit now leaves the reserve (128 + 2 workers + 64 queued) free beyond it.
void expect_capacity_under_limit(rlim_t soft, rlim_t hard, std::size_t max_open, std::size_t expected) {
  rlimit r{soft, hard};
  if (::setrlimit(RLIMIT_NOFILE, &r) != 0) std::_Exit(2);
  const ConnectionGate gate = make_gate(max_open);
  if (::getrlimit(RLIMIT_NOFILE, &r) != 0) std::_Exit(3);
  std::_Exit(gate.capacity() == expected && r.rlim_cur >= expected + 128 + 2 + 64 ? 0 : 1);
}

}  // namespace

TEST(ConnectionGate, HeadEndsAtTheBlankLine) {
  EXPECT_FALSE(head_complete(""));
  EXPECT_FALSE(head_complete("GET / HTTP/1.1\r\nHost: x\r\n"));
  EXPECT_FALSE(head_complete("GET / HTTP/1.1\nHost: x\n\n"));  // bare LF: the library would not accept it either
  EXPECT_TRUE(head_complete("GET / HTTP/1.1\r\nHost: x\r\n\r\n"));
  EXPECT_TRUE(head_complete("POST / HTTP/1.1\r\nContent-Length: 2\r\n\r\n{}"));
}

TEST(ConnectionGate, HoldsWhatTheDescriptorLimitAllows) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  // Room enough: the asked number.
  EXPECT_EXIT(expect_capacity_under_limit(4096, 4096, 1024, 1024), ::testing::ExitedWithCode(0), "");
  // A low soft limit under a high hard one is raised to fit.
  EXPECT_EXIT(expect_capacity_under_limit(256, 4096, 1024, 1024), ::testing::ExitedWithCode(0), "");
  // A low hard limit: fewer connections, leaving the reserve (128 + 2 workers + the probe lane's worker + 64
  // queued + 64 probes queued) free.
  EXPECT_EXIT(expect_capacity_under_limit(512, 512, 1024, 512 - 128 - 2 - 1 - 64 - 64), ::testing::ExitedWithCode(0), "");
}

namespace {

// An address of either family on `port` (0: any).
sockaddr_storage gate_test_address(const char* ip, in_port_t port, socklen_t& len) {
  sockaddr_storage addr{};
  if (std::string(ip).find(':') == std::string::npos) {
    auto& a = reinterpret_cast<sockaddr_in&>(addr);
    a.sin_family = AF_INET;
    a.sin_port = port;
    ::inet_pton(AF_INET, ip, &a.sin_addr);
    len = sizeof a;
  } else {
    auto& a = reinterpret_cast<sockaddr_in6&>(addr);
    a.sin6_family = AF_INET6;
    a.sin6_port = port;
    ::inet_pton(AF_INET6, ip, &a.sin6_addr);
    len = sizeof a;
  }
  return addr;
}

// Listens on `listen_on`, connects from a socket of `connect_to`'s family, and returns client_key of the
// accepted socket; "unbound" when this machine has no such address (no IPv6).
std::string gate_key_of_client(const char* listen_on, const char* connect_to) {
  socklen_t len = 0;
  sockaddr_storage addr = gate_test_address(listen_on, 0, len);
  const int listener = ::socket(addr.ss_family, SOCK_STREAM, 0);
  if (::bind(listener, reinterpret_cast<sockaddr*>(&addr), len) != 0 || ::listen(listener, 1) != 0 ||
      ::getsockname(listener, reinterpret_cast<sockaddr*>(&addr), &len) != 0) {
    ::close(listener);
    return "unbound";
  }
  // The port sits at the same offset in sockaddr_in and sockaddr_in6.
  const in_port_t port = reinterpret_cast<sockaddr_in&>(addr).sin_port;
  socklen_t to_len = 0;
  sockaddr_storage to = gate_test_address(connect_to, port, to_len);
  const int client = ::socket(to.ss_family, SOCK_STREAM, 0);
  std::string key = "unconnected";
  if (::connect(client, reinterpret_cast<sockaddr*>(&to), to_len) == 0) {
    const int served = ::accept(listener, nullptr, nullptr);
    key = softtune::http::client_key(served);
    ::close(served);
  }
  ::close(client);
  ::close(listener);
  return key;
}

}  // namespace

TEST(ConnectionGate, ClientKeyIsThePeersAddress) {
  EXPECT_EQ(gate_key_of_client("127.0.0.1", "127.0.0.1"), std::string("\x7f\x00\x00\x01", 4));
  const std::string v6 = gate_key_of_client("::1", "::1");
  if (v6 != "unbound") {
    std::string loopback(16, '\0');
    loopback[15] = 1;
    EXPECT_EQ(v6, loopback);
  }
  // An IPv4 client of a dual-stack listener counts as its IPv4 address, not as a second, IPv6, client.
  const std::string mapped = gate_key_of_client("::", "127.0.0.1");
  if (mapped != "unbound") {
    EXPECT_EQ(mapped, std::string("\x7f\x00\x00\x01", 4));
  }
  // A socket without an IP peer has no key (it is never limited).
  int pair[2];
  ASSERT_EQ(::socketpair(AF_UNIX, SOCK_STREAM, 0, pair), 0);
  EXPECT_EQ(softtune::http::client_key(pair[0]), "");
  ::close(pair[0]);
  ::close(pair[1]);
}
