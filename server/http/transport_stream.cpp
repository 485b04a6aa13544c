#include "http/transport_stream.h"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>

#include <algorithm>
#include <array>
#include <cerrno>

#include "http/connection_gate.h"
#include "http/limits.h"
#include "http/request_framing.h"

namespace softtune::http {
namespace {

// Response bytes collected before a send (see LimitedStream::write).
constexpr std::size_t kWriteBufferBytes = 64 * 1024;

// >0 ready, 0 timed out, <0 error.
int wait_for(int sock, short events, int timeout_ms) {
  pollfd p{sock, events, 0};
  for (;;) {
    const int n = ::poll(&p, 1, timeout_ms);
    if (n < 0 && errno == EINTR) continue;
    return n;
  }
}

int remaining_ms(TransportClock::time_point deadline) {
  const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - TransportClock::now()).count();
  return left <= 0 ? 0 : static_cast<int>(left);
}

void peer_address(int sock, bool local, std::string& ip, int& port) {
  sockaddr_storage addr{};
  socklen_t len = sizeof addr;
  const int rc = local ? ::getsockname(sock, reinterpret_cast<sockaddr*>(&addr), &len)
                       : ::getpeername(sock, reinterpret_cast<sockaddr*>(&addr), &len);
  if (rc != 0) return;
  char buf[INET6_ADDRSTRLEN] = {};
  if (addr.ss_family == AF_INET) {
    const auto* a = reinterpret_cast<const sockaddr_in*>(&addr);
    ::inet_ntop(AF_INET, &a->sin_addr, buf, sizeof buf);
    port = ntohs(a->sin_port);
  } else if (addr.ss_family == AF_INET6) {
    const auto* a = reinterpret_cast<const sockaddr_in6*>(&addr);
    ::inet_ntop(AF_INET6, &a->sin6_addr, buf, sizeof buf);
    port = ntohs(a->sin6_port);
  }
  ip = buf;
}

}  // namespace

void LimitedStream::start_request(TransportClock::time_point first_byte) {
  state_ = ConnectionState{};
  state_.request_start = first_byte;
  deadline_ = first_byte + options_.request_read_timeout;
}

TransportClock::time_point body_deadline(TransportClock::time_point head_read, std::size_t content_length) {
  return head_read + limits::kBodyGrace +
         std::chrono::milliseconds(content_length * 1000 / limits::kMinBodyBytesPerSecond);
}

bool LimitedStream::request_buffered() const {
  const std::string_view rest = std::string_view(buffer_).substr(begin_);
  const std::optional<std::size_t> size = request_size(rest, limits::kMaxBodyBytes);
  return size && rest.size() >= *size;
}

std::string LimitedStream::take_buffered() {
  std::string rest = buffer_.substr(begin_);
  buffer_.clear();
  begin_ = 0;
  return rest;
}

bool LimitedStream::read_for(std::chrono::microseconds wait) {
  pollfd p{sock_, POLLIN, 0};
  const timespec t{0, static_cast<long>(std::chrono::nanoseconds(wait).count())};
  const int ready = ::ppoll(&p, 1, &t, nullptr);
  if (ready < 0) return errno == EINTR;
  if (ready == 0) return true;
  return receive() > 0;
}

TransportClock::time_point LimitedStream::read_deadline() const {
  return state_.head_done ? std::min(deadline_, state_.body_deadline) : deadline_;
}

bool LimitedStream::wait_readable() const {
  if (wait_for(sock_, POLLIN, remaining_ms(read_deadline())) > 0) return true;
  if (state_.head_done) state_.body_timed_out = true;
  return false;
}

bool LimitedStream::is_readable() const {
  if (has_buffered()) return true;
  if (!out_.empty() && !flush()) return false;
  return wait_readable();
}

bool LimitedStream::is_writable() const {
  return wait_for(sock_, POLLOUT, static_cast<int>(options_.write_timeout.count())) > 0;
}

// Reads try the socket first and wait only when it has nothing: one system call per read, not two.
ssize_t LimitedStream::read(char* ptr, size_t size) {
  if (!has_buffered()) {
    if (!out_.empty() && !flush()) return -1;
    ssize_t n = receive();
    if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) {
      if (!wait_readable()) return -1;
      n = receive();
    }
    if (n <= 0) return n;
  }
  std::size_t n = std::min(size, buffer_.size() - begin_);
  if (!state_.head_done) {
    if (state_.head_bytes + n > limits::kMaxHeaderBytes) {
      state_.head_overflow = true;
      return -1;
    }
    state_.head_bytes += n;
    state_.head_seen.append(buffer_.data() + begin_, n);
  }
  std::copy_n(buffer_.data() + begin_, n, ptr);
  begin_ += n;
  return static_cast<ssize_t>(n);
}

// The library writes a response's head and body separately; collecting them and sending once after
// the request (flush()) saves a system call and a TCP segment per response. Large bodies go out as
// the buffer fills, and anything pending goes out before the stream waits to read (100-continue).
ssize_t LimitedStream::write(const char* ptr, size_t size) {
  out_.append(ptr, size);
  if (out_.size() >= kWriteBufferBytes && !flush()) return -1;
  return static_cast<ssize_t>(size);
}

bool LimitedStream::flush() const {
  std::size_t sent = 0;
  while (sent < out_.size()) {
    ssize_t n = ::send(sock_, out_.data() + sent, out_.size() - sent, MSG_NOSIGNAL | MSG_DONTWAIT);
    if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) {
      if (wait_for(sock_, POLLOUT, static_cast<int>(options_.write_timeout.count())) <= 0) break;
      continue;
    }
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    sent += static_cast<std::size_t>(n);
  }
  const bool all = sent == out_.size();
  out_.clear();
  return all;
}

// The library asks for both addresses on every request; they do not change, so ask the kernel once.
void LimitedStream::get_remote_ip_and_port(std::string& ip, int& port) const {
  if (remote_port_ < 0) peer_address(sock_, false, remote_ip_, remote_port_);
  ip = remote_ip_;
  port = remote_port_;
}

void LimitedStream::get_local_ip_and_port(std::string& ip, int& port) const {
  if (local_port_ < 0) peer_address(sock_, true, local_ip_, local_port_);
  ip = local_ip_;
  port = local_port_;
}

// One non-blocking recv appended to the buffer (consumed bytes are dropped first).
ssize_t LimitedStream::receive() {
  if (begin_ == buffer_.size()) {
    buffer_.clear();
    begin_ = 0;
  }
  std::array<char, 4096> chunk;
  const ssize_t n = ::recv(sock_, chunk.data(), chunk.size(), MSG_DONTWAIT);
  if (n > 0) buffer_.append(chunk.data(), static_cast<std::size_t>(n));
  return n;
}

}  // namespace softtune::http
