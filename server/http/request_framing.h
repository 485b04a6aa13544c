#pragma once
// Where a request ends, read from its raw head, for the ConnectionGate: it holds a connection until the
// whole request (head and a Content-Length body) has arrived, so that a worker is taken only by a request
// it can serve at once, and a body trickling in costs a buffer, never a worker. Knows only the framing
// headers (RFC 9112 6.3); everything else about the head is the request policy's (request_policy.h).

#include <cstddef>
#include <optional>
#include <string_view>

namespace softtune::http {

/// The size of the head (request line, headers and the blank line) when `received` holds all of it.
std::optional<std::size_t> head_size(std::string_view received);

/// How many bytes of `received` make up its first request, once the head is complete: the head plus
/// the body its one well-formed Content-Length declares, when that is at most `max_body_bytes` and the head
/// has no Transfer-Encoding and no Expect. For any other head, the head alone: the worker refuses it before
/// reading a body (411, 413, 400) or reads an expected body itself. Nullopt while the head is incomplete.
std::optional<std::size_t> request_size(std::string_view received, std::size_t max_body_bytes);

/// True when the first request is a GET or HEAD of /api/v1/health or /metrics: those go to the reserved
/// lane, so that a probe is answered however many other requests wait.
bool is_lane_request(std::string_view received);

}  // namespace softtune::http
