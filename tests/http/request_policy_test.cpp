#include "http/request_policy.h"

#include <gtest/gtest.h>

#include "http/limits.h"

using softtune::http::check_request_head;
using softtune::http::HttpRequest;

namespace {

HttpRequest head(std::string method, std::initializer_list<std::pair<const char*, std::string>> headers) {
  HttpRequest r;
  r.method = std::move(method);
  r.path = "/api/v1/tune";
  for (const auto& [k, v] : headers) r.headers.emplace(k, v);
  if (!r.header("Host")) r.headers.emplace("Host", "t");  // an HTTP/1.1 request names its host
  return r;
}

// "status field" of the refusal, or "ok".
std::string verdict(const HttpRequest& r) {
  auto p = check_request_head(r);
  return p ? std::to_string(p->status) + " " + p->field : "ok";
}

}  // namespace

TEST(RequestPolicy, AcceptsAJsonPostWithALength) {
  EXPECT_EQ(verdict(head("POST", {{"Content-Type", "application/json"}, {"Content-Length", "17"}})), "ok");
  EXPECT_EQ(verdict(head("POST", {{"content-type", "Application/JSON; charset=utf-8"}, {"content-length", "2"}})), "ok");
  EXPECT_EQ(verdict(head("GET", {})), "ok");
  EXPECT_EQ(verdict(head("GET", {{"Content-Length", "0"}})), "ok");
}

TEST(RequestPolicy, RefusesBodiesTheLibraryWouldReadWithoutALimit) {
  EXPECT_EQ(verdict(head("POST", {{"Content-Type", "application/json"}, {"Transfer-Encoding", "chunked"}})),
            "411 Transfer-Encoding");
  EXPECT_EQ(verdict(head("POST", {{"Content-Type", "application/json"}, {"Content-Length", "20"},
                                  {"Content-Encoding", "gzip"}})),
            "415 Content-Encoding");
  EXPECT_EQ(verdict(head("POST", {{"Content-Type", "application/json"}})), "411 Content-Length");
  EXPECT_EQ(verdict(head("PUT", {{"Content-Type", "application/json"}})), "411 Content-Length");
}

TEST(RequestPolicy, LimitsTheBodySize) {
  const auto limit = std::to_string(softtune::http::limits::kMaxBodyBytes);
  const auto over = std::to_string(softtune::http::limits::kMaxBodyBytes + 1);
  EXPECT_EQ(verdict(head("POST", {{"Content-Type", "application/json"}, {"Content-Length", limit}})), "ok");
  EXPECT_EQ(verdict(head("POST", {{"Content-Type", "application/json"}, {"Content-Length", over}})), "413 Content-Length");
  EXPECT_EQ(verdict(head("POST", {{"Content-Type", "application/json"}, {"Content-Length", "99999999999999999999999"}})),
            "400 Content-Length");
  EXPECT_EQ(verdict(head("POST", {{"Content-Type", "application/json"}, {"Content-Length", "-1"}})), "400 Content-Length");
  EXPECT_EQ(verdict(head("POST", {{"Content-Type", "application/json"}, {"Content-Length", "12abc"}})), "400 Content-Length");
}

TEST(RequestPolicy, NeedsJsonBodiesAndBodilessGets) {
  EXPECT_EQ(verdict(head("POST", {{"Content-Type", "text/plain"}, {"Content-Length", "2"}})), "415 Content-Type");
  EXPECT_EQ(verdict(head("POST", {{"Content-Length", "2"}})), "415 Content-Type");
  EXPECT_EQ(verdict(head("POST", {{"Content-Type", "application/jsonx"}, {"Content-Length", "2"}})), "415 Content-Type");
  EXPECT_EQ(verdict(head("GET", {{"Content-Length", "5"}})), "400 Content-Length");
}

// RFC 9112 3.2 and 5.1: one well-formed Host (HTTP/1.0 may omit it), and no space before a header's colon.
TEST(RequestPolicy, NeedsOneHostAndTokenHeaderNames) {
  HttpRequest bare;
  bare.method = "GET";
  bare.path = "/api/v1/health";
  ASSERT_TRUE(check_request_head(bare));
  EXPECT_EQ(check_request_head(bare)->field, "Host");
  EXPECT_FALSE(check_request_head(bare, "HTTP/1.0"));
  for (const std::string host : {"example.com", "127.0.0.1:8080", "[::1]:8080", "a-b.c_d~e"}) {
    EXPECT_EQ(verdict(head("GET", {{"Host", host}})), "ok") << host;
  }
  for (const std::string host : {"a b", "a/b", ":80", "a:8x", "[::1", "x@y"}) {
    EXPECT_EQ(verdict(head("GET", {{"Host", host}})), "400 Host") << host;
  }
  EXPECT_EQ(verdict(head("GET", {{"Host", "a"}, {"host", "a"}})), "400 Host");
  EXPECT_EQ(verdict(head("GET", {{"Host ", "x"}})), "400 Host");
  EXPECT_EQ(verdict(head("POST", {{"Transfer-Encoding ", "chunked"}, {"Content-Length", "2"}, {"Content-Type", "application/json"}})),
            "400 Transfer-Encoding");
  EXPECT_EQ(verdict(head("GET", {{"X(y)", "1"}})), "400 X(y)");
}

namespace softtune::http {
namespace {

// POST /api/v1/identify alone also takes a CSV body (identify_routes.h); every other route stays JSON-only.
TEST(RequestPolicy, IdentifyAloneTakesCsv) {
  HttpRequest r;
  r.method = "POST";
  r.path = "/api/v1/identify";
  r.headers.emplace("Host", "t");
  r.headers.emplace("Content-Type", "text/csv; charset=utf-8");
  r.headers.emplace("Content-Length", "10");
  EXPECT_FALSE(check_request_head(r));
  r.path = "/api/v1/tune";
  ASSERT_TRUE(check_request_head(r));
  EXPECT_EQ(check_request_head(r)->status, 415);
}

}  // namespace
}  // namespace softtune::http
