// The one file that includes cpp-httplib. Debian's 0.11.4 is a compiled library, so its CPPHTTPLIB_*
// macros do nothing here; everything is set at run time. Its gaps, and how each is closed:
//  - Nagle + delayed ACK cost ~40 ms per keep-alive request: TCP_NODELAY on every connection.
//  - The payload limit skips chunked bodies and gzip bodies inflate without a limit: the pre-routing
//    hook refuses Transfer-Encoding, Content-Encoding and bodies without Content-Length, before the
//    body is read (request_policy.h), and closes the connection since the body was left unread.
//  - Its thread pool queues without bound, a connection holds a worker from its first byte to its close,
//    and its read timeout is per read(), so clients trickling one byte every few seconds (slowloris) or
//    merely keeping connections open take every worker. Here the library only accepts: each connection
//    waits in the ConnectionGate (one epoll loop) until its request head is complete, and only then
//    takes a worker (process_and_close_socket is overridden, as its own SSLServer does). The gate bounds
//    the connections it holds, the heads waiting for a worker (503 above) and the time to send a head
//    (408); a worker bounds the time left for the body and the head's bytes (431), and hands an idle
//    keep-alive connection back to the gate.

#include "http/http_transport.h"

#include <arpa/inet.h>
#include <httplib.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <condition_variable>
#include <cstdio>
#include <deque>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <vector>

#include "codec/problem.h"
#include "http/connection_gate.h"
#include "http/request_policy.h"

