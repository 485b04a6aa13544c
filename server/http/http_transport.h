#pragma once
// The HTTP transport: the only part that knows cpp-httplib. Connections wait in a ConnectionGate until
// their request head is complete; then a worker reads the rest with the limits of http/limits.h,
// refuses bad heads before their bodies are read (request_policy.h), hands plain HttpRequests to the
// Service, logs one line per request and feeds the metrics.

#include <chrono>
#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <string_view>

#include "http/limits.h"
#include "http/service.h"

namespace softtune::http {

struct TransportOptions {
  std::string host = "127.0.0.1";
  int port = 8080;  ///< 0: any free port (bind() returns it)
  int threads = limits::kDefaultThreads;
  std::size_t max_queued = limits::kMaxQueuedConnections;  ///< complete heads waiting for a worker
  std::size_t max_open_connections = limits::kMaxOpenConnections;
  /// Connections one client address may have open at once (held, queued or served); 0: no limit.
  std::size_t max_client_connections = limits::kMaxConnectionsPerClient;
  std::chrono::milliseconds request_read_timeout = limits::kRequestReadTimeout;
  std::chrono::milliseconds write_timeout = limits::kWriteTimeout;
  std::chrono::milliseconds keep_alive_timeout = limits::kKeepAliveTimeout;
  std::size_t keep_alive_max_requests = limits::kKeepAliveMaxRequests;
  /// Receives one line per answered request ("POST /api/v1/tune 200 412us"); none when empty.
  std::function<void(std::string_view)> log;
};

class HttpServer {
 public:
  HttpServer(Service& service, TransportOptions options);
  ~HttpServer();
  HttpServer(const HttpServer&) = delete;
  HttpServer& operator=(const HttpServer&) = delete;

  /// Binds the listening socket; returns the port. Throws std::runtime_error when it cannot.
  int bind();
  /// Serves until stop(), then waits for the requests in flight to finish.
  void run();
  /// Stops accepting and closes idle connections; safe from any thread (not from a signal handler).
  void stop();
  /// True once run() is accepting connections.
  bool running() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace softtune::http
