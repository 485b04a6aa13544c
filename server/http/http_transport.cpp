// The transport's glue to httplib::Server: the library accepts connections and parses requests; the
// ConnectionGate holds each connection until its head is complete; a worker then serves it on a
// LimitedStream (transport_stream.h); the library's hooks hand plain HttpRequests to the Service and
// answers that no handler writes to the refusal writer (transport_refusals.h); each answered request
// gets one log line and one metrics sample here. Only the transport's files (this one,
// transport_stream.* and transport_refusals.*) include cpp-httplib; tests/http checks it.
//
// Debian's cpp-httplib 0.11.4 is a compiled library, so its CPPHTTPLIB_* macros do nothing here;
// everything is set at run time. Its gaps, and how each is closed:
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
//    (408); it also holds the body a Content-Length declares until all of it has arrived, at a minimum
//    rate (408 below it), so a body trickling in holds no worker either; health and metrics have a
//    reserved worker (connection_gate.h). A worker bounds the time for a body it reads itself and the
//    head's bytes (431), and hands an idle keep-alive connection back to the gate.
//  - It serves Range requests by building the whole multipart answer in memory, any number of ranges
//    (Server::apply_ranges): one 3 KB header of 1000 ranges made a 229 MB answer of openapi.json. Range
//    is ignored here, as RFC 9110 14.2 allows: the setup hook that process_request runs after parsing the
//    head clears the parsed ranges, so every answer is the whole representation with its own status
//    (HEAD says "Accept-Ranges: none"). A Range header the library cannot parse it answers 416 itself.
//  - It sends "Content-Length: 0" on a 204 and a 304, which RFC 9110 8.6 forbids: the post-routing hook
//    removes it.
//  - Its query parser drops a repeated name=value pair, so "format=json&format=json" would look like one
//    value: the query is split again here from the raw target.
//
// Library internals this file relies on, beyond the public API, all of 0.11.4 (the version
// server/CMakeLists.txt pins; check each one before moving to another version):
//  - Server::process_and_close_socket (a private virtual): overridden so that an accepted socket goes
//    to the gate instead of a library thread.
//  - Server::process_request(Stream&, close_connection, connection_closed, setup) (protected): called to
//    serve one request from our stream; with close_connection it answers with "Connection: close".
//  - Server::svr_sock_ (protected): the listening socket, listened on again with SOMAXCONN since the
//    library's backlog is a compiled-in 5.
//  - Server::new_task_queue called once per listen, and TaskQueue::enqueue called on the accept thread
//    with a task that runs process_and_close_socket(sock), and TaskQueue::shutdown() on stop: the gate
//    is created with the queue and enqueue runs the task inline.
//  - The order of the hooks for one request: the head is read through the stream, then the setup hook
//    (process_request's last argument), then the 100-continue handler (when asked), then the pre-routing
//    handler, then the body, then the route handler; the error handler runs with the library's own status
//    and an empty body (400 when reading the body failed); the post-routing handler runs after the
//    library added its own headers, just before they are written; the logger runs once after each answer.
//  - httplib::detail::decode_url(s, convert_plus_to_space), which the compiled library exports.

#include "http/http_transport.h"

#include <httplib.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <stdexcept>

#include "http/connection_gate.h"
#include "http/transport_refusals.h"
#include "http/transport_stream.h"

namespace softtune::http {
namespace {

using Clock = TransportClock;

thread_local ConnectionState* t_connection = nullptr;
thread_local int t_socket = -1;  ///< the connection the worker serves

// True once the client closed its side (or the connection failed): the request's work may stop
// (softtune/support/run_limit.h), since no one will read its answer.
bool client_closed(int sock) {
  pollfd p{sock, POLLRDHUP, 0};
  return ::poll(&p, 1, 0) > 0 && (p.revents & (POLLRDHUP | POLLHUP | POLLERR)) != 0;
}

// How long a worker waits for the next request on a keep-alive connection before handing it back to
// the gate, unless other requests are waiting for a worker: a busy client sends it within a round trip,
// and serving it here saves two thread hand-offs. Checked in slices, so waiting requests cut it short.
constexpr std::chrono::microseconds kKeepAliveGrace{2000};
constexpr std::chrono::microseconds kGraceSlice{200};

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

// Every name=value pair of the target's query, repeats included (the library keeps one of equal pairs).
std::multimap<std::string, std::string> raw_query(const std::string& target) {
  std::multimap<std::string, std::string> out;
  const std::size_t q = target.find('?');
  if (q == std::string::npos) return out;
  const std::string_view query = std::string_view(target).substr(q + 1);
  std::size_t start = 0;
  while (start <= query.size()) {
    std::size_t end = query.find('&', start);
    if (end == std::string_view::npos) end = query.size();
    const std::string_view pair = query.substr(start, end - start);
    start = end + 1;
    const std::size_t eq = pair.find('=');
    const std::string key(pair.substr(0, eq));
    if (key.empty()) continue;  // as the library does
    const std::string value(eq == std::string_view::npos ? std::string_view() : pair.substr(eq + 1));
    out.emplace(httplib::detail::decode_url(key, true), httplib::detail::decode_url(value, true));
  }
  return out;
}

HttpRequest plain_request(const httplib::Request& req) {
  HttpRequest out;
  out.method = req.method;
  out.path = req.path;
  for (const auto& [k, v] : req.headers) out.headers.emplace(k, v);
  out.query = raw_query(req.target);
  out.body = req.body;
  if (const int sock = t_socket; sock >= 0) out.client_gone = [sock] { return client_closed(sock); };
  return out;
}

// Range is ignored (see the top of this file): the whole representation, never a library-built range.
void ignore_ranges(httplib::Request& req) { req.ranges.clear(); }

void fill(httplib::Response& res, HttpResponse&& plain) {
  res.status = plain.status;
  for (const auto& [k, v] : plain.headers) res.set_header(k, v);
  res.body = std::move(plain.body);
  // A 304 or 204 has no content, so no Content-Type line (not an empty one).
  if (!plain.content_type.empty()) res.set_header("Content-Type", plain.content_type);
}

std::optional<std::string> origin_of(const httplib::Request& req) {
  if (!req.has_header("Origin")) return std::nullopt;
  return req.get_header_value("Origin");
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
    g.max_per_client = options_.max_client_connections;
    g.max_ready = options_.max_queued;
    g.max_head_bytes = limits::kMaxHeaderBytes;
    g.request_read_timeout = options_.request_read_timeout;
    g.keep_alive_timeout = options_.keep_alive_timeout;
    g.max_body_bytes = limits::kMaxBodyBytes;
    g.min_body_rate = limits::kMinBodyBytesPerSecond;
    g.body_grace = limits::kBodyGrace;
    g.max_buffered_bytes = limits::kMaxGateBufferedBytes;
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
    t_socket = c.sock;
    LimitedStream stream(c.sock, state, options_, std::move(c.received));
    AfterServe after = AfterServe::close;
    for (;;) {
      stream.start_request(c.request_start);
      bool closed = false;
      const bool last = c.served + 1 >= options_.keep_alive_max_requests;
      const bool answered = process_request(stream, last, closed, ignore_ranges);
      const bool ok = stream.flush() && answered;
      ++c.served;
      if (state.close_after || state.head_overflow) {
        after = AfterServe::drain_and_close;
        break;
      }
      if (!ok || closed || last) break;
      // The reserved lane's worker serves one probe and gives the connection back.
      if (c.lane) {
        c.received = stream.take_buffered();
        c.request_start = Clock::now();
        after = AfterServe::keep_alive;
        break;
      }
      if (!next_head_soon(stream)) break;
      c.request_start = Clock::now();
      if (!stream.request_buffered() || gate_->requests_waiting()) {
        c.received = stream.take_buffered();
        after = AfterServe::keep_alive;
        break;
      }
    }
    t_connection = nullptr;
    t_socket = -1;
    return after;
  }

