// The OpenAPI document itself: the embedded bytes are the file's, every route is documented and every
// documented path is served, the limits are those of the server and the codecs, every $ref resolves, and
// the schemas agree with the codecs on real requests and responses.
#include <gtest/gtest.h>

#include <fstream>
#include <functional>
#include <iterator>
#include <map>
#include <sstream>

#include "app/budgets.h"
#include "app/job_runner.h"
#include "app/accuracy_app.h"
#include "app/modes_app.h"
#include "app/simulate_app.h"
#include "app/check_cost.h"
#include "app/check_request.h"
#include "app/verify_app.h"
#include "app/identify_app.h"
#include "codec/identify_codec.h"
#include "softtune/identify.h"
#include "app/stability_app.h"
#include "codec/accuracy_codec.h"
#include "codec/problem.h"
#include "app/simulate_app.h"
#include "codec/scene_codec.h"
#include "codec/stability_codec.h"
#include "app/tune_app.h"
#include "codec/tune_codec.h"
#include "http/limits.h"
#include "http/limits_registry.h"
#include "http/routes.h"
#include "openapi_conformance.h"
#include "softtune/accuracy.h"
#include "softtune/designer.h"
#include "softtune/render/frame_pipeline.h"
#include "softtune/scene/limits.h"

using nlohmann::json;
using softtune::http::testing::conformance_error;
using softtune::http::testing::openapi_document;

namespace {

std::string openapi_key(std::string pattern) {
  const std::size_t rest = pattern.find("...}");
  if (rest != std::string::npos) pattern.erase(rest, 3);
  return pattern;
}

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

void collect_refs(const json& node, std::vector<std::string>& out) {
  if (node.is_object()) {
    for (auto it = node.begin(); it != node.end(); ++it) {
      if (it.key() == "$ref" && it->is_string()) out.push_back(*it);
      else collect_refs(*it, out);
    }
  } else if (node.is_array()) {
    for (const auto& e : node) collect_refs(e, out);
  }
}

const json& tune_request_schema() { return openapi_document()["components"]["schemas"]["TuneRequest"]; }

std::string request_error(const json& request) {
  auto e = softtune::codec::validate_json_schema(request, tune_request_schema(), openapi_document());
  return e ? e->pointer + " " + e->rule : "";
}

}  // namespace

