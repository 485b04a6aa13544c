// The transport's stream (transport_stream.cpp) over a socket pair: the bytes the gate already read come
// first, a request's head is counted against limits::kMaxHeaderBytes (its body is not), every read of one
// request shares one deadline, and a response's pieces leave in one send at flush().
#include "http/transport_stream.h"

#include <gtest/gtest.h>

#include <sys/socket.h>
#include <unistd.h>

#include <string>

#include "http/limits.h"

namespace softtune::http {
namespace {

using namespace std::chrono_literals;

struct Pair {
  int fd[2] = {-1, -1};
  Pair() { EXPECT_EQ(::socketpair(AF_UNIX, SOCK_STREAM, 0, fd), 0); }
  ~Pair() {
    ::close(fd[0]);
    ::close(fd[1]);
  }
  void peer_sends(const std::string& s) const { ASSERT_EQ(::send(fd[1], s.data(), s.size(), 0), static_cast<ssize_t>(s.size())); }
  // What the peer has received so far (non-blocking).
  std::string peer_received() const {
    char buf[4096];
    const ssize_t n = ::recv(fd[1], buf, sizeof buf, MSG_DONTWAIT);
    return n > 0 ? std::string(buf, static_cast<std::size_t>(n)) : std::string();
  }
};

std::string read_all_buffered(LimitedStream& s) {
  std::string out;
  char buf[64];
  while (s.has_buffered()) {
    const ssize_t n = s.read(buf, sizeof buf);
    if (n <= 0) break;
    out.append(buf, static_cast<std::size_t>(n));
  }
  return out;
}

TEST(TransportStream, GateBytesComeFirstThenTheSocket) {
  Pair p;
  ConnectionState state;
  TransportOptions options;
  LimitedStream s(p.fd[0], state, options, "GET / HTTP/1.1\r\n");
  s.start_request(TransportClock::now());
  EXPECT_FALSE(s.request_buffered());
  p.peer_sends("Host: x\r\n\r\n");
  ASSERT_TRUE(s.read_for(200ms));
  EXPECT_TRUE(s.request_buffered());
  EXPECT_EQ(read_all_buffered(s), "GET / HTTP/1.1\r\nHost: x\r\n\r\n");
  EXPECT_EQ(state.head_bytes, 27u);
  p.peer_sends("next");
  ASSERT_TRUE(s.read_for(200ms));
  EXPECT_EQ(s.take_buffered(), "next");  // handed back to the gate
  EXPECT_FALSE(s.has_buffered());
}

TEST(TransportStream, TheHeadIsCountedAndTheBodyIsNot) {
  Pair p;
  ConnectionState state;
  TransportOptions options;
  const std::string head(limits::kMaxHeaderBytes + 10, 'h');
  LimitedStream s(p.fd[0], state, options, head);
  s.start_request(TransportClock::now());
  std::string buf(limits::kMaxHeaderBytes, '\0');
  EXPECT_EQ(s.read(buf.data(), buf.size()), static_cast<ssize_t>(limits::kMaxHeaderBytes));  // exactly the cap
  EXPECT_EQ(s.read(buf.data(), 1), -1);  // one byte more
  EXPECT_TRUE(state.head_overflow);
  state.head_done = true;  // the pre-routing hook ran: what follows is body
  EXPECT_EQ(s.read(buf.data(), buf.size()), 10);
}

TEST(TransportStream, ReadsOfOneRequestShareOneDeadline) {
  Pair p;
  ConnectionState state;
  TransportOptions options;
  options.request_read_timeout = 60ms;
  LimitedStream s(p.fd[0], state, options, "");
  const auto start = TransportClock::now();
  s.start_request(start);
  char c;
  EXPECT_EQ(s.read(&c, 1), -1);  // the peer says nothing: the read ends at the deadline
  const auto waited = TransportClock::now() - start;
  EXPECT_GE(waited, 50ms);
  EXPECT_LT(waited, 2s);
  EXPECT_FALSE(s.is_readable());  // the deadline is spent: no further wait
  EXPECT_LT(TransportClock::now() - start, 2s);
}

TEST(TransportStream, AResponseLeavesInOneSendAtFlush) {
  Pair p;
  ConnectionState state;
  TransportOptions options;
  LimitedStream s(p.fd[0], state, options, "");
  EXPECT_EQ(s.write("HTTP/1.1 200 OK\r\n", 17), 17);
  EXPECT_EQ(s.write("\r\n", 2), 2);
  EXPECT_EQ(p.peer_received(), "");  // collected, not sent yet
  EXPECT_TRUE(s.flush());
  EXPECT_EQ(p.peer_received(), "HTTP/1.1 200 OK\r\n\r\n");
  EXPECT_TRUE(s.is_writable());
}

}  // namespace
}  // namespace softtune::http
