// POST /api/v1/stability with a `preset`: the per-joint table conforms to openapi.json, is what the CLI's
// app function answers for the same preset, and its refusals are problems naming the field.
#include <gtest/gtest.h>

#include "app/stability_app.h"
#include "codec/stability_codec.h"
#include "openapi_conformance.h"
#include "test_server.h"

using nlohmann::json;
using softtune::http::testing::conformance_error;
using softtune::http::testing::presets_config;
using softtune::http::testing::quick_options;
using softtune::http::testing::TestServer;

namespace {

using softtune::http::testing::kJson;

TEST(PresetStabilityRoute, GroundJointAnswersNoLimitAndConforms) {
  TestServer s(quick_options(), presets_config());
  auto client = s.client();
  client.set_read_timeout(60, 0);
  auto r = client.Post("/api/v1/stability", R"({"preset": "stiff"})", kJson);
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 200) << r->body;
  const json doc = json::parse(r->body);
  EXPECT_EQ(conformance_error("/api/v1/stability", "post", 200, kJson, doc), "");
  const json& row = doc.at("preset_limits").at("limits").at(0);
  EXPECT_EQ(row.at("kind"), "none_in_range");
  const json cli = softtune::app::run_stability(softtune::codec::decode_stability_request({{"preset", "stiff"}}),
                                                presets_config().presets_dir);
  EXPECT_EQ(doc.at("preset_limits"), cli.at("preset_limits"));

  auto mixed = client.Post("/api/v1/stability", R"({"preset": "stiff", "chain": false})", kJson);
  ASSERT_TRUE(mixed);
  EXPECT_EQ(mixed->status, 422);
  EXPECT_EQ(json::parse(mixed->body).at("field"), "chain");
  auto svg = client.Post("/api/v1/stability?format=svg", R"({"preset": "stiff"})", kJson);
  ASSERT_TRUE(svg);
  EXPECT_EQ(svg->status, 422);
  EXPECT_EQ(json::parse(svg->body).at("field"), "format");
}

}  // namespace