// The served document is the source file as written plus the limits registry's figures, nothing else; the
// file itself holds no limit (they would drift).
TEST(OpenApi, ServedDocumentIsTheSourceFilePlusTheLimitsRegistry) {
  std::ifstream in(SOFTTUNE_SOURCE_DIR "/server/http/openapi.json", std::ios::binary);
  ASSERT_TRUE(in);
  const std::string file((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  json source = json::parse(file);
  EXPECT_FALSE(source["info"].contains("x-softtune-limits")) << "limits are written from the registry, not by hand";
  source["info"]["x-softtune-limits"] = softtune::http::limits_json();
  EXPECT_EQ(openapi_document(), source);
  EXPECT_EQ(openapi_document()["openapi"], "3.1.0");
  EXPECT_TRUE(softtune::http::openapi_text().starts_with("{\n  \"openapi\": \"3.1.0\",")) << "key order as written";
}

TEST(OpenApi, DocumentsExactlyTheRoutesServed) {
  const json& paths = openapi_document()["paths"];
  std::size_t operations = 0;
  for (const auto& route : softtune::http::service_routes()) {
    const std::string key = openapi_key(route.pattern);
    EXPECT_TRUE(paths.contains(key) && paths[key].contains(lower(route.method)))
        << route.method << " " << route.pattern << " has no OpenAPI entry";
    ++operations;
  }
  std::size_t documented = 0;
  for (const auto& [path, item] : paths.items()) documented += item.size();
  EXPECT_EQ(documented, operations) << "the document lists an operation no route serves";
}

TEST(OpenApi, LimitsAreThoseOfTheServer) {
  namespace l = softtune::http::limits;
  const json& x = openapi_document()["info"]["x-softtune-limits"];
  EXPECT_EQ(x["max_body_bytes"], l::kMaxBodyBytes);
  EXPECT_EQ(x["max_header_bytes"], l::kMaxHeaderBytes);
  EXPECT_EQ(x["max_json_depth"], l::kMaxJsonDepth);
  EXPECT_EQ(x["default_threads"], l::kDefaultThreads);
  EXPECT_EQ(x["max_threads"], l::kMaxThreads);
  EXPECT_EQ(x["max_queued_connections"], l::kMaxQueuedConnections);
  EXPECT_EQ(x["max_open_connections"], l::kMaxOpenConnections);
  EXPECT_EQ(x["max_connections_per_client"], l::kMaxConnectionsPerClient);
  EXPECT_EQ(x["request_read_timeout_ms"], l::kRequestReadTimeout.count());
  EXPECT_EQ(x["min_body_bytes_per_s"], l::kMinBodyBytesPerSecond);
  EXPECT_EQ(x["body_grace_ms"], l::kBodyGrace.count());
  EXPECT_EQ(x["max_gate_buffered_bytes"], l::kMaxGateBufferedBytes);
  EXPECT_EQ(x["write_timeout_ms"], l::kWriteTimeout.count());
  EXPECT_EQ(x["keep_alive_timeout_ms"], l::kKeepAliveTimeout.count());
  EXPECT_EQ(x["keep_alive_max_requests"], l::kKeepAliveMaxRequests);
  EXPECT_EQ(x["response_cache_entries"], l::kResponseCacheEntries);
  EXPECT_EQ(x["response_cache_bytes"], l::kResponseCacheBytes);
  EXPECT_EQ(x["max_header_line_bytes"], l::kMaxHeaderLineBytes);
  EXPECT_EQ(x["max_preview_frames"], softtune::render::caps::kMaxFrames);
  EXPECT_EQ(x["max_preview_width"], softtune::render::caps::kMaxWidth);
  EXPECT_EQ(x["max_preview_height"], softtune::render::caps::kMaxHeight);
  EXPECT_EQ(x["scene_max_duration_s"], softtune::scene::limits::kMaxDurationS);
  EXPECT_EQ(x["scene_max_steps"], softtune::scene::limits::kMaxSceneSteps);
  EXPECT_EQ(x["scene_max_body_steps"], softtune::scene::limits::kMaxBodySteps);
  EXPECT_EQ(x["scene_max_bodies"], softtune::scene::limits::kMaxBodies);
  EXPECT_EQ(x["scene_max_joints"], softtune::scene::limits::kMaxJoints);
  EXPECT_EQ(x["scene_max_typed_stiffness"], softtune::scene::limits::kMaxTypedStiffness);
  EXPECT_EQ(x["modes_max_dynamic_bodies"], softtune::scene::limits::kMaxModeBodies);
  EXPECT_EQ(x["modal_max_targets"], softtune::scene::limits::kMaxModeTargets);
  EXPECT_EQ(x["modal_max_groups"], softtune::scene::limits::kMaxJointGroups);
  EXPECT_EQ(x["simulate_max_frame_stride"], softtune::codec::kMaxFrameStride);
  EXPECT_EQ(x["accuracy_max_step_rates"], softtune::limits::kMaxStepRates);
  EXPECT_EQ(x["accuracy_max_soft_substeps"], softtune::limits::kMaxSoftSubsteps);
  EXPECT_EQ(x["accuracy_max_timing_repeats"], softtune::limits::kMaxTimingRepeats);
  EXPECT_EQ(x["accuracy_max_steps_per_row"], softtune::limits::kMaxAccuracyStepsPerRow);
  EXPECT_EQ(x["stability_max_grid_entries"], softtune::codec::kMaxGridEntries);
  EXPECT_EQ(x["stability_max_cases"], softtune::codec::kMaxCases);
  EXPECT_EQ(x["stability_max_observe_steps"], softtune::codec::kMaxObserveSteps);
  EXPECT_EQ(x["identify_max_samples"], softtune::kIdentifyMaxSamples);
  EXPECT_EQ(x["identify_max_probes"], softtune::kIdentifyMaxProbes);
  EXPECT_EQ(x["identify_max_values"], softtune::kIdentifyMaxCells);
  EXPECT_EQ(x["identify_max_csv_bytes"], softtune::codec::kCsvMaxBytes);
  EXPECT_EQ(x["identify_max_previous"], softtune::codec::kIdentifyMaxPrevious);
  EXPECT_EQ(x["check_max_work"], softtune::app::kMaxCheckWork);
  EXPECT_EQ(x["check_max_presets"], softtune::app::kMaxCheckPresets);
  EXPECT_EQ(x["check_max_scenes"], softtune::app::kMaxCheckScenes);
  EXPECT_EQ(x["check_max_rates"], softtune::scene::limits::kMaxRates);
  EXPECT_EQ(x["request_budget_cpu_s"], softtune::app::budgets::kCpuSeconds);
  EXPECT_EQ(x["request_budget_peak_bytes"], softtune::app::budgets::kPeakBytes);
  EXPECT_EQ(x["job_budget_cpu_s"], softtune::app::budgets::kJobCpuSeconds);
  EXPECT_EQ(x["check_job_max_work"], softtune::app::kMaxCheckJobWork);
  EXPECT_EQ(x["max_queued_jobs"], softtune::app::kMaxQueuedJobs);
  EXPECT_EQ(x["max_kept_jobs"], softtune::app::kMaxKeptJobs);
  EXPECT_EQ(x["job_kept_s"], softtune::app::kKeepJobsFor.count());
  EXPECT_EQ(x["max_kept_job_bytes"], softtune::app::kMaxKeptJobBytes);
  EXPECT_EQ(x.size(), 55u) << "a limit is documented that this test does not check";
  // A list's length in a schema is the codec's.
  EXPECT_EQ(openapi_document()["components"]["schemas"]["AccuracyRequest"]["properties"]["soft_substeps"]["maxItems"],
            softtune::limits::kMaxSoftSubsteps);
}

TEST(OpenApi, EveryRefResolves) {
  std::vector<std::string> refs;
  collect_refs(openapi_document(), refs);
  EXPECT_FALSE(refs.empty());
  for (const std::string& ref : refs) {
    ASSERT_EQ(ref.rfind("#/", 0), 0u) << ref;
    EXPECT_TRUE(openapi_document().contains(json::json_pointer(ref.substr(1)))) << ref;
  }
}

TEST(OpenApi, TuneSchemasAgreeWithTheCodec) {
  const json example = openapi_document()["paths"]["/api/v1/tune"]["post"]["requestBody"]["content"]["application/json"]["example"];
  const std::vector<json> requests = {
      example,
      json::parse(R"({"frequency_hz": 25, "damping_ratio": 0, "effective_mass": 1, "fps": 60, "mode": "exact"})"),
      json::parse(R"({"frequency_hz": 40, "oscillation": "free", "effective_mass": 1, "fps": 60, "mode": "exact"})"),
      json::parse(R"({"response_frames": 8, "basis_fps": 30, "oscillation": "none", "fps": 120, "substeps": 4,
                      "constraint": {"dimension": 2, "type": "linear", "body_a": {"mass": 3, "inertia": 0.5},
                                     "body_b": "static", "anchor_a": [0.5, 0], "anchor_b": [1, 0], "axis": [0, 2]}})"),
      json::parse(R"({"response_frames": 10, "oscillation": "some", "constraint": {"dimension": 3, "type": "angular",
                      "body_a": {"mass": 2, "inertia": [[1, 0, 0], [0, 2, 0], [0, 0, 3]]}, "body_b": "static",
                      "axis": [0, 0, 1]}})"),
  };
  for (const json& request : requests) {
    EXPECT_EQ(request_error(request), "") << request.dump();
    const json response = softtune::app::run_tune(request);
    EXPECT_EQ(conformance_error("/api/v1/tune", "post", 200, "application/json", response), "") << request.dump();
  }
}