namespace softtune::http {
namespace {

using Clock = std::chrono::steady_clock;

// What the hooks of one connection share while a worker serves it, reached through a thread-local
// pointer from the library's callbacks.
struct ConnectionState {
  Clock::time_point request_start;
  std::size_t head_bytes = 0;  ///< request line and header bytes consumed so far
  bool head_done = false;      ///< the pre-routing hook ran: what follows is body
  bool head_overflow = false;  ///< the head outgrew limits::kMaxHeaderBytes
  bool close_after = false;    ///< answer, then close (the body was left unread)
  std::string_view route;      ///< the route pattern that answered (metrics label), empty if none ran
};
thread_local ConnectionState* t_connection = nullptr;

// How long a worker waits for the next request on a keep-alive connection before handing it back to
// the gate, unless other requests are waiting for a worker: a busy client sends it within a round trip,
// and serving it here saves two thread hand-offs. Checked in slices, so waiting requests cut it short.
constexpr std::chrono::microseconds kKeepAliveGrace{2000};
constexpr std::chrono::microseconds kGraceSlice{200};
// Response bytes collected before a send (see LimitedStream::write).
constexpr std::size_t kWriteBufferBytes = 64 * 1024;

int remaining_ms(Clock::time_point deadline) {
  const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
  return left <= 0 ? 0 : static_cast<int>(left);
}

// >0 ready, 0 timed out, <0 error.
int wait_for(int sock, short events, int timeout_ms) {
  pollfd p{sock, events, 0};
  for (;;) {
    const int n = ::poll(&p, 1, timeout_ms);
    if (n < 0 && errno == EINTR) continue;
    return n;
  }
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

// A socket stream that starts with the bytes the gate already read, whose reads share one deadline per
// request and count the head's bytes.
class LimitedStream final : public httplib::Stream {
 public:
  LimitedStream(int sock, ConnectionState& state, const TransportOptions& options, std::string received)
      : sock_(sock), state_(state), options_(options), buffer_(std::move(received)) {}

  void start_request(Clock::time_point first_byte) {
    state_ = ConnectionState{};
    state_.request_start = first_byte;
    deadline_ = first_byte + options_.request_read_timeout;
  }
  bool has_buffered() const { return begin_ < buffer_.size(); }
  bool head_buffered() const { return head_complete(std::string_view(buffer_).substr(begin_)); }
  std::string take_buffered() {
    std::string rest = buffer_.substr(begin_);
    buffer_.clear();
    begin_ = 0;
    return rest;
  }
  // Appends what has arrived, waiting up to `wait` for something; false when the client closed or the
  // socket failed.
  bool read_for(std::chrono::microseconds wait) {
    pollfd p{sock_, POLLIN, 0};
    const timespec t{0, static_cast<long>(std::chrono::nanoseconds(wait).count())};
    const int ready = ::ppoll(&p, 1, &t, nullptr);
    if (ready < 0) return errno == EINTR;
    if (ready == 0) return true;
    return receive() > 0;
  }

  bool is_readable() const override {
    if (has_buffered()) return true;
    if (!out_.empty() && !flush()) return false;
    return wait_for(sock_, POLLIN, remaining_ms(deadline_)) > 0;
  }
  bool is_writable() const override {
    return wait_for(sock_, POLLOUT, static_cast<int>(options_.write_timeout.count())) > 0;
  }

  // Reads try the socket first and wait only when it has nothing: one system call per read, not two.
  ssize_t read(char* ptr, size_t size) override {
    if (!has_buffered()) {
      if (!out_.empty() && !flush()) return -1;
      ssize_t n = receive();
      if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) {
        if (wait_for(sock_, POLLIN, remaining_ms(deadline_)) <= 0) return -1;
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
    }
    std::copy_n(buffer_.data() + begin_, n, ptr);
    begin_ += n;
    return static_cast<ssize_t>(n);
  }

  // The library writes a response's head and body separately; collecting them and sending once after
  // the request (flush()) saves a system call and a TCP segment per response. Large bodies go out as
  // the buffer fills, and anything pending goes out before the stream waits to read (100-continue).
  ssize_t write(const char* ptr, size_t size) override {
    out_.append(ptr, size);
    if (out_.size() >= kWriteBufferBytes && !flush()) return -1;
    return static_cast<ssize_t>(size);
  }

  bool flush() const {
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
  void get_remote_ip_and_port(std::string& ip, int& port) const override {
    if (remote_port_ < 0) peer_address(sock_, false, remote_ip_, remote_port_);
    ip = remote_ip_;
    port = remote_port_;
  }
  void get_local_ip_and_port(std::string& ip, int& port) const override {
    if (local_port_ < 0) peer_address(sock_, true, local_ip_, local_port_);
    ip = local_ip_;
    port = local_port_;
  }
  socket_t socket() const override { return sock_; }

 private:
  // One non-blocking recv appended to the buffer (consumed bytes are dropped first).
  ssize_t receive() {
    if (begin_ == buffer_.size()) {
      buffer_.clear();
      begin_ = 0;
    }
    std::array<char, 4096> chunk;
    const ssize_t n = ::recv(sock_, chunk.data(), chunk.size(), MSG_DONTWAIT);
    if (n > 0) buffer_.append(chunk.data(), static_cast<std::size_t>(n));
    return n;
  }

  int sock_;
  ConnectionState& state_;
  const TransportOptions& options_;
  Clock::time_point deadline_ = Clock::now();
  std::string buffer_;
  std::size_t begin_ = 0;
  mutable std::string out_;  ///< response bytes not sent yet (mutable: the library's is_readable() is const)
  mutable std::string remote_ip_, local_ip_;
  mutable int remote_port_ = -1, local_port_ = -1;
};

// The library's task queue, reduced to running the accept loop's hand-off inline: the override of
// process_and_close_socket passes the socket on to the gate this queue owns.
class GateQueue final : public httplib::TaskQueue {
 public:
  GateQueue(GateOptions options, ConnectionGate::Serve serve, ConnectionGate::Refuse refuse)
      : gate(options, std::move(serve), std::move(refuse)) {}
  void enqueue(std::function<void()> fn) override { fn(); }
  void shutdown() override { gate.shutdown(); }
  ConnectionGate gate;
};

HttpRequest plain_request(const httplib::Request& req) {
  HttpRequest out;
  out.method = req.method;
  out.path = req.path;
  for (const auto& [k, v] : req.headers) out.headers.emplace(k, v);
  out.query.insert(req.params.begin(), req.params.end());
  out.body = req.body;
  return out;
}

// The head as the request policy sees it: method, path and the few headers it reads.
HttpRequest policy_head(const httplib::Request& req) {
  HttpRequest out;
  out.method = req.method;
  out.path = req.path;
  for (const char* name : kPolicyHeaders) {
    if (auto it = req.headers.find(name); it != req.headers.end()) out.headers.emplace(name, it->second);
  }
  return out;
}

void fill(httplib::Response& res, HttpResponse&& plain) {
  res.status = plain.status;
  for (const auto& [k, v] : plain.headers) res.set_header(k, v);
  res.body = std::move(plain.body);
  res.set_header("Content-Type", plain.content_type);
}

// Answer, then close: the client learns it from the Connection header (the library adds one itself
// when the client asked to close).
void close_connection(const httplib::Request& req, httplib::Response& res) {
  if (req.get_header_value("Connection") != "close") res.set_header("Connection", "close");
  if (t_connection) t_connection->close_after = true;
}

// Control characters and spaces in a logged path become %XX, so a log line stays one readable line.
std::string printable(std::string_view s) {
  std::string out;
  for (char c : s.substr(0, 200)) {
    const auto u = static_cast<unsigned char>(c);
    if (u <= 0x20 || u == 0x7f || c == '%') {
      char buf[4];
      std::snprintf(buf, sizeof buf, "%%%02X", u);
      out += buf;
    } else {
      out += c;
    }
  }
  return out;
}

// Problems for the statuses the library produces itself, before any handler runs.
codec::Problem library_problem(int status) {
  switch (status) {
    case 400: return codec::Problem(400, "Bad request", "", "the request line or a header is malformed");
    case 413: return codec::Problem(413, "Payload too large", "Content-Length",
                                    "request bodies are limited to " + std::to_string(limits::kMaxBodyBytes) + " bytes");
    case 414: return codec::Problem(414, "URI too long", "path", "the request target is too long");
    case 404: return codec::Problem(404, "Not found", "path", "no route for this method and path");
    default: return codec::Problem(status, "HTTP error", "", "the request could not be served");
  }
}

}  // namespace

class LibraryServer final : public httplib::Server {
 public:
  LibraryServer(Service& service, const TransportOptions& options) : service_(service), options_(options) {}

  // The library listens with a backlog of 5: a burst of connections (a page loading, a load test, an
  // attack) overflows it, and a dropped SYN costs the client a one-second retransmission. Linux takes a
  // second listen() on a listening socket as a new backlog.
  void widen_backlog() { ::listen(svr_sock_, SOMAXCONN); }

  // The library's accept loop creates its task queue when it starts listening: the gate comes with it.
  httplib::TaskQueue* new_gate_queue() {
    GateOptions g;
    g.threads = options_.threads;
    g.max_open = options_.max_open_connections;
    g.max_ready = options_.max_queued;
    g.max_head_bytes = limits::kMaxHeaderBytes;
    g.request_read_timeout = options_.request_read_timeout;
    g.keep_alive_timeout = options_.keep_alive_timeout;
    auto* queue = new GateQueue(
        g, [this](ReadyConnection& c) { return serve(c); },
        [this](Refusal why, std::string_view received) { return refusal(why, received); });
    gate_ = &queue->gate;
    return queue;
  }

 private:
  // Runs on the accept thread: the connection goes to the gate, which closes it in the end.
  bool process_and_close_socket(socket_t sock) override {
    const int one = 1;
    ::setsockopt(sock, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
    gate_->admit(sock);
    return true;
  }

  // Runs on a worker with a whole head received: serves it, and the requests that follow at once.
  AfterServe serve(ReadyConnection& c) {
    ConnectionState state;
    t_connection = &state;
    LimitedStream stream(c.sock, state, options_, std::move(c.received));
    AfterServe after = AfterServe::close;
    for (;;) {
      stream.start_request(c.request_start);
      bool closed = false;
      const bool last = c.served + 1 >= options_.keep_alive_max_requests;
      const bool answered = process_request(stream, last, closed, nullptr);
      const bool ok = stream.flush() && answered;
      ++c.served;
      if (state.close_after || state.head_overflow) {
        after = AfterServe::drain_and_close;
        break;
      }
      if (!ok || closed || last) break;
      if (!next_head_soon(stream)) break;
      c.request_start = Clock::now();
      if (!stream.head_buffered() || gate_->requests_waiting()) {
        c.received = stream.take_buffered();
        after = AfterServe::keep_alive;
        break;
      }
    }
    t_connection = nullptr;
    return after;
  }

  // Reads the next request's head for a moment unless others wait for a worker; false when the client
  // closed.
  bool next_head_soon(LimitedStream& stream) const {
    for (auto waited = std::chrono::microseconds(0);
         waited < kKeepAliveGrace && !stream.head_buffered() && !gate_->requests_waiting(); waited += kGraceSlice) {
      if (!stream.read_for(kGraceSlice)) return false;
    }
    return true;
  }

  // The answer the gate sends itself: 503 when too many heads wait for a worker, 408 when a head is
  // not complete in time.
  std::string refusal(Refusal why, std::string_view received) {
    const Clock::time_point start = Clock::now();
    const codec::Problem p =
        why == Refusal::busy
            ? codec::Problem(503, "Service unavailable", "",
                             "the server is busy: " + std::to_string(options_.max_queued) +
                                 " requests are already waiting for a worker; retry shortly")
            : codec::Problem(408, "Request timeout", "",
                             "the request line and headers must arrive within " +
                                 std::to_string(options_.request_read_timeout.count()) + " ms");
    const std::string body = codec::problem_json(p).dump();
    const std::string_view line = received.substr(0, received.find("\r\n"));
    const std::string_view method = line.substr(0, line.find(' '));
    const std::size_t path_start = line.find(' ') == std::string_view::npos ? line.size() : line.find(' ') + 1;
    const std::string_view path = line.substr(path_start, line.find(' ', path_start) - path_start);
    finish(method, path, p.status, start);
    return "HTTP/1.1 " + std::to_string(p.status) + (why == Refusal::busy ? " Service Unavailable" : " Request Timeout") +
           "\r\nContent-Type: application/problem+json\r\n" + (why == Refusal::busy ? "Retry-After: 1\r\n" : "") +
           "Connection: close\r\nContent-Length: " + std::to_string(body.size()) + "\r\n\r\n" + body;
  }

 public:
  // One log line and one metrics sample per answered request.
  void finish(std::string_view method, std::string_view path, int status, Clock::time_point start,
              std::string_view route = {}) {
    const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
    service_.metrics().record_request(route.empty() ? service_.route_label(method, path) : route, status, seconds);
    if (options_.log) {
      options_.log(printable(method.substr(0, 16)) + " " + printable(path) + " " + std::to_string(status) + " " +
                   std::to_string(static_cast<long long>(seconds * 1e6)) + "us");
    }
  }

 private:
  Service& service_;
  const TransportOptions& options_;
  ConnectionGate* gate_ = nullptr;  ///< owned by the library's task queue while listening
};

struct HttpServer::Impl {
  Impl(Service& service, TransportOptions opts) : service(service), options(std::move(opts)), server(service, options) {}
  Service& service;
  TransportOptions options;
  LibraryServer server;
};

HttpServer::HttpServer(Service& service, TransportOptions options)
    : impl_(std::make_unique<Impl>(service, std::move(options))) {
  LibraryServer& s = impl_->server;
  const TransportOptions& o = impl_->options;
  s.set_tcp_nodelay(true);
  s.set_payload_max_length(limits::kMaxBodyBytes);
  s.set_keep_alive_max_count(o.keep_alive_max_requests);
  s.set_keep_alive_timeout(std::chrono::duration_cast<std::chrono::seconds>(o.keep_alive_timeout).count());
  s.set_read_timeout(o.request_read_timeout);
  s.set_write_timeout(o.write_timeout);
  s.new_task_queue = [&s] { return s.new_gate_queue(); };

  s.set_pre_routing_handler([](const httplib::Request& req, httplib::Response& res) {
    if (t_connection) t_connection->head_done = true;
    if (auto problem = check_request_head(policy_head(req))) {
      fill(res, problem_response(*problem));
      close_connection(req, res);
      return httplib::Server::HandlerResponse::Handled;
    }
    return httplib::Server::HandlerResponse::Unhandled;
  });

  // "Expect: 100-continue" is answered before the pre-routing hook runs: refuse there too, so a client
  // never sends a body we would refuse.
  s.set_expect_100_continue_handler([](const httplib::Request& req, httplib::Response& res) {
    if (auto problem = check_request_head(policy_head(req))) {
      fill(res, problem_response(*problem));
      close_connection(req, res);
      return problem->status;
    }
    return 100;
  });

  auto dispatch = [&routed = impl_->service](const httplib::Request& req, httplib::Response& res) {
    HttpResponse response = routed.handle(plain_request(req));
    if (t_connection) t_connection->route = response.route;
    fill(res, std::move(response));
  };
  s.Get(".*", dispatch);
  s.Post(".*", dispatch);
  s.Put(".*", dispatch);
  s.Patch(".*", dispatch);
  s.Delete(".*", dispatch);
  s.Options(".*", dispatch);

  // Statuses the library sets itself (malformed head, too long a target, ...) get a problem body too.
  s.set_error_handler(httplib::Server::HandlerWithResponse([](const httplib::Request& req, httplib::Response& res) {
    if (!res.body.empty()) return httplib::Server::HandlerResponse::Unhandled;
    // The library refuses a header line over its compiled-in limit with a bare 400; the bytes read
    // tell that case apart from a malformed head.
    const bool line_too_long = t_connection && !t_connection->head_done && res.status == 400 &&
                               t_connection->head_bytes > limits::kMaxHeaderLineBytes;
    if (t_connection && (t_connection->head_overflow || line_too_long)) {
      fill(res, problem_response(codec::Problem(431, "Request header fields too large", "headers",
                                                "the request line and headers are limited to " +
                                                    std::to_string(limits::kMaxHeaderBytes) + " bytes, each line to " +
                                                    std::to_string(limits::kMaxHeaderLineBytes))));
    } else {
      fill(res, problem_response(library_problem(res.status)));
    }
    close_connection(req, res);
    return httplib::Server::HandlerResponse::Handled;
  }));
  s.set_exception_handler([](const httplib::Request&, httplib::Response& res, std::exception_ptr) {
    fill(res, problem_response(codec::Problem(500, "Internal error", "", "the request could not be served")));
  });

  s.set_logger([&s](const httplib::Request& req, const httplib::Response& res) {
    if (!t_connection) return;
    s.finish(req.method, req.path, res.status, t_connection->request_start, t_connection->route);
  });
}

HttpServer::~HttpServer() { stop(); }

int HttpServer::bind() {
  const TransportOptions& o = impl_->options;
  if (o.port == 0) {
    const int port = impl_->server.bind_to_any_port(o.host);
    if (port <= 0) throw std::runtime_error("cannot listen on " + o.host + " (any port)");
    impl_->server.widen_backlog();
    return port;
  }
  if (!impl_->server.bind_to_port(o.host, o.port)) {
    throw std::runtime_error("cannot listen on " + o.host + ":" + std::to_string(o.port));
  }
  impl_->server.widen_backlog();
  return o.port;
}

void HttpServer::run() { impl_->server.listen_after_bind(); }

void HttpServer::stop() { impl_->server.stop(); }

bool HttpServer::running() const { return impl_->server.is_running(); }

}  // namespace softtune::http
