// POST /api/v1/check through the real transport: the JSON report is the use case's answer for the same
// request and conforms to the OpenAPI document, JUnit comes as application/xml, and a request above the work
// budget is refused before any step with a problem naming the fields.
#include <gtest/gtest.h>

#include "app/check_request.h"
#include "openapi_conformance.h"
#include "test_server.h"

using nlohmann::json;
using softtune::http::testing::conformance_error;
using softtune::http::testing::presets_config;
using softtune::http::testing::quick_options;
using softtune::http::testing::TestServer;
using softtune::http::testing::web_config;

namespace {

using softtune::http::testing::kJson;

}  // namespace

TEST(CheckRoutes, TheReportIsTheUseCasesAnswer) {
  TestServer s(quick_options(), presets_config());
  // The chain passes at 60 fps and opens past its 3 cm bound at 30 (its pins stretch as h^2).
  const json request = {{"presets", {"mouse", "chain"}}, {"fps", {30, 60}}};
  auto r = s.client().Post("/api/v1/check", request.dump(), kJson);
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 200) << r->body;
  const json doc = json::parse(r->body);
  EXPECT_EQ(doc, softtune::app::run_check_request(request, softtune::http::testing::kRepositoryPresets).json);
  EXPECT_EQ(conformance_error("/api/v1/check", "post", 200, kJson, doc), "");
  EXPECT_FALSE(doc["passed"].get<bool>());
  ASSERT_EQ(doc["cases"].size(), 4u);
  EXPECT_EQ(doc["cases"][0]["key"], "chain@30x2");
  EXPECT_FALSE(doc["cases"][0]["passed"].get<bool>());
  EXPECT_EQ(doc["cases"][0]["failures"][0].get<std::string>().rfind("max_constraint_error = ", 0), 0u);
  EXPECT_TRUE(doc["cases"][1]["passed"].get<bool>());

  auto x = s.client().Post("/api/v1/check", R"({"presets": ["mouse"], "format": "junit"})", kJson);
  ASSERT_TRUE(x);
  EXPECT_EQ(x->status, 200);
  EXPECT_EQ(x->get_header_value("Content-Type"), "application/xml; charset=utf-8");
  EXPECT_EQ(x->body.rfind("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites", 0), 0u) << x->body;
}

TEST(CheckRoutes, AboveTheBudgetIsRefusedNamingTheFields) {
  TestServer s(quick_options(), presets_config());
  auto r = s.client().Post("/api/v1/check", R"({"fps": [30, 60, 120, 144, 240, 480], "substeps": [1, 4, 8]})", kJson);
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 422) << r->body;
  const json p = json::parse(r->body);
  EXPECT_EQ(p["field"], "presets, scenes, fps, substeps");
  EXPECT_EQ(conformance_error("/api/v1/check", "post", 422, "application/problem+json", p), "");
}
