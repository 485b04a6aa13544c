#pragma once
// Holds open connections while their requests arrive, so that a worker thread is taken only by a
// connection with a whole request to serve: its head, and the body its Content-Length declares
// (request_framing.h). Slow clients (slowloris heads, bodies trickling in) and idle keep-alive
// connections then cost a buffer and a file descriptor each, never a worker: they wait in one epoll
// loop until their request is complete, their deadline passes, or newer connections need their place.
// Health and metrics probes go to a reserved lane with its own worker, so they are answered however
// many other requests wait. Plain POSIX sockets and threads; it knows nothing of HTTP beyond where a
// request ends and which requests are probes.

#include <chrono>
#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <string_view>

namespace softtune::http {

/// True once `received` holds a whole request head (request line and headers up to the blank line).
bool head_complete(std::string_view received);

struct GateOptions {
  int threads = 8;                ///< workers serving connections whose head is complete
  /// Connections held at once (waiting for a head, idle or draining). The gate raises the process's
  /// soft descriptor limit to fit them if it can, and holds fewer if it cannot (capacity()).
  std::size_t max_open = 1024;
  std::size_t max_ready = 64;     ///< complete heads waiting for a free worker; more get 503
  std::size_t max_head_bytes = 16 * 1024;  ///< a head still incomplete at this size goes to a worker (which answers 431)
  /// From a request's first byte until the whole request (head and body) has arrived.
  std::chrono::milliseconds request_read_timeout{10'000};
  /// Largest body the gate waits for (a larger Content-Length goes to a worker with its head, to be refused).
  std::size_t max_body_bytes = 1 << 20;
  /// Once the head is complete, its body must arrive within body_grace + Content-Length / min_body_rate
  /// (bytes per second), and within request_read_timeout in any case; else 408.
  std::size_t min_body_rate = 128 * 1024;
  std::chrono::milliseconds body_grace{1'000};
  /// Bytes the gate buffers in all (heads and bodies arriving); past it the connection that has waited
  /// longest is closed, so slow bodies count against a total as connections do against max_open.
  std::size_t max_buffered_bytes = 64u << 20;
  /// Connections one client address (IPv4, or IPv6 in full; an IPv4-mapped IPv6 address counts as its
  /// IPv4 one) may have open at once: held, queued or being served. The next one from that address is
  /// answered 503 (Refusal::client_limit) at once and closed, without taking a place of anyone else's.
  /// 0: no limit.
  std::size_t max_per_client = 0;
  /// Probes (is_lane_request) waiting for the reserved lane's worker; more get 503.
  std::size_t max_lane = 64;
  /// A connection without any byte of a (next) request is closed after this time.
  std::chrono::milliseconds keep_alive_timeout{5'000};
};

/// A connection handed to a worker: its socket, the bytes read so far (a whole head, possibly more),
/// when the request's first byte arrived, and how many requests it has already served.
struct ReadyConnection {
  int sock = -1;
  std::string received;
  std::chrono::steady_clock::time_point request_start;
  std::size_t served = 0;
  bool lane = false;  ///< a probe on the reserved lane: serve this one request, then hand the connection back
};

/// What a worker says about the connection it served.
enum class AfterServe {
  keep_alive,       ///< wait for the next request (ReadyConnection::received holds its bytes so far, maybe a whole head)
  close,            ///< close now
  drain_and_close,  ///< answered while the client may still be sending: half-close, discard briefly, close
};

/// Why the gate answers a request itself.
enum class Refusal {
  busy,     ///< max_ready complete heads are already waiting for a worker: 503
  timeout,  ///< the request (head and body) did not arrive in time: 408
  client_limit,  ///< the client's address already has max_per_client connections open: 503, nothing read
};

/// The key a connection's peer address is counted under for GateOptions::max_per_client: the address's
/// bytes (4 for IPv4 and IPv4-mapped IPv6, 16 for IPv6); empty when the socket has no IP peer.
std::string client_key(int sock);

class ConnectionGate {
 public:
  /// Serves the requests of a connection; runs on a worker thread.
  using Serve = std::function<AfterServe(ReadyConnection&)>;
  /// The whole HTTP response the gate sends for a refusal, given the bytes received so far (it may log).
  using Refuse = std::function<std::string(Refusal, std::string_view received)>;

  ConnectionGate(GateOptions options, Serve serve, Refuse refuse);
  ~ConnectionGate();
  ConnectionGate(const ConnectionGate&) = delete;
  ConnectionGate& operator=(const ConnectionGate&) = delete;

  /// Takes ownership of a newly accepted socket. When its client address already has max_per_client
  /// connections open, answers 503 and closes it. When max_open connections are already held, one
  /// draining after a refusal, or else the one that has waited longest, is closed to make room.
  void admit(int sock);
  /// Closes every held connection, lets the workers finish the requests already handed to them, and
  /// joins all threads. admit() after shutdown() closes the socket at once.
  void shutdown();
  /// True while more complete heads wait than idle workers can take: a worker should then not linger
  /// on its connection.
  bool requests_waiting() const;
  /// How many connections the gate holds at most: max_open, or fewer when descriptors are short.
  std::size_t capacity() const;
  /// Connections held by the gate now (waiting for a head, idle or draining), not those being served.
  std::size_t held() const;
  /// Connections open now from the address `client_key` names (held, queued or being served).
  std::size_t open_from(const std::string& client_key) const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace softtune::http
