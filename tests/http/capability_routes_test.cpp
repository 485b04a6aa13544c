// The capabilities shared with the CLI, through the real transport: simulate, presets, accuracy and
// stability answer what the CLI's codec functions answer for the same request, conform to the OpenAPI
// document, refuse bad input with a problem naming the field, and serve SVG/CSV with their content types.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "box2d_spring.h"
#include "app/accuracy_app.h"
#include "app/stability_app.h"
#include "codec/accuracy_codec.h"
#include "app/modes_app.h"
#include "app/simulate_app.h"
#include "codec/scene_codec.h"
#include "codec/stability_codec.h"
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
const char* kProblem = "application/problem+json";

using softtune::http::testing::media_type;

// A small accuracy request: 2 Hz, zeta 0.1, one step rate, one timing repeat (a few ms of work).
const char* kSmallAccuracy = R"({"frequency_hz": 2, "damping_ratio": 0.1, "effective_mass": 1, "fps": 60,
                                 "step_rates": [60], "timing_repeats": 1})";
// A small custom sweep: 2 methods x 3 ratios x 2 damping ratios x the default masses and steps, no chain.
const char* kSmallSweep = R"({"methods": ["soft", "explicit_euler"], "frequency_ratios": [0.01, 0.1, 1],
                              "damping_ratios": [0, 1], "masses": [1], "steps": [0.01], "chain": false})";

// The report without what depends on the clock: CPU times, and the recommendation picked by them.
json without_timing(json report) {
  for (json& row : report["rows"]) row.erase("cpu_seconds_per_sim_second");
  report.erase("recommendation");
  return report;
}

// Expects a 422 problem naming `field`, conforming to the document's problem schema.
void expect_problem(const httplib::Result& r, int status, const std::string& field, const std::string& path,
                    const std::string& method) {
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, status) << r->body;
  EXPECT_EQ(media_type(r), kProblem);
  const json p = json::parse(r->body);
  EXPECT_EQ(p["field"], field) << r->body;
  EXPECT_EQ(conformance_error(path, method, status, kProblem, p), "") << r->body;
}

}  // namespace

TEST(CapabilityRoutes, SimulateBuddhasIsTheCliAnswer) {
  TestServer s(quick_options(), presets_config());
  const json request = {{"preset", "buddhas"}};
  auto r = s.client().Post("/api/v1/simulate", request.dump(), kJson);
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 200) << r->body;
  EXPECT_EQ(media_type(r), kJson);
  const json doc = json::parse(r->body);
  EXPECT_EQ(doc, softtune::app::run_simulate(request, softtune::http::testing::kRepositoryPresets));
  EXPECT_EQ(doc["name"], "buddhas");
  EXPECT_TRUE(doc["finite"].get<bool>());
  EXPECT_EQ(conformance_error("/api/v1/simulate", "post", 200, kJson, doc), "");
}

TEST(CapabilityRoutes, SimulateFramesConformAndBadOptionsNameTheField) {
  TestServer s(quick_options(), presets_config());
  auto r = s.client().Post("/api/v1/simulate", R"({"preset": "buddhas", "frames": true, "frame_stride": 50})", kJson);
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 200) << r->body;
  const json doc = json::parse(r->body);
  ASSERT_TRUE(doc.contains("snapshots"));
  // One snapshot per 50 frames (the first included).
  EXPECT_EQ(doc["snapshots"].size(), static_cast<std::size_t>((doc["frames"].get<int>() + 49) / 50));
  EXPECT_EQ(conformance_error("/api/v1/simulate", "post", 200, kJson, doc), "");

  expect_problem(s.client().Post("/api/v1/simulate", R"({"preset": "buddhas", "frame_stride": 0})", kJson), 422,
                 "frame_stride", "/api/v1/simulate", "post");
  expect_problem(s.client().Post("/api/v1/simulate", R"({"preset": "no_such_preset"})", kJson), 404, "preset",
                 "/api/v1/simulate", "post");
}

