// The refusal writer without sockets: what each answer written before a handler runs says. The live
// transport's refusals (a real 431, 408, 503 on the wire) are in hardening_test.cpp.
#include "http/transport_refusals.h"

#include <gtest/gtest.h>

#include "http/limits.h"

namespace softtune::http {
namespace {

nlohmann::json body(const HttpResponse& r) { return nlohmann::json::parse(r.body); }

TEST(TransportRefusals, AHeadThePolicyRefusesIsAnsweredBeforeItsBody) {
  httplib::Request chunked;
  chunked.method = "POST";
  chunked.path = "/api/v1/tune";
  chunked.headers.emplace("Host", "t");
  chunked.headers.emplace("Transfer-Encoding", "chunked");
  const auto refusal = head_refusal(chunked);
  ASSERT_TRUE(refusal);
  EXPECT_EQ(refusal->status, 411);
  EXPECT_EQ(refusal->content_type, "application/problem+json");
  EXPECT_EQ(body(*refusal)["status"], 411);

  httplib::Request fine;
  fine.method = "GET";
  fine.path = "/api/v1/health";
  fine.headers.emplace("Host", "t");
  EXPECT_FALSE(head_refusal(fine));
}

TEST(TransportRefusals, ALongUnfinishedHeadIs431AndAMalformedOne400) {
  ConnectionState long_line;
  long_line.head_bytes = limits::kMaxHeaderLineBytes + 1;  // the library's bare 400 for its line limit
  EXPECT_EQ(library_refusal(400, "GET", &long_line).status, 431);
  EXPECT_EQ(body(library_refusal(400, "GET", &long_line))["field"], "headers");

  ConnectionState overflow;
  overflow.head_overflow = true;
  EXPECT_EQ(library_refusal(400, "GET", &overflow).status, 431);

  ConnectionState short_head;
  short_head.head_bytes = 100;
  EXPECT_EQ(library_refusal(400, "GET", &short_head).status, 400);
  ConnectionState body_read = long_line;
  body_read.head_done = true;  // past the head: a 400 is the library's own
  EXPECT_EQ(library_refusal(400, "GET", &body_read).status, 400);
  EXPECT_EQ(library_refusal(400, "GET", nullptr).status, 400);
}

TEST(TransportRefusals, TheLibrarysOwnStatusesKeepTheirStatusAndNameTheirField) {
  EXPECT_EQ(body(library_refusal(414, "GET", nullptr))["field"], "path");
  EXPECT_EQ(body(library_refusal(413, "GET", nullptr))["field"], "Content-Length");
  EXPECT_EQ(library_refusal(404, "GET", nullptr).status, 404);
  EXPECT_EQ(library_refusal(418, "GET", nullptr).status, 418);
  EXPECT_EQ(internal_error_refusal().status, 500);
  EXPECT_EQ(internal_error_refusal().content_type, "application/problem+json");
}

TEST(TransportRefusals, TheGatesAnswersAreWholeResponsesThatClose) {
  TransportOptions options;
  const GateRefusal busy = gate_refusal(Refusal::busy, "POST /api/v1/tune HTTP/1.1\r\nHost: x\r\n", options);
  EXPECT_EQ(busy.status, 503);
  EXPECT_EQ(busy.method, "POST");
  EXPECT_EQ(busy.path, "/api/v1/tune");
  EXPECT_EQ(busy.response.rfind("HTTP/1.1 503 Service Unavailable\r\n", 0), 0u) << busy.response;
  EXPECT_NE(busy.response.find("\r\nRetry-After: 1\r\n"), std::string::npos);
  EXPECT_NE(busy.response.find("\r\nConnection: close\r\n"), std::string::npos);
  const std::string json = busy.response.substr(busy.response.find("\r\n\r\n") + 4);
  EXPECT_NE(busy.response.find("Content-Length: " + std::to_string(json.size()) + "\r\n"), std::string::npos);
  EXPECT_EQ(nlohmann::json::parse(json)["status"], 503);

  const GateRefusal late = gate_refusal(Refusal::timeout, "GET /slo", options);  // a head cut short
  EXPECT_EQ(late.status, 408);
  EXPECT_EQ(late.method, "GET");
  EXPECT_EQ(late.path, "/slo");
  EXPECT_EQ(late.response.rfind("HTTP/1.1 408 Request Timeout\r\n", 0), 0u);
  EXPECT_EQ(late.response.find("Retry-After"), std::string::npos);
  EXPECT_EQ(gate_refusal(Refusal::timeout, "", options).method, "");
}

// With --cors-origin, the gate's own answers carry the CORS headers too (cors.h: every answer does), for
// the Origin of the head received so far; without an Origin, or with CORS off, they carry none.
TEST(TransportRefusals, TheGatesAnswersCarryCorsHeaders) {
  TransportOptions options;
  CorsPolicy cors;
  cors.origins = {"https://tools.example"};
  const std::string head = "POST /api/v1/tune HTTP/1.1\r\nHost: x\r\norigin:  https://tools.example \r\n";
  for (Refusal why : {Refusal::busy, Refusal::timeout}) {
    const std::string r = gate_refusal(why, head, options, cors).response;
    EXPECT_NE(r.find("\r\nAccess-Control-Allow-Origin: https://tools.example\r\n"), std::string::npos) << r;
    EXPECT_NE(r.find("\r\nVary: Origin\r\n"), std::string::npos) << r;
    EXPECT_EQ(gate_refusal(why, head, options).response.find("Access-Control"), std::string::npos);
    EXPECT_EQ(gate_refusal(why, "GET / HTTP/1.1\r\nOrigin: https://evil.example\r\n", options, cors).response.find("Access-Control"),
              std::string::npos);
  }
  EXPECT_EQ(raw_header("GET / HTTP/1.1\r\nOrigin: a\r\nOrig", "Origin"), "a");
  EXPECT_FALSE(raw_header("GET / HTTP/1.1\r\nOrigin: a", "Origin"));  // a line cut short does not count
  EXPECT_FALSE(raw_header("GET / HTTP/1.1\r\n\r\nOrigin: a\r\n", "Origin"));  // the body is not the head
}


// RFC 9110 15.6.2: a method the server does not implement for any resource is 501, not a malformed
// request; methods are case-sensitive, so a lower-case "get" is such a method too.
TEST(TransportRefusals, UnknownMethodsAre501) {
  for (const char* method : {"TRACE", "CONNECT", "get", "FOO", "M-SEARCH"}) {
    const HttpResponse r = library_refusal(400, method, nullptr);
    EXPECT_EQ(r.status, 501) << method;
    EXPECT_EQ(body(r)["field"], "method") << method;
  }
  EXPECT_EQ(library_refusal(400, "GET", nullptr).status, 400);          // a served method: malformed elsewhere
  EXPECT_EQ(library_refusal(400, "G\x01T", nullptr).status, 400);       // not a token
  EXPECT_EQ(library_refusal(400, "", nullptr).status, 400);
}

}  // namespace
}  // namespace softtune::http