// The page reads the designer's oscillation words from here (web/state.js), so they must be core's.
TEST(OpenApi, OscillationWordsMapToCoresDampingRatios) {
  const json& words = openapi_document()["components"]["schemas"]["TuneRequest"]["properties"]["oscillation"];
  const json& zeta = words["x-damping-ratio"];
  ASSERT_EQ(zeta.size(), 3u);
  EXPECT_EQ(words["enum"], json({"free", "some", "none"}));
  EXPECT_EQ(zeta["free"].get<double>(), softtune::damping_ratio_of(softtune::Oscillation::free));
  EXPECT_EQ(zeta["some"].get<double>(), softtune::damping_ratio_of(softtune::Oscillation::some));
  EXPECT_EQ(zeta["none"].get<double>(), softtune::damping_ratio_of(softtune::Oscillation::none));
}

TEST(OpenApi, TuneRequestSchemaRefusesWhatTheCodecRefuses) {
  const std::vector<json> bad = {
      json::parse(R"({"response_frames": 12, "oscillation": "some", "effective_mass": 2, "fps": 0})"),
      json::parse(R"({"response_frames": 12, "oscillation": "sometimes", "effective_mass": 2})"),
      json::parse(R"({"response_frames": 12, "oscillation": "some", "effective_mass": -1})"),
      json::parse(R"({"response_frames": 12, "oscillation": "some", "effective_mass": 2, "substeps": 1.5})"),
      json::parse(R"({"response_frames": 12, "oscillation": "some", "effective_mass": 2, "colour": "red"})"),
  };
  for (const json& request : bad) {
    EXPECT_NE(request_error(request), "") << request.dump();
    EXPECT_THROW(softtune::app::run_tune(request), softtune::codec::Problem) << request.dump();
  }
}