  // Reads the next request's head for a moment unless others wait for a worker; false when the client
  // closed.
  bool next_head_soon(LimitedStream& stream) const {
    for (auto waited = std::chrono::microseconds(0);
         waited < kKeepAliveGrace && !stream.request_buffered() && !gate_->requests_waiting(); waited += kGraceSlice) {
      if (!stream.read_for(kGraceSlice)) return false;
    }
    return true;
  }

  // The answer the gate sends itself: 503 when too many heads wait for a worker or the client's address
  // has too many connections open, 408 when a head is not complete in time.
  std::string refusal(Refusal why, std::string_view received) {
    const Clock::time_point start = Clock::now();
    GateRefusal answer = gate_refusal(why, received, options_, service_.config().cors);
    finish(answer.method, answer.path, answer.status, start);
    return std::move(answer.response);
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

  s.set_pre_routing_handler([&service = impl_->service](const httplib::Request& req, httplib::Response& res) {
    if (t_connection) {
      t_connection->head_done = true;
      // For a body the gate did not buffer. The request policy below checks the length; a longer one is
      // refused unread, so the bound here only keeps the arithmetic in range.
      const std::size_t length = std::strtoull(req.get_header_value("Content-Length").c_str(), nullptr, 10);
      t_connection->body_deadline = body_deadline(Clock::now(), std::min<std::size_t>(length, limits::kMaxBodyBytes));
    }
    if (auto refusal = head_refusal(req)) {
      service.add_cors(origin_of(req), *refusal);
      fill(res, std::move(*refusal));
      close_connection(req, res);
      return httplib::Server::HandlerResponse::Handled;
    }
    return httplib::Server::HandlerResponse::Unhandled;
  });

  // "Expect: 100-continue" is answered before the pre-routing hook runs: refuse there too, so a client
  // never sends a body we would refuse.
  s.set_expect_100_continue_handler([&service = impl_->service](const httplib::Request& req, httplib::Response& res) {
    if (auto refusal = head_refusal(req)) {
      service.add_cors(origin_of(req), *refusal);
      const int status = refusal->status;
      fill(res, std::move(*refusal));
      close_connection(req, res);
      return status;
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
  s.set_error_handler(httplib::Server::HandlerWithResponse([&service = impl_->service](const httplib::Request& req, httplib::Response& res) {
    if (!res.body.empty()) return httplib::Server::HandlerResponse::Unhandled;
    HttpResponse refusal = library_refusal(res.status, req.method, t_connection);
    // A 414 is answered before the headers are parsed: its Origin is found in the bytes read.
    std::optional<std::string> origin = origin_of(req);
    if (!origin && t_connection) origin = raw_header(t_connection->head_seen, "Origin");
    service.add_cors(origin, refusal);
    fill(res, std::move(refusal));
    close_connection(req, res);
    return httplib::Server::HandlerResponse::Handled;
  }));
  s.set_exception_handler([](const httplib::Request&, httplib::Response& res, std::exception_ptr) {
    fill(res, internal_error_refusal());
  });

  // The library has added its own headers: a 1xx, 204 or 304 carries no Content-Length (RFC 9110 8.6),
  // and HEAD says ranges are not served (the library says "bytes").
  s.set_post_routing_handler([](const httplib::Request& req, httplib::Response& res) {
    if (res.status < 200 || res.status == 204 || res.status == 304) res.headers.erase("Content-Length");
    if (req.method == "HEAD") {
      res.headers.erase("Accept-Ranges");
      res.set_header("Accept-Ranges", "none");
    }
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