TEST(CapabilityRoutes, ModesAreTheCliAnswerAndBadOptionsNameTheField) {
  TestServer s(quick_options(), presets_config());
  const json request = {{"preset", "vehicle_per_spring"}};
  auto r = s.client().Post("/api/v1/modes", request.dump(), kJson);
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 200) << r->body;
  const json doc = json::parse(r->body);
  EXPECT_EQ(doc, softtune::app::run_modes(request, softtune::http::testing::kRepositoryPresets));
  EXPECT_EQ(conformance_error("/api/v1/modes", "post", 200, kJson, doc), "");
  expect_problem(s.client().Post("/api/v1/modes", R"({"preset": "vehicle", "at_s": -1})", kJson), 422, "at_s",
                 "/api/v1/modes", "post");
  expect_problem(s.client().Post("/api/v1/modes", R"({"preset": "oscillator"})", kJson), 422, "bodies",
                 "/api/v1/modes", "post");
}

// `engine` on the scene routes (issue 32): the default engine named answers what the app answers and says
// which engine ran; an unknown engine or setting is a 422 naming it; the engines index conforms.
TEST(CapabilityRoutes, SceneRoutesTakeTheEngineAndRefuseUnknownOnes) {
  TestServer s(quick_options(), presets_config());
  const json request = {{"preset", "buddhas"}, {"engine", "box2d_v2_4"}};
  auto r = s.client().Post("/api/v1/simulate", request.dump(), kJson);
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 200) << r->body;
  const json doc = json::parse(r->body);
  EXPECT_EQ(doc, softtune::app::run_simulate(request, softtune::http::testing::kRepositoryPresets));
  EXPECT_EQ(doc["engine"]["name"], "box2d_v2_4");
  EXPECT_EQ(conformance_error("/api/v1/simulate", "post", 200, kJson, doc), "");
  expect_problem(s.client().Post("/api/v1/simulate", R"({"preset": "buddhas", "engine": "havok"})", kJson), 422, "engine",
                 "/api/v1/simulate", "post");
  expect_problem(s.client().Post("/api/v1/simulate", R"({"preset": "buddhas", "engine_settings": {"noSuchSetting": 1}})", kJson),
                 422, "engine_settings.noSuchSetting", "/api/v1/simulate", "post");
  expect_problem(s.client().Post("/api/v1/modes", R"({"preset": "vehicle", "engine": "havok"})", kJson), 422, "engine",
                 "/api/v1/modes", "post");
  expect_problem(s.client().Post("/api/v1/check", R"({"presets": ["mouse"], "engine": "havok"})", kJson), 422, "engine",
                 "/api/v1/check", "post");
  expect_problem(s.client().Post("/api/v1/preview", R"({"preset": "mouse", "frames": 4, "engine": "havok"})", kJson), 422,
                 "engine", "/api/v1/preview", "post");

  auto engines = s.client().Get("/api/v1/scene-engines");
  ASSERT_TRUE(engines);
  ASSERT_EQ(engines->status, 200) << engines->body;
  const json index = json::parse(engines->body);
  EXPECT_EQ(index, softtune::app::scene_engines_index());
  EXPECT_EQ(index["engines"][0]["name"], "box2d_v2_4");
  EXPECT_EQ(conformance_error("/api/v1/scene-engines", "get", 200, kJson, index), "");
}

TEST(CapabilityRoutes, PresetsListAndOnePreset) {
  TestServer s(quick_options(), presets_config());
  auto list = s.client().Get("/api/v1/presets");
  ASSERT_TRUE(list);
  ASSERT_EQ(list->status, 200) << list->body;
  const json index = json::parse(list->body);
  EXPECT_EQ(index, softtune::app::presets_index(softtune::http::testing::kRepositoryPresets));
  EXPECT_EQ(conformance_error("/api/v1/presets", "get", 200, kJson, index), "");
  std::vector<std::string> names;
  for (const json& p : index["presets"]) names.push_back(p["name"]);
  EXPECT_NE(std::find(names.begin(), names.end(), "buddhas"), names.end());
  EXPECT_EQ(std::find(names.begin(), names.end(), "schema"), names.end());

  auto one = s.client().Get("/api/v1/presets/buddhas");
  ASSERT_TRUE(one);
  ASSERT_EQ(one->status, 200) << one->body;
  std::ifstream file(softtune::http::testing::kRepositoryPresets + "/buddhas.json");
  EXPECT_EQ(json::parse(one->body), json::parse(file));
  EXPECT_EQ(conformance_error("/api/v1/presets/{name}", "get", 200, kJson, json::parse(one->body)), "");
}

