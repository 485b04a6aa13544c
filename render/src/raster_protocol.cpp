#include "raster_protocol.h"

#include <poll.h>
#include <sys/socket.h>

#include <cerrno>

namespace softtune::render::raster {

Io send_all(int fd, const void* data, std::size_t bytes) {
  const auto* p = static_cast<const char*>(data);
  while (bytes > 0) {
    const ssize_t n = send(fd, p, bytes, MSG_NOSIGNAL);
    if (n < 0) {
      if (errno == EINTR) continue;
      return errno == EPIPE || errno == ECONNRESET ? Io::eof : Io::error;
    }
    p += n;
    bytes -= static_cast<std::size_t>(n);
  }
  return Io::ok;
}

Io receive_exact(int fd, void* data, std::size_t bytes, int timeout_ms) {
  auto* p = static_cast<char*>(data);
  while (bytes > 0) {
    pollfd pfd{fd, POLLIN, 0};
    const int ready = poll(&pfd, 1, timeout_ms);
    if (ready < 0) {
      if (errno == EINTR) continue;
      return Io::error;
    }
    if (ready == 0) return Io::timeout;
    const ssize_t n = recv(fd, p, bytes, 0);
    if (n < 0) {
      if (errno == EINTR || errno == EAGAIN) continue;
      return errno == ECONNRESET ? Io::eof : Io::error;
    }
    if (n == 0) return Io::eof;
    p += n;
    bytes -= static_cast<std::size_t>(n);
  }
  return Io::ok;
}

}  // namespace softtune::render::raster
