// POST /api/v1/identify without sockets: a text/csv body with the query, a JSON body, and a query on a
// JSON body (refused, naming the parameter).
#include "http/identify_routes.h"

#include <gtest/gtest.h>

#include "codec/problem.h"
#include "http/routes.h"

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

}  // namespace
}  // namespace softtune::http
