#include "http/cors.h"

#include <gtest/gtest.h>

using namespace softtune::http;

namespace {

std::string header(const HttpResponse& r, const std::string& name) {
  for (const auto& [k, v] : r.headers) {
    if (k == name) return v;
  }
  return "";
}

HttpRequest preflight_request(std::string origin, std::string method, std::string headers = "") {
  HttpRequest r;
  r.method = "OPTIONS";
  r.path = "/api/v1/tune";
  r.headers.emplace("Origin", std::move(origin));
  r.headers.emplace("Access-Control-Request-Method", std::move(method));
  if (!headers.empty()) r.headers.emplace("Access-Control-Request-Headers", std::move(headers));
  return r;
}

}  // namespace

TEST(Cors, OffByDefaultAndOnlyForListedOrigins) {
  HttpResponse r;
  add_cors_headers(CorsPolicy{}, std::string("https://a.example"), r);
  EXPECT_TRUE(r.headers.empty());
  const CorsPolicy one{{"https://a.example"}};
  add_cors_headers(one, std::string("https://b.example"), r);
  EXPECT_TRUE(r.headers.empty());
  add_cors_headers(one, std::string("https://a.example"), r);
  EXPECT_EQ(header(r, "Access-Control-Allow-Origin"), "https://a.example");
  EXPECT_EQ(header(r, "Vary"), "Origin");
  HttpResponse any;
  add_cors_headers(CorsPolicy{{"*"}}, std::string("https://z.example"), any);
  EXPECT_EQ(header(any, "Access-Control-Allow-Origin"), "*");
}

TEST(Cors, PreflightListsThePathsMethodsAndRefusesOthers) {
  const CorsPolicy policy{{"https://a.example"}};
  ASSERT_TRUE(is_preflight(preflight_request("https://a.example", "POST")));
  const HttpResponse ok = preflight_response(policy, preflight_request("https://a.example", "POST", "content-type"), "POST");
  EXPECT_EQ(ok.status, 204);
  EXPECT_EQ(header(ok, "Access-Control-Allow-Methods"), "POST, OPTIONS");
  EXPECT_EQ(header(ok, "Access-Control-Allow-Headers"), kCorsAllowedHeaders);
  for (const HttpRequest& bad : {preflight_request("https://a.example", "DELETE"),
                                 preflight_request("https://a.example", "POST", "X-Secret"),
                                 preflight_request("https://evil.example", "POST")}) {
    const HttpResponse r = preflight_response(policy, bad, "POST");
    EXPECT_EQ(r.status, 204);
    EXPECT_EQ(header(r, "Access-Control-Allow-Methods"), "");
  }
}
