#pragma once
// What a request's head must satisfy before its body is read (the transport calls this from its
// pre-routing hook). It closes cpp-httplib 0.11.4's gaps: its payload limit does not apply to chunked
// bodies, it inflates gzip bodies without a limit, and it leaves a GET's body unread in the stream.

#include <optional>
#include <string_view>

#include "codec/problem.h"
#include "http/http_types.h"

namespace softtune::http {

/// The first rule the request head breaks, or nothing:
///   a header name that is not a token (RFC 9110 5.6.2), such as "Transfer-Encoding " with a space
///   before the colon (RFC 9112 5.1: a server must refuse it; read as another header it is the shape of
///   request smuggling)                  -> 400 naming the header
///   HTTP/1.1 without Host, Host twice, or a Host that is no host[:port] (RFC 9112 3.2) -> 400 naming Host
///   Transfer-Encoding present            -> 411 (bodies must come with Content-Length)
///   Content-Encoding present             -> 415 (compressed bodies are refused)
///   POST/PUT/PATCH without Content-Length -> 411
///   Content-Type or Content-Length twice -> 400
///   Content-Length not a decimal number  -> 400
///   Content-Length > limits::kMaxBodyBytes -> 413
///   GET/HEAD/DELETE/OPTIONS with a body   -> 400
///   a body whose Content-Type is not application/json -> 415 (POST /api/v1/identify also takes text/csv)
/// `version` is the request line's ("HTTP/1.0" may omit Host).
std::optional<codec::Problem> check_request_head(const HttpRequest& head, std::string_view version = "HTTP/1.1");

}  // namespace softtune::http
