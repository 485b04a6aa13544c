#pragma once
// What a request's head must satisfy before its body is read (the transport calls this from its
// pre-routing hook). It closes cpp-httplib 0.11.4's gaps: its payload limit does not apply to chunked
// bodies, it inflates gzip bodies without a limit, and it leaves a GET's body unread in the stream.

#include <optional>

#include "codec/problem.h"
#include "http/http_types.h"

namespace softtune::http {

/// The only headers check_request_head reads (the transport copies just these for it).
inline constexpr const char* kPolicyHeaders[] = {"Transfer-Encoding", "Content-Encoding", "Content-Length", "Content-Type"};

/// The first rule the request head breaks, or nothing:
///   Transfer-Encoding present            -> 411 (bodies must come with Content-Length)
///   Content-Encoding present             -> 415 (compressed bodies are refused)
///   POST/PUT/PATCH without Content-Length -> 411
///   Content-Type or Content-Length twice -> 400
///   Content-Length not a decimal number  -> 400
///   Content-Length > limits::kMaxBodyBytes -> 413
///   GET/HEAD/DELETE/OPTIONS with a body   -> 400
///   a body whose Content-Type is not application/json -> 415 (POST /api/v1/identify also takes text/csv)
std::optional<codec::Problem> check_request_head(const HttpRequest& head);

}  // namespace softtune::http
