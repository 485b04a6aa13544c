#include "http/service.h"

#include <gtest/gtest.h>

#include "codec/problem.h"
#include "handler_requests.h"

using nlohmann::json;
using softtune::http::HttpRequest;
using softtune::http::HttpResponse;
using softtune::http::Route;
using softtune::http::Service;

namespace {

using softtune::http::test::request;

Service throwing_service() {
  std::vector<Route> routes = {
      {"GET", "/problem", [](const HttpRequest&, Service&) -> HttpResponse {
         throw softtune::codec::invalid_field("a.b", "must be positive");
       }},
      {"GET", "/std", [](const HttpRequest&, Service&) -> HttpResponse { throw std::runtime_error("boom"); }},
      {"GET", "/int", [](const HttpRequest&, Service&) -> HttpResponse { throw 42; }},
      {"GET", "/echo/{name}", [](const HttpRequest& r, Service&) { return softtune::http::json_response(r.params); }},
      {"POST", "/echo/{name}", [](const HttpRequest& r, Service&) { return softtune::http::json_response(r.params); }},
  };
  return Service({}, std::move(routes));
}

}  // namespace

TEST(Service, OneWrapperMapsEveryExceptionToAProblem) {
  Service s = throwing_service();
  const HttpResponse p = s.handle(request("GET", "/problem"));
  EXPECT_EQ(p.status, 422);
  EXPECT_EQ(p.content_type, "application/problem+json");
  EXPECT_EQ(json::parse(p.body)["field"], "a.b");
  EXPECT_EQ(json::parse(p.body)["detail"], "must be positive");
  for (const char* path : {"/std", "/int"}) {
    const HttpResponse r = s.handle(request("GET", path));
    EXPECT_EQ(r.status, 500) << path;
    EXPECT_EQ(json::parse(r.body)["status"], 500) << path;
  }
}

TEST(Service, NoRouteIs404AndAWrongMethodIs405) {
  Service s = throwing_service();
  EXPECT_EQ(s.handle(request("GET", "/nothing")).status, 404);
  const HttpResponse r = s.handle(request("DELETE", "/echo/x"));
  EXPECT_EQ(r.status, 405);
  ASSERT_EQ(r.headers.size(), 1u);
  EXPECT_EQ(r.headers[0].first, "Allow");
  EXPECT_EQ(r.headers[0].second, "GET, POST, HEAD, OPTIONS");
  EXPECT_EQ(json::parse(s.handle(request("HEAD", "/echo/y")).body)["name"], "y");
}

TEST(Service, RouteLabelsAreThePatterns) {
  Service s = throwing_service();
  EXPECT_EQ(s.route_label("GET", "/echo/abc"), "/echo/{name}");
  EXPECT_EQ(s.route_label("GET", "/nothing"), "unmatched");
}
