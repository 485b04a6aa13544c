#pragma once
// An in-process server on an ephemeral loopback port, and a raw socket client for requests that
// httplib::Client will not send (path tricks, chunked heads, slow clients).

#include <arpa/inet.h>
#include <httplib.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <string>
#include <thread>

#include "http/http_transport.h"
#include "http/routes.h"

namespace softtune::http::testing {

/// Timeouts short enough that every test stays within a few seconds.
inline TransportOptions quick_options() {
  TransportOptions o;
  o.host = "127.0.0.1";
  o.port = 0;
  o.threads = 4;
  o.request_read_timeout = std::chrono::milliseconds(1500);
  o.write_timeout = std::chrono::milliseconds(1500);
  o.keep_alive_timeout = std::chrono::milliseconds(1500);
  return o;
}

inline ServiceConfig web_config() {
  ServiceConfig c;
  c.web_root = SOFTTUNE_SOURCE_DIR "/web";
  return c;
}

/// The repository's presets directory, and the service as `softtune serve --presets DIR` gives it
/// (not through $SOFTTUNE_PRESETS).
/// The JSON media type, as a request's Content-Type.
inline constexpr const char* kJson = "application/json";

/// An answer's media type, without parameters ("application/json; charset=utf-8" -> "application/json").
inline std::string media_type(const httplib::Result& r) {
  const std::string t = r->get_header_value("Content-Type");
  return t.substr(0, t.find(';'));
}

inline const std::string kRepositoryPresets = SOFTTUNE_SOURCE_DIR "/presets";
inline ServiceConfig presets_config() {
  ServiceConfig c = web_config();
  c.presets_dir = kRepositoryPresets;
  return c;
}

class TestServer {
 public:
  explicit TestServer(TransportOptions options = quick_options(), ServiceConfig config = web_config())
      : service_(std::move(config), service_routes()), server_(service_, std::move(options)) {
    port_ = server_.bind();
    thread_ = std::thread([this] { server_.run(); });
    while (!server_.running()) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  ~TestServer() {
    server_.stop();
    thread_.join();
  }
  int port() const { return port_; }
  Service& service() { return service_; }
  HttpServer& server() { return server_; }
  httplib::Client client() const {
    httplib::Client c("127.0.0.1", port_);
    c.set_read_timeout(5, 0);
    return c;
  }

 private:
  Service service_;
  HttpServer server_;
  int port_ = 0;
  std::thread thread_;
};

/// A plain TCP connection to the test server.
class RawConnection {
 public:
  /// `source`: the local IPv4 address to connect from ("127.0.0.2": any of 127.0.0.0/8 is this machine),
  /// so that one test can be several clients; the default lets the kernel choose (127.0.0.1).
  explicit RawConnection(int port, const char* source = nullptr) {
    fd_ = ::socket(AF_INET, SOCK_STREAM, 0);
    if (source != nullptr) {
      sockaddr_in local{};
      local.sin_family = AF_INET;
      ::inet_pton(AF_INET, source, &local.sin_addr);
      if (::bind(fd_, reinterpret_cast<sockaddr*>(&local), sizeof local) != 0) return;
    }
    sockaddr_in addr{};
    addr.sin_family = AF_INET;
    addr.sin_port = htons(static_cast<uint16_t>(port));
    addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    connected_ = ::connect(fd_, reinterpret_cast<sockaddr*>(&addr), sizeof addr) == 0;
  }
  ~RawConnection() { ::close(fd_); }
  bool connected() const { return connected_; }

  bool send(const std::string& bytes) {
    return ::send(fd_, bytes.data(), bytes.size(), MSG_NOSIGNAL) == static_cast<ssize_t>(bytes.size());
  }

  /// Everything received until the peer closes or `timeout` passes with nothing new.
  std::string receive(std::chrono::milliseconds timeout = std::chrono::milliseconds(3000)) {
    std::string out;
    char buf[4096];
    pollfd p{fd_, POLLIN, 0};
    while (::poll(&p, 1, static_cast<int>(timeout.count())) > 0) {
      const ssize_t n = ::recv(fd_, buf, sizeof buf, 0);
      if (n <= 0) {
        closed_ = true;
        break;
      }
      out.append(buf, static_cast<std::size_t>(n));
    }
    return out;
  }
  /// What one read returns once something arrives (empty when `timeout` passes or the peer closed).
  std::string receive_some(std::chrono::milliseconds timeout = std::chrono::milliseconds(3000)) {
    char buf[65536];
    pollfd p{fd_, POLLIN, 0};
    if (::poll(&p, 1, static_cast<int>(timeout.count())) <= 0) return {};
    const ssize_t n = ::recv(fd_, buf, sizeof buf, 0);
    if (n <= 0) {
      closed_ = true;
      return {};
    }
    return std::string(buf, static_cast<std::size_t>(n));
  }
  /// True once receive() or receive_some() saw the server close the connection.
  bool closed() const { return closed_; }

 private:
  int fd_ = -1;
  bool connected_ = false;
  bool closed_ = false;
};

/// The status code of a raw HTTP response ("HTTP/1.1 404 ..." -> 404), 0 when there is none.
inline int status_of(const std::string& response) {
  if (response.rfind("HTTP/1.", 0) != 0 || response.size() < 12) return 0;
  return std::stoi(response.substr(9, 3));
}

/// One raw request on a fresh connection; the whole response (the server closes after refusals).
inline std::string exchange(int port, const std::string& request,
                            std::chrono::milliseconds timeout = std::chrono::milliseconds(3000)) {
  RawConnection c(port);
  c.send(request);
  return c.receive(timeout);
}

/// The body of a raw HTTP response.
inline std::string body_of(const std::string& response) {
  const std::size_t end = response.find("\r\n\r\n");
  return end == std::string::npos ? "" : response.substr(end + 4);
}

}  // namespace softtune::http::testing
