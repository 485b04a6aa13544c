#pragma once
// The transport's refusal writer (private to the transport: only its files include it): every 4xx/5xx
// answer written before a route handler runs, as problem+json like the handlers' own answers:
//  - a head the request policy refuses (request_policy.h: 411, 415, 400, 413), from the pre-routing and
//    100-continue hooks, before the body is read;
//  - a status the library set itself on a head it could not take (400, 413, 414, 404), and 431 for a
//    head past limits::kMaxHeaderBytes or a line past limits::kMaxHeaderLineBytes;
//  - 500 from the library's exception handler (Service::handle never lets one out: a last guard);
//  - the ConnectionGate's own answers, written here as whole HTTP responses since no library request
//    exists yet: 503 when too many heads wait for a worker or the client's address has too many connections
//    open, 408 when a head does not arrive in time.
//
// cpp-httplib 0.11.4 used here (the version server/CMakeLists.txt pins): httplib::Request's method, path
// and headers; that its error handler sees the status it set with an empty body; and that it refuses a
// header line longer than its compiled-in CPPHTTPLIB_HEADER_MAX_LENGTH (8192 bytes, which
// limits::kMaxHeaderLineBytes repeats) with a bare 400, told apart here by the head bytes the stream read.

#include <httplib.h>

#include <optional>
#include <string>
#include <string_view>

#include "http/connection_gate.h"
#include "http/http_transport.h"
#include "http/cors.h"
#include "http/http_types.h"
#include "http/transport_stream.h"

namespace softtune::http {

/// The request policy's refusal of this head, or nothing (the request goes on to its handler).
std::optional<HttpResponse> head_refusal(const httplib::Request& req);

/// The methods the transport hands to the service (HEAD is served as GET).
inline constexpr const char* kServedMethods[] = {"GET", "HEAD", "POST", "PUT", "PATCH", "DELETE", "OPTIONS"};

/// The answer to `status`, which the library set itself before any handler ran. `state` is the
/// connection's (null outside a worker): its head counts tell a too-long head (431) from a malformed one.
/// `method` is the request line's first word as the library read it: a 400 for a well-formed method the
/// service does not implement (TRACE, CONNECT, a lower-case "get", any other token; methods are
/// case-sensitive, RFC 9110 9.1) is 501 instead.
HttpResponse library_refusal(int status, std::string_view method, const ConnectionState* state);

/// The answer when a handler's exception reached the library (500).
HttpResponse internal_error_refusal();

/// An answer the ConnectionGate sends itself: the whole HTTP response, and what its log line needs.
struct GateRefusal {
  int status = 0;
  std::string_view method, path;  ///< from the request line received so far (views into `received`)
  std::string response;           ///< status line, headers (Connection: close) and problem+json body
};
/// With `cors` on, the answer carries the CORS headers for the Origin header of the head received so far
/// (every answer does, cors.h; a 408's head may be cut short, and then it has them when Origin arrived).
GateRefusal gate_refusal(Refusal why, std::string_view received, const TransportOptions& options,
                         const CorsPolicy& cors = {});

/// The value of header `name` (case-insensitive, RFC 9110 5.1) in a raw request head, possibly incomplete:
/// only whole lines count. Nullopt when absent.
std::optional<std::string> raw_header(std::string_view head, std::string_view name);

}  // namespace softtune::http