TEST(CapabilityRoutes, UnknownAndTrickyPresetNamesAreRefused) {
  TestServer s(quick_options(), presets_config());
  expect_problem(s.client().Get("/api/v1/presets/no_such_preset"), 404, "name", "/api/v1/presets/{name}", "get");
  expect_problem(s.client().Get("/api/v1/presets/Buddhas"), 422, "name", "/api/v1/presets/{name}", "get");
  expect_problem(s.client().Get("/api/v1/presets/schema"), 422, "name", "/api/v1/presets/{name}", "get");
  // ..%2f decodes to "../": not one segment, so no preset route; the static page refuses the dot segment.
  softtune::http::testing::RawConnection raw(s.port());
  ASSERT_TRUE(raw.connected());
  raw.send("GET /api/v1/presets/..%2fetc HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n");
  const std::string answer = raw.receive();
  EXPECT_EQ(softtune::http::testing::status_of(answer), 400) << answer;
  EXPECT_NE(answer.find(kProblem), std::string::npos) << answer;
}

TEST(CapabilityRoutes, AccuracyIsTheCliReportWithTheBox2DRow) {
  TestServer s;
  auto r = s.client().Post("/api/v1/accuracy", kSmallAccuracy, kJson);
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 200) << r->body;
  EXPECT_EQ(media_type(r), kJson);
  const json doc = json::parse(r->body);
  EXPECT_EQ(conformance_error("/api/v1/accuracy", "post", 200, kJson, doc), "");
  const std::optional<softtune::EngineRunner> box2d = softtune::EngineRunner{softtune::kBox2DRowName, softtune::run_box2d_spring};
  EXPECT_EQ(without_timing(doc), without_timing(softtune::app::run_accuracy(json::parse(kSmallAccuracy), box2d)));
  bool box2d_row = false;
  for (const json& row : doc["rows"]) {
    box2d_row = box2d_row || row["method"] == softtune::kBox2DRowName;
    // Exact softness places the discrete poles on the asked ones (docs/math.md): 2 Hz at any step.
    if (row["method"] == "soft_exact") {
      EXPECT_NEAR(row["achieved_frequency_hz"]["poles"].get<double>(), 2.0, 1e-9);
    }
  }
  EXPECT_TRUE(box2d_row);
  EXPECT_EQ(s.service().metrics().prometheus_text().find("cache=\"accuracy\""), std::string::npos)
      << "accuracy answers carry CPU times and must not be cached";
}

TEST(CapabilityRoutes, AccuracyCsvSvgAndErrors) {
  TestServer s;
  auto csv = s.client().Post("/api/v1/accuracy?format=csv", kSmallAccuracy, kJson);
  ASSERT_TRUE(csv);
  ASSERT_EQ(csv->status, 200) << csv->body;
  EXPECT_EQ(media_type(csv), "text/csv");
  // A header line and one line per row: 11 methods x substeps at 60 fps plus Box2D's.
  const json rows = softtune::app::run_accuracy(json::parse(kSmallAccuracy),
                                                  softtune::EngineRunner{softtune::kBox2DRowName, softtune::run_box2d_spring})["rows"];
  EXPECT_EQ(static_cast<std::size_t>(std::count(csv->body.begin(), csv->body.end(), '\n')), rows.size() + 1);

  auto svg = s.client().Post("/api/v1/accuracy?format=svg", kSmallAccuracy, kJson);
  ASSERT_TRUE(svg);
  ASSERT_EQ(svg->status, 200) << svg->body;
  EXPECT_EQ(media_type(svg), "image/svg+xml");
  EXPECT_NE(svg->body.find("<svg"), std::string::npos);

  expect_problem(s.client().Post("/api/v1/accuracy?format=png", kSmallAccuracy, kJson), 422, "format", "/api/v1/accuracy", "post");
  expect_problem(s.client().Post("/api/v1/accuracy", R"({"frequency_hz": 2, "oscillation": "some", "effective_mass": 1,
                                                        "error_budget": 0})", kJson),
                 422, "error_budget", "/api/v1/accuracy", "post");
}

