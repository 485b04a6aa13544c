// POST /api/v1/identify without sockets: a text/csv body with the query, a JSON body, and a query on a
// JSON body (refused, naming the parameter).
#include "http/identify_routes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "codec/problem.h"
#include "http/routes.h"
#include "openapi_conformance.h"

namespace softtune::http {
namespace {

HttpRequest post(std::string type, std::string body) {
  HttpRequest r;
  r.method = "POST";
  r.path = std::string(kIdentifyPath);
  r.headers.emplace("Content-Type", std::move(type));
  r.body = std::move(body);
  return r;
}

TEST(IdentifyRoutes, CsvMediaType) {
  EXPECT_TRUE(is_csv_media_type("text/csv"));
  EXPECT_TRUE(is_csv_media_type("Text/CSV; charset=utf-8"));
  EXPECT_FALSE(is_csv_media_type("text/csvx"));
  EXPECT_FALSE(is_csv_media_type("application/json"));
}

TEST(IdentifyRoutes, CsvAndJsonBodies) {
  Service service({}, service_routes());
  HttpRequest csv = post("text/csv", "t,x\n0,1\n0.1,0.5\n0.2,0.2\n");
  csv.query.emplace("engine", "godot");
  const HttpResponse a = identify(csv, service);
  EXPECT_EQ(a.status, 200);
  EXPECT_EQ(nlohmann::json::parse(a.body)["engine"], "godot");
  const HttpResponse b = identify(post("application/json", R"({"time_s": [0, 0.1, 0.2], "probes": {"x": [1, 0.5, 0.2]}})"), service);
  EXPECT_EQ(nlohmann::json::parse(b.body)["samples"], 3);
  HttpRequest mixed = post("application/json", "{}");
  mixed.query.emplace("engine", "godot");
  try {
    identify(mixed, service);
    FAIL() << "expected a Problem";
  } catch (const codec::Problem& p) {
    EXPECT_EQ(p.status, 422);
    EXPECT_EQ(p.field, "engine");
  }
}

// Through the service's route table, as a client calls it: the CSV's query (the page's drop sends its tune
// request and engine this way) reaches the codec, an unknown parameter is named by it, and a query beside a
// JSON body is refused. The table once declared no query parameters, so every CSV with a query got a 422.
TEST(IdentifyRoutes, TheServiceLetsTheCsvQueryThrough) {
  Service service({}, service_routes());
  HttpRequest csv = post("text/csv", "t,x\n0,1\n0.1,0.5\n0.2,0.2\n0.3,0.1\n");
  csv.query.emplace("engine", "godot");
  csv.query.emplace("response_frames", "12");
  csv.query.emplace("basis_fps", "60");
  csv.query.emplace("oscillation", "some");
  csv.query.emplace("effective_mass", "1");
  const HttpResponse ok = service.handle(csv);
  ASSERT_EQ(ok.status, 200) << ok.body;
  const nlohmann::json answer = nlohmann::json::parse(ok.body);
  EXPECT_EQ(answer["engine"], "godot");
  EXPECT_TRUE(answer.contains("correction")) << "the query's request reached the answer";
  HttpRequest unknown = csv;
  unknown.query.emplace("colour", "red");
  const HttpResponse bad = service.handle(unknown);
  EXPECT_EQ(bad.status, 422);
  EXPECT_NE(nlohmann::json::parse(bad.body)["field"].get<std::string>().find("colour"), std::string::npos) << bad.body;
  HttpRequest mixed = post("application/json", "{}");
  mixed.query.emplace("engine", "godot");
  const HttpResponse refused = service.handle(mixed);
  EXPECT_EQ(refused.status, 422);
  EXPECT_EQ(nlohmann::json::parse(refused.body)["field"], "engine");
}

// A correction's answer (typed with no damping, so next is a negative ratio, and an earlier round) conforms
// to the documented 200, with the correction's verdict and its fields.
TEST(IdentifyRoutes, CorrectionAnswerConformsToTheDocument) {
  Service service({}, service_routes());
  std::string csv = "t,x\n";
  for (int n = 0; n < 240; ++n) {
    const double t = n / 60.0, w = 2.0 * 3.141592653589793 * 4.3, zeta = 0.61;
    char row[64];
    std::snprintf(row, sizeof row, "%.6f,%.9f\n", t, 0.01 * std::exp(-zeta * w * t) * std::cos(w * std::sqrt(1 - zeta * zeta) * t));
    csv += row;
  }
  nlohmann::json doc = {{"csv", csv},
                        {"request", {{"frequency_hz", 5}, {"damping_ratio", 0.2}, {"effective_mass", 2}}},
                        {"typed", {{"frequency_hz", 5.2}, {"damping_ratio", 0.01}}},
                        {"previous", nlohmann::json::array({{{"measured", {{"frequency_hz", 4.2}, {"damping_ratio", 0.63}}},
                                                             {"typed", {{"frequency_hz", 5}, {"damping_ratio", 0.2}}}}})}};
  const HttpResponse r = identify(post("application/json", doc.dump()), service);
  ASSERT_EQ(r.status, 200);
  const nlohmann::json answer = nlohmann::json::parse(r.body);
  EXPECT_EQ(testing::conformance_error(std::string(kIdentifyPath), "post", 200, "application/json", answer), "");
  EXPECT_EQ(answer["correction"]["method"], "secant");
  EXPECT_TRUE(answer["correction"]["verdict"].is_string());
  EXPECT_LT(answer["correction"]["next"]["damping_ratio"].get<double>(), 0.0);
}

}  // namespace
}  // namespace softtune::http
