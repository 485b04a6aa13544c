// The service's routes (routes.cpp): POST /api/v1/tune answers the shared tune contract, with the Problems
// of the codec (422 naming the field, 400 for malformed or duplicated JSON).
#include "http/routes.h"

#include <gtest/gtest.h>

#include <cmath>

#include "handler_requests.h"
#include "http/service.h"

using nlohmann::json;
using softtune::http::HttpResponse;
using softtune::http::Service;
using softtune::http::test::request;

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
