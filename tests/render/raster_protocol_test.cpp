// The raster socket's reads and writes (raster_protocol.cpp) over a real socket pair: every byte arrives in
// order however the kernel splits it, a silent peer is a timeout, a closed one is eof (before or in the middle
// of a message, and on send without SIGPIPE).
#include "raster_protocol.h"

#include <gtest/gtest.h>

#include <sys/socket.h>
#include <unistd.h>

#include <numeric>
#include <thread>
#include <vector>

namespace softtune::render::raster {
namespace {

struct SocketPair {
  int fd[2] = {-1, -1};
  SocketPair() { EXPECT_EQ(socketpair(AF_UNIX, SOCK_STREAM, 0, fd), 0); }
  ~SocketPair() {
    for (int f : fd) {
      if (f >= 0) close(f);
    }
  }
  void close_end(int i) {
    close(fd[i]);
    fd[i] = -1;
  }
};

TEST(RasterProtocol, EveryByteArrivesInOrder) {
  SocketPair s;
  std::vector<std::uint8_t> sent(4 << 20);  // far more than a socket buffer: many partial sends and reads
  std::iota(sent.begin(), sent.end(), std::uint8_t{7});
  Io send_result = Io::error;
  std::thread writer([&] { send_result = send_all(s.fd[0], sent.data(), sent.size()); });
  std::vector<std::uint8_t> got(sent.size());
  EXPECT_EQ(receive_exact(s.fd[1], got.data(), got.size(), 5000), Io::ok);
  writer.join();
  EXPECT_EQ(send_result, Io::ok);
  EXPECT_EQ(got, sent);
}

TEST(RasterProtocol, ASilentPeerIsATimeout) {
  SocketPair s;
  RasterReply reply;
  EXPECT_EQ(receive_exact(s.fd[1], &reply, sizeof reply, 20), Io::timeout);
}

TEST(RasterProtocol, AClosedPeerIsEofBeforeOrInTheMiddle) {
  SocketPair s;
  const RasterRequest request{kRequestMagic, 64, 36, 0, 3};
  ASSERT_EQ(send_all(s.fd[0], &request, sizeof request / 2), Io::ok);  // half a header, then gone
  s.close_end(0);
  RasterRequest got;
  EXPECT_EQ(receive_exact(s.fd[1], &got, sizeof got, 1000), Io::eof);
  EXPECT_EQ(receive_exact(s.fd[1], &got, sizeof got, 1000), Io::eof);
}

TEST(RasterProtocol, SendingToAClosedPeerIsEofNotSigpipe) {
  SocketPair s;
  s.close_end(1);
  const std::vector<char> bytes(1 << 16, 'x');
  EXPECT_EQ(send_all(s.fd[0], bytes.data(), bytes.size()), Io::eof);  // the test process is still alive
}

}  // namespace
}  // namespace softtune::render::raster
