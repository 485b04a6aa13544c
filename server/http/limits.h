#pragma once
// Every limit of the HTTP service, named once. docs/limits-and-security.md "Limits" and the OpenAPI document
// (info.x-softtune-limits) list the same numbers; tests/http/openapi_test.cpp checks that they agree.

#include <chrono>
#include <cstddef>

#include "codec/json_reader.h"

namespace softtune::http::limits {

/// Largest request body (bytes); a larger Content-Length is refused with 413 before the body is read.
inline constexpr std::size_t kMaxBodyBytes = 1 << 20;
/// Largest request line plus headers (bytes); more is refused with 431.
inline constexpr std::size_t kMaxHeaderBytes = 16 * 1024;
/// Longest single request line or header line (bytes): cpp-httplib 0.11.4's compiled-in
/// CPPHTTPLIB_HEADER_MAX_LENGTH / CPPHTTPLIB_REQUEST_URI_MAX_LENGTH; a longer header line is 431, a
/// longer request line 414.
inline constexpr std::size_t kMaxHeaderLineBytes = 8192;
/// Deepest JSON nesting accepted (400 above); nlohmann's recursive dump and copy crash on deep documents.
inline constexpr int kMaxJsonDepth = codec::kMaxJsonDepth;

/// Worker threads, each serving one connection whose request head is complete.
inline constexpr int kDefaultThreads = 8;
inline constexpr int kMaxThreads = 256;
/// Requests with a complete head waiting for a free worker; a request arriving when this many are
/// already waiting gets 503 at once.
inline constexpr std::size_t kMaxQueuedConnections = 64;
/// Connections held open while their request head arrives, idle on keep-alive, or draining after a
/// refusal (they cost a buffer and a file descriptor, never a worker). A new connection arriving when
/// this many are held closes one that is draining, or else the one that has waited longest.
inline constexpr std::size_t kMaxOpenConnections = 1024;
/// Connections one client address may have open at once, wherever they are (arriving, idle, queued, being
/// served), so that one client cannot take every place among kMaxOpenConnections; the next one from that
/// address is answered 503 with Retry-After: 1 at once, before any byte of it is read, and closed.
inline constexpr std::size_t kMaxConnectionsPerClient = 128;

/// Reading one whole request (line, headers and body) must finish within this time, however slowly
/// the bytes trickle in (a per-read timeout alone lets a client send one byte every few seconds forever);
/// a head still incomplete then gets 408.
inline constexpr std::chrono::milliseconds kRequestReadTimeout{10'000};
/// Once the head is in, its body (Content-Length bytes) must arrive within kBodyGrace plus its length at
/// kMinBodyBytesPerSecond, and within kRequestReadTimeout in any case; else 408. A body arriving waits in
/// the connection gate, never in a worker.
inline constexpr std::size_t kMinBodyBytesPerSecond = 128 * 1024;
inline constexpr std::chrono::milliseconds kBodyGrace{1'000};
/// Request bytes (heads and bodies arriving) the connection gate holds in all; past it the connection
/// that has waited longest is closed.
inline constexpr std::size_t kMaxGateBufferedBytes = 64u << 20;
/// Each write of a response must make progress within this time.
inline constexpr std::chrono::milliseconds kWriteTimeout{10'000};
/// An idle keep-alive connection is closed after this time, and after this many requests.
inline constexpr std::chrono::milliseconds kKeepAliveTimeout{5'000};
inline constexpr std::size_t kKeepAliveMaxRequests = 1000;

/// A request is stopped while it runs once its thread has taken this multiple of its CPU budget
/// (app/budgets.h kCpuSeconds; a job of kJobCpuSeconds), or when its client has gone: the estimate before
/// the work may be wrong (a crowded scene), the limit at run time holds (softtune/support/run_limit.h).
inline constexpr double kRunLimitFactor = 2.0;

/// Responses of deterministic contracts (tune) kept for repeated requests (a designer moving a slider
/// back and forth asks the same thing again): at most this many entries and bytes, least recently
/// used evicted first.
inline constexpr std::size_t kResponseCacheEntries = 4096;
inline constexpr std::size_t kResponseCacheBytes = 64u << 20;

}  // namespace softtune::http::limits
