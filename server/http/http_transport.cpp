// The one file that includes cpp-httplib. Debian's 0.11.4 is a compiled library, so its CPPHTTPLIB_*
// macros do nothing here; everything is set at run time. Its gaps, and how each is closed:
//  - Nagle + delayed ACK cost ~40 ms per keep-alive request: TCP_NODELAY on every connection.
//  - The payload limit skips chunked bodies and gzip bodies inflate without a limit: the pre-routing
//    hook refuses Transfer-Encoding, Content-Encoding and bodies without Content-Length, before the
//    body is read (request_policy.h), and closes the connection since the body was left unread.
//  - Its thread pool queues without bound and its read timeout is per read(), so a client trickling
//    one byte every few seconds holds a worker forever. Connections are served here instead
//    (process_and_close_socket is overridden, as its own SSLServer does): a bounded queue that answers
//    503 when full, a deadline for reading each whole request, a cap on the request head's bytes (431),
//    and idle keep-alive connections closed after a timeout or a number of requests.

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
#include "http/request_policy.h"

namespace softtune::http {
namespace {

using Clock = std::chrono::steady_clock;

// What the hooks of one connection share. A connection is served by one thread from accept to close,
// so a thread-local pointer reaches it from the library's callbacks.
struct ConnectionState {
  Clock::time_point request_start;
  std::size_t head_bytes = 0;  ///< request line and header bytes consumed so far
  bool head_done = false;      ///< the pre-routing hook ran: what follows is body
  bool head_overflow = false;  ///< the head outgrew limits::kMaxHeaderBytes
  bool close_after = false;    ///< answer, then close (the body was left unread)
  std::string_view route;      ///< the route pattern that answered (metrics label), empty if none ran
};
thread_local ConnectionState* t_connection = nullptr;
// Set while the accept thread runs a connection that found the queue full: it gets 503 at once.
thread_local bool t_shed = false;

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

// A socket stream whose reads share one deadline per request and count the head's bytes.
class LimitedStream final : public httplib::Stream {
 public:
  LimitedStream(int sock, ConnectionState& state, const TransportOptions& options)
      : sock_(sock), state_(state), options_(options) {}

  void start_request() {
    state_ = ConnectionState{};
    state_.request_start = Clock::now();
    deadline_ = state_.request_start + options_.request_read_timeout;
  }
  bool has_buffered() const { return begin_ < end_; }

  bool is_readable() const override { return has_buffered() || wait_for(sock_, POLLIN, remaining_ms(deadline_)) > 0; }
  bool is_writable() const override {
    return wait_for(sock_, POLLOUT, static_cast<int>(options_.write_timeout.count())) > 0;
  }

  // Reads try the socket first and wait only when it has nothing: one system call per read, not two.
  ssize_t read(char* ptr, size_t size) override {
    if (!has_buffered()) {
      ssize_t n = ::recv(sock_, buffer_.data(), buffer_.size(), MSG_DONTWAIT);
      if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) {
        if (wait_for(sock_, POLLIN, remaining_ms(deadline_)) <= 0) return -1;
        n = ::recv(sock_, buffer_.data(), buffer_.size(), MSG_DONTWAIT);
      }
      if (n <= 0) return n;
      begin_ = 0;
      end_ = static_cast<std::size_t>(n);
    }
    std::size_t n = std::min(size, end_ - begin_);
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

  ssize_t write(const char* ptr, size_t size) override {
    ssize_t n = ::send(sock_, ptr, size, MSG_NOSIGNAL | MSG_DONTWAIT);
    if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) {
      if (wait_for(sock_, POLLOUT, static_cast<int>(options_.write_timeout.count())) <= 0) return -1;
      n = ::send(sock_, ptr, size, MSG_NOSIGNAL | MSG_DONTWAIT);
    }
    return n;
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
  int sock_;
  ConnectionState& state_;
  const TransportOptions& options_;
  Clock::time_point deadline_ = Clock::now();
  std::array<char, 4096> buffer_{};
  std::size_t begin_ = 0, end_ = 0;
  mutable std::string remote_ip_, local_ip_;
  mutable int remote_port_ = -1, local_port_ = -1;
};

// A fixed pool whose queue of waiting connections is bounded; past the bound the connection is run
// on the accepting thread with t_shed set, which answers 503 without reading much.
class BoundedQueue final : public httplib::TaskQueue {
 public:
  BoundedQueue(int threads, std::size_t max_queued) : max_queued_(max_queued) {
    for (int i = 0; i < threads; ++i) workers_.emplace_back([this] { work(); });
  }

  void enqueue(std::function<void()> fn) override {
    {
      std::unique_lock lock(mutex_);
      if (jobs_.size() < max_queued_) {
        jobs_.push_back(std::move(fn));
        lock.unlock();
        ready_.notify_one();
        return;
      }
    }
    t_shed = true;
    fn();
    t_shed = false;
  }

  void shutdown() override {
    {
      const std::lock_guard lock(mutex_);
      stopping_ = true;
    }
    ready_.notify_all();
    for (std::thread& t : workers_) t.join();
  }

 private:
  void work() {
    for (;;) {
      std::function<void()> fn;
      {
        std::unique_lock lock(mutex_);
        ready_.wait(lock, [this] { return stopping_ || !jobs_.empty(); });
        if (jobs_.empty()) return;
        fn = std::move(jobs_.front());
        jobs_.pop_front();
      }
      fn();
    }
  }