TEST(CapabilityRoutes, StabilityDefaultSweepIsKeptAndPasses) {
  TestServer s;
  auto client = s.client();
  client.set_read_timeout(600, 0);  // the first answer runs the sweep: long under the sanitizers
  const auto first_started = std::chrono::steady_clock::now();
  auto first = client.Get("/api/v1/stability");
  const auto first_took = std::chrono::steady_clock::now() - first_started;
  ASSERT_TRUE(first);
  ASSERT_EQ(first->status, 200);
  EXPECT_EQ(media_type(first), kJson);
  const json doc = json::parse(first->body);
  EXPECT_EQ(conformance_error("/api/v1/stability", "get", 200, kJson, doc), "");
  EXPECT_TRUE(doc["summary"]["passed"].get<bool>());
  EXPECT_GE(doc["summary"]["cases"].get<int>(), 10000);
  EXPECT_EQ(doc["cases"].size(), doc["summary"]["cases"].get<std::size_t>());

  // The second answer is the kept one: the same bytes, without running the sweep again (so in a small
  // part of the first one's time, however slow this build or machine is).
  const auto started = std::chrono::steady_clock::now();
  auto second = client.Get("/api/v1/stability");
  ASSERT_TRUE(second);
  EXPECT_EQ(second->body, first->body);
  auto svg = client.Get("/api/v1/stability?format=svg");
  ASSERT_TRUE(svg);
  ASSERT_EQ(svg->status, 200);
  EXPECT_EQ(media_type(svg), "image/svg+xml");
  EXPECT_NE(svg->body.find("<svg"), std::string::npos);
  EXPECT_EQ(svg->body, softtune::app::stability_svg(doc));
  EXPECT_LT(std::chrono::steady_clock::now() - started, first_took / 4);

  expect_problem(s.client().Get("/api/v1/stability?format=csv"), 422, "format", "/api/v1/stability", "get");
}

TEST(CapabilityRoutes, StabilityCustomSweepIsTheCliAnswer) {
  TestServer s;
  auto r = s.client().Post("/api/v1/stability", kSmallSweep, kJson);
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 200) << r->body;
  const json doc = json::parse(r->body);
  EXPECT_EQ(doc, softtune::app::run_stability(json::parse(kSmallSweep)));
  EXPECT_EQ(conformance_error("/api/v1/stability", "post", 200, kJson, doc), "");
  // Soft constraints are implicit Euler: stable at every ratio; explicit Euler grows undamped (zeta 0).
  for (const json& c : doc["cases"]) {
    if (c["method"] == "soft") {
      EXPECT_TRUE(c["observed_stable"].get<bool>()) << c.dump();
    }
    if (c["method"] == "explicit_euler" && c["damping_ratio"] == 0.0) {
      EXPECT_FALSE(c["observed_stable"].get<bool>()) << c.dump();
    }
  }

  auto svg = s.client().Post("/api/v1/stability?format=svg", kSmallSweep, kJson);
  ASSERT_TRUE(svg);
  ASSERT_EQ(svg->status, 200);
  EXPECT_EQ(media_type(svg), "image/svg+xml");

  expect_problem(s.client().Post("/api/v1/stability", R"({"observe_steps": 5})", kJson), 422, "observe_steps",
                 "/api/v1/stability", "post");
}
