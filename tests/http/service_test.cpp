#include "http/service.h"

#include <gtest/gtest.h>

#include "codec/problem.h"
#include "http/routes.h"

using nlohmann::json;
using softtune::http::HttpRequest;
using softtune::http::HttpResponse;
using softtune::http::Route;
using softtune::http::Service;

namespace {

HttpRequest request(std::string method, std::string path, std::string body = "") {
  HttpRequest r;
  r.method = std::move(method);
  r.path = std::move(path);
  r.body = std::move(body);
  return r;
}

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
  EXPECT_EQ(r.headers[0].second, "GET, POST");
  EXPECT_EQ(json::parse(s.handle(request("HEAD", "/echo/y")).body)["name"], "y");
}

TEST(Service, RouteLabelsAreThePatterns) {
  Service s = throwing_service();
  EXPECT_EQ(s.route_label("GET", "/echo/abc"), "/echo/{name}");
  EXPECT_EQ(s.route_label("GET", "/nothing"), "unmatched");
}

TEST(Service, TuneRunsTheSharedContract) {
  Service s({}, softtune::http::service_routes());
  // 60 Hz steps, 12 frames per period: f = 60 / 12 = 5 Hz; k = m omega^2 = 2 (10 pi)^2 in standard mode.
  const HttpResponse ok =
      s.handle(request("POST", "/api/v1/tune", R"({"response_frames": 12, "oscillation": "free", "effective_mass": 2})"));
  ASSERT_EQ(ok.status, 200) << ok.body;
  const json doc = json::parse(ok.body);
  EXPECT_NEAR(doc["frequency_hz"].get<double>(), 5.0, 1e-12);
  EXPECT_NEAR(doc["k"].get<double>(), 2.0 * 100.0 * M_PI * M_PI, 1e-9);

  const HttpResponse bad = s.handle(request("POST", "/api/v1/tune", R"({"response_frames": 12, "oscillation": "free"})"));
  EXPECT_EQ(bad.status, 422);
  EXPECT_EQ(json::parse(bad.body)["field"], "effective_mass");
  EXPECT_EQ(s.handle(request("POST", "/api/v1/tune", R"({"fps": 60,)")).status, 400);
  EXPECT_EQ(s.handle(request("POST", "/api/v1/tune", R"({"fps": 60, "fps": 30})")).status, 400);
}