  const std::size_t max_queued_;
  std::mutex mutex_;
  std::condition_variable ready_;
  std::deque<std::function<void()>> jobs_;
  std::vector<std::thread> workers_;
  bool stopping_ = false;
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
    if (req.has_header(name)) out.headers.emplace(name, req.get_header_value(name));
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

 private:
  bool process_and_close_socket(socket_t sock) override {
    bool ret = false;
    if (t_shed) {
      shed(sock);
    } else {
      ret = serve_connection(sock);
    }
    ::shutdown(sock, SHUT_RDWR);
    ::close(sock);
    return ret;
  }

  // After a refusal the client may still be sending the body we did not read; closing now would reset
  // the connection and could destroy the answer before the client reads it. So: send FIN, discard what
  // still arrives for a moment (bounded in bytes and time), then close.
  static void lingering_close(int sock) {
    ::shutdown(sock, SHUT_WR);
    const Clock::time_point deadline = Clock::now() + std::chrono::milliseconds(500);
    std::size_t discarded = 0;
    char buf[16384];
    while (discarded < 2 * limits::kMaxBodyBytes && wait_for(sock, POLLIN, remaining_ms(deadline)) > 0) {
      const ssize_t n = ::recv(sock, buf, sizeof buf, 0);
      if (n <= 0) break;
      discarded += static_cast<std::size_t>(n);
    }
  }

  bool serve_connection(int sock) {
    const int one = 1;
    ::setsockopt(sock, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
    ConnectionState state;
    t_connection = &state;
    LimitedStream stream(sock, state, options_);
    bool ret = false;
    for (std::size_t served = 0; served < options_.keep_alive_max_requests; ++served) {
      if (!stream.has_buffered() && !wait_for_request(sock)) break;
      stream.start_request();
      bool closed = false;
      const bool last = served + 1 == options_.keep_alive_max_requests;
      ret = process_request(stream, last, closed, nullptr);
      if (state.close_after || state.head_overflow) {
        lingering_close(sock);
        break;
      }
      if (!ret || closed) break;
    }
    t_connection = nullptr;
    return ret;
  }

  // Waits for the next request on an idle connection in short slices, so stop() closes it promptly.
  bool wait_for_request(int sock) const {
    const Clock::time_point idle_deadline = Clock::now() + options_.keep_alive_timeout;
    while (svr_sock_ != INVALID_SOCKET) {
      const int left = remaining_ms(idle_deadline);
      if (left == 0) return false;
      const int n = wait_for(sock, POLLIN, std::min(left, 100));
      if (n != 0) return n > 0;
    }
    return false;
  }

  // 503 without handing the connection to a worker: drain what the client has sent (briefly, so the
  // close does not reset the connection before the answer is read), answer, close.
  void shed(int sock) {
    const Clock::time_point start = Clock::now();
    std::string head;
    char buf[4096];
    const Clock::time_point deadline = start + std::chrono::milliseconds(50);
    while (head.find("\r\n\r\n") == std::string::npos && head.size() < limits::kMaxHeaderBytes &&
           wait_for(sock, POLLIN, remaining_ms(deadline)) > 0) {
      const ssize_t n = ::recv(sock, buf, sizeof buf, MSG_DONTWAIT);
      if (n <= 0) break;
      head.append(buf, static_cast<std::size_t>(n));
    }
    const codec::Problem p(503, "Service unavailable", "",
                           "the server is busy: " + std::to_string(options_.max_queued) +
                               " connections are already waiting; retry shortly");
    const std::string body = codec::problem_json(p).dump();
    const std::string response = "HTTP/1.1 503 Service Unavailable\r\nContent-Type: application/problem+json\r\n"
                                 "Retry-After: 1\r\nConnection: close\r\nContent-Length: " +
                                 std::to_string(body.size()) + "\r\n\r\n" + body;
    ::send(sock, response.data(), response.size(), MSG_NOSIGNAL | MSG_DONTWAIT);
    ::shutdown(sock, SHUT_WR);
    while (wait_for(sock, POLLIN, remaining_ms(deadline)) > 0 && ::recv(sock, buf, sizeof buf, MSG_DONTWAIT) > 0) {
    }
    const std::string line = head.substr(0, head.find("\r\n"));
    const std::string method = line.substr(0, line.find(' '));
    const std::size_t path_start = line.find(' ') == std::string::npos ? line.size() : line.find(' ') + 1;
    const std::string path = line.substr(path_start, line.find(' ', path_start) - path_start);
    finish(method, path, 503, start);
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
  const int threads = o.threads;
  const std::size_t queued = o.max_queued;
  s.new_task_queue = [threads, queued] { return new BoundedQueue(threads, queued); };

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
    return port;
  }
  if (!impl_->server.bind_to_port(o.host, o.port)) {
    throw std::runtime_error("cannot listen on " + o.host + ":" + std::to_string(o.port));
  }
  return o.port;
}

void HttpServer::run() { impl_->server.listen_after_bind(); }

void HttpServer::stop() { impl_->server.stop(); }

bool HttpServer::running() const { return impl_->server.is_running(); }

}  // namespace softtune::http