TEST(OpenApi, ProblemsConform) {
  try {
    softtune::app::run_tune(json::parse(R"({"response_frames": 12, "oscillation": "some"})"));
    FAIL() << "expected a Problem";
  } catch (const softtune::codec::Problem& p) {
    EXPECT_EQ(conformance_error("/api/v1/tune", "post", 422, "application/problem+json", softtune::codec::problem_json(p)), "");
  }
}

// Every documented request example is valid against its own schema, and the codec runs it into a
// response that conforms to the documented one.
TEST(OpenApi, CapabilityExamplesRunAndConform) {
  const std::string presets = SOFTTUNE_SOURCE_DIR "/presets";
  const std::map<std::string, std::function<json(const json&)>> contracts = {
      {"/api/v1/simulate", [&](const json& q) { return softtune::app::run_simulate(q, presets); }},
      {"/api/v1/modes", [&](const json& q) { return softtune::app::run_modes(q, presets); }},
      {"/api/v1/accuracy", [](const json& q) { return softtune::app::run_accuracy(q); }},
      {"/api/v1/stability", [](const json& q) { return softtune::app::run_stability(q); }},
      {"/api/v1/verify", [](const json& q) { return softtune::app::run_verify(q); }},
      {"/api/v1/identify", [](const json& q) { return softtune::app::run_identify(q); }},
      {"/api/v1/check", [&](const json& q) { return softtune::app::run_check_request(q, presets).json; }},
  };
  for (const auto& [path, contract] : contracts) {
    const json& body = openapi_document()["paths"][path]["post"]["requestBody"]["content"]["application/json"];
    const json& schema = softtune::http::testing::resolve(body["schema"]);
    auto e = softtune::codec::validate_json_schema(body["example"], schema, openapi_document());
    EXPECT_FALSE(e) << path << ": " << (e ? e->pointer + " " + e->rule : "");
    EXPECT_EQ(conformance_error(path, "post", 200, "application/json", contract(body["example"])), "") << path;
  }
  // A scene that tunes its modes answers with modal_tuning, documented too.
  const json vehicle = softtune::app::run_simulate({{"preset", "vehicle"}}, presets);
  ASSERT_TRUE(vehicle.contains("modal_tuning"));
  EXPECT_EQ(conformance_error("/api/v1/simulate", "post", 200, "application/json", vehicle), "");
}
