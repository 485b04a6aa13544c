#pragma once
// The transport's stream (private to the transport, like transport_refusals.h: no other file includes
// it): the httplib::Stream a worker hands to the library for one connection. It starts with the
// bytes the ConnectionGate already read, gives every read of one request a single deadline, counts the
// head's bytes against limits::kMaxHeaderBytes, and collects a response's pieces into one send.
//
// cpp-httplib 0.11.4 used here (the version server/CMakeLists.txt pins):
//  - httplib::Stream, the abstract stream that Server::process_request reads a request from and writes
//    its response to: is_readable, is_writable, read, write, get_remote_ip_and_port,
//    get_local_ip_and_port and socket are its whole interface, each overridden below.
//  - That the library reads the head through read() before it runs the pre-routing hook, which sets
//    ConnectionState::head_done, so bytes read before that hook are the head's.
//  - That it calls both get_*_ip_and_port on every request (cached here) and that is_readable() is const
//    (so the pending output it may flush is mutable).

#include <httplib.h>

#include <chrono>
#include <cstddef>
#include <string>
#include <string_view>

#include "http/http_transport.h"

namespace softtune::http {

using TransportClock = std::chrono::steady_clock;

/// What the library's callbacks of one connection share while a worker serves it (reached through a
/// thread-local pointer in http_transport.cpp). start_request() resets it for each request.
struct ConnectionState {
  TransportClock::time_point request_start;
  std::size_t head_bytes = 0;  ///< request line and header bytes consumed so far
  bool head_done = false;      ///< the pre-routing hook ran: what follows is body
  bool head_overflow = false;  ///< the head outgrew limits::kMaxHeaderBytes
  bool close_after = false;    ///< answer, then close (the body was left unread)
  std::string_view route;      ///< the route pattern that answered (metrics label), empty if none ran
  /// The body's deadline, set from its Content-Length once the head is read (body_deadline()); a read
  /// that waits past it fails and sets body_timed_out (the answer is 408).
  TransportClock::time_point body_deadline = TransportClock::time_point::max();
  bool body_timed_out = false;
  /// The head's bytes as read (at most limits::kMaxHeaderBytes): an answer the library writes before it
  /// parsed the headers (414) still finds the request's Origin here.
  std::string head_seen;
};

/// When a body of `content_length` bytes, whose head was read at `head_read`, must have arrived: the
/// ConnectionGate's rule (limits::kBodyGrace + length / limits::kMinBodyBytesPerSecond) for the bodies a
/// worker reads itself (after "Expect: 100-continue", or the next request on a busy keep-alive connection).
TransportClock::time_point body_deadline(TransportClock::time_point head_read, std::size_t content_length);

class LimitedStream final : public httplib::Stream {
 public:
  LimitedStream(int sock, ConnectionState& state, const TransportOptions& options, std::string received)
      : sock_(sock), state_(state), options_(options), buffer_(std::move(received)) {}

  /// A new request on this connection, whose first byte arrived at `first_byte`: resets the state and
  /// starts the request's read deadline.
  void start_request(TransportClock::time_point first_byte);
  bool has_buffered() const { return begin_ < buffer_.size(); }
  /// True when the unread bytes hold a whole request (head and its Content-Length body, request_framing.h).
  bool request_buffered() const;
  /// The unread bytes, handed back to the gate with the connection.
  std::string take_buffered();
  /// Appends what has arrived, waiting up to `wait` for something; false when the client closed or the
  /// socket failed.
  bool read_for(std::chrono::microseconds wait);

  bool is_readable() const override;
  bool is_writable() const override;
  ssize_t read(char* ptr, size_t size) override;
  ssize_t write(const char* ptr, size_t size) override;
  /// Sends the collected response bytes; false when not all of them went out.
  bool flush() const;
  void get_remote_ip_and_port(std::string& ip, int& port) const override;
  void get_local_ip_and_port(std::string& ip, int& port) const override;
  socket_t socket() const override { return sock_; }

 private:
  ssize_t receive();
  /// The request's deadline, or the body's when it comes first.
  TransportClock::time_point read_deadline() const;
  /// Waits for bytes until read_deadline(); false when none came (a body's wait then sets body_timed_out).
  bool wait_readable() const;

  int sock_;
  ConnectionState& state_;
  const TransportOptions& options_;
  TransportClock::time_point deadline_ = TransportClock::now();
  std::string buffer_;
  std::size_t begin_ = 0;
  mutable std::string out_;  ///< response bytes not sent yet (mutable: the library's is_readable() is const)
  mutable std::string remote_ip_, local_ip_;
  mutable int remote_port_ = -1, local_port_ = -1;
};

}  // namespace softtune::http
