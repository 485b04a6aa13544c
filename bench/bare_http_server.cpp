// The baseline for bench/http_bench.sh: a bare cpp-httplib endpoint answering POST /api/v1/tune with a
// fixed JSON body (the bytes softtune returns for the benchmark's request), on the same thread count,
// TCP_NODELAY and keep-alive settings as `softtune serve`, so the ratio measures what softtune adds:
// routing, limits, parsing, the tune itself, metrics and logging.
//
//   bare_http_server BODY_FILE [THREADS]   prints "port N", serves on 127.0.0.1 until killed
#include <httplib.h>

#include <fstream>
#include <iostream>
#include <iterator>

#include "http/limits.h"

int main(int argc, char** argv) {
  if (argc < 2) {
    std::cerr << "usage: bare_http_server BODY_FILE [THREADS]\n";
    return 2;
  }
  std::ifstream in(argv[1], std::ios::binary);
  const std::string body((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const int threads = argc > 2 ? std::atoi(argv[2]) : softtune::http::limits::kDefaultThreads;
  httplib::Server server;
  server.new_task_queue = [threads] { return new httplib::ThreadPool(static_cast<size_t>(threads)); };
  server.set_tcp_nodelay(true);
  server.set_keep_alive_max_count(softtune::http::limits::kKeepAliveMaxRequests);
  server.set_keep_alive_timeout(5);
  server.Post("/api/v1/tune", [&body](const httplib::Request&, httplib::Response& res) {
    res.set_content(body, "application/json");
  });
  const int port = server.bind_to_any_port("127.0.0.1");
  if (port <= 0) return 1;
  std::cout << "port " << port << std::endl;
  server.listen_after_bind();
  return 0;
}
