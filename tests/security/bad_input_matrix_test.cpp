// The bad-input matrix: generated hostile variants of a valid request for every field of every JSON
// route (tune, simulate, accuracy, stability, preview, presets). Each case must end as a 4xx Problem
// naming the field (or, where a value is legal, a 2xx answer), never as a 5xx, an escaped exception or a
// non-finite number. Every case goes over HTTP to an in-process server, as a client would send it
// (content type, empty and non-UTF-8 bodies included; a preset name percent-encoded into the path).
#include <gtest/gtest.h>

#include <cctype>
#include <cstdio>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "bad_input_cases.h"
#include "http/router.h"
#include "harnesses.h"
// After Eigen (through the codec headers): cpp-httplib brings <resolv.h>, whose `_res` macro breaks
// Eigen's parameters of that name.
#include "../http/openapi_conformance.h"
#include "../http/test_server.h"

namespace softtune::security {
namespace {

using nlohmann::json;

const std::string kPresets = SOFTTUNE_SOURCE_DIR "/presets";

/// What a route did with one case.
struct Outcome {
  int status = 0;
  std::string field;  ///< the Problem's field ("" for success)
  json body;          ///< the answer (success) or the problem document
};

/// The Problem's field and the mutated path name the same place: equal, or one holds the other (a
/// missing nested object is reported at its parent; a wrong array at its element). A scene's schema
/// problems name the JSON pointer inside the scene ("/world/fps" for "scene.world.fps"), so a reported
/// path that ends the mutated one also names it.
bool names_field(const std::string& reported, const std::string& mutated) {
  if (mutated == kAnyField) return !reported.empty();
  const std::string r = normalize_path(reported);
  const std::string m = normalize_path(mutated);
  if (r.empty() || m.empty()) return r == m || !r.empty();
  auto holds = [](const std::string& outer, const std::string& inner) {
    return inner.rfind(outer, 0) == 0 && (inner.size() == outer.size() || inner[outer.size()] == '.');
  };
  for (std::size_t dot = m.find('.'); dot != std::string::npos; dot = m.find('.', dot + 1)) {
    const std::string tail = m.substr(dot + 1);
    if (holds(r, tail) || holds(tail, r)) return true;
  }
  return holds(r, m) || holds(m, r);
}

void check(const Case& c, const Outcome& o) {
  SCOPED_TRACE(c.route + " / " + c.name + " / body: " + c.body.substr(0, 300));
  SCOPED_TRACE("answer: " + o.body.dump().substr(0, 400));
  EXPECT_LT(o.status, 500) << "a server error";
  EXPECT_TRUE(fuzz::all_finite(o.body)) << "a non-finite number";
  if (o.status >= 400) {
    EXPECT_GE(o.status, 400);
    if (c.field) {
      EXPECT_TRUE(names_field(o.field, *c.field)) << "the problem names \"" << o.field << "\", not \"" << *c.field << "\"";
    }
    return;
  }
  EXPECT_FALSE(c.must_fail) << "accepted a value that has no meaning (status " << o.status << ")";
}

class BadInputMatrix : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    http::ServiceConfig config = http::testing::web_config();
    config.presets_dir = kPresets;
    server_ = new http::testing::TestServer(http::testing::quick_options(), config);
  }
  static void TearDownTestSuite() {
    delete server_;
    server_ = nullptr;
  }

  /// POSTs over HTTP (GET for a preset name); a 2xx answer must also conform to the OpenAPI document.
  static Outcome over_http(const std::string& path, const Case& c) {
    auto client = server_->client();
    // A hang guard, not a speed bar: a stability body without `chain` runs the default chain sweep, about
    // 1 s in Release and 70 s in the ASan build (Eigen's tiny arrays are not inlined there).
    client.set_read_timeout(300, 0);
    const bool get = c.route == "presets";
    auto res = get ? client.Get(path.c_str()) : client.Post(path.c_str(), c.body, c.content_type.c_str());
    if (!res) return {599, "", json{{"error", "no answer"}}};
    Outcome o{res->status, "", json()};
    o.body = json::parse(res->body, nullptr, false);
    const std::string documented = get ? "/api/v1/presets/{name}" : path;
    if (res->status >= 400) {
      EXPECT_EQ(res->get_header_value("Content-Type").rfind("application/problem+json", 0), 0u) << c.name;
      if (o.body.is_object() && o.body.contains("field")) o.field = o.body["field"].get<std::string>();
      // The document lists every status a route answers with.
      EXPECT_EQ(http::testing::conformance_error(documented, get ? "get" : "post", res->status, "application/problem+json",
                                                 o.body), "")
          << c.name;
    } else {
      EXPECT_EQ(http::testing::conformance_error(documented, get ? "get" : "post", res->status, "application/json", o.body), "")
          << c.name;
    }
    return o;
  }

  static http::testing::TestServer* server_;
};

http::testing::TestServer* BadInputMatrix::server_ = nullptr;

// A preset name as a client puts it into the path: every byte outside [A-Za-z0-9._~-] percent-encoded.
std::string preset_path(const std::string& name) {
  std::string out = "/api/v1/presets/";
  for (const char ch : name) {
    const auto u = static_cast<unsigned char>(ch);
    if (std::isalnum(u) || ch == '.' || ch == '_' || ch == '~' || ch == '-') {
      out += ch;
    } else {
      char buf[4];
      std::snprintf(buf, sizeof buf, "%%%02X", u);
      out += buf;
    }
  }
  return out;
}

// The document's path pattern that a request path (its query dropped) falls under.
std::string documented_pattern(const std::string& target) {
  const std::string path = target.substr(0, target.find('?'));
  for (const auto& [pattern, item] : http::testing::openapi_document()["paths"].items()) {
    if (pattern != "/{path}" && http::match_route(pattern, path)) return pattern;
  }
  return "/{path}";
}

TEST_F(BadInputMatrix, EveryCaseEndsAs4xxNamingTheFieldOrAFiniteAnswer) {
  const std::vector<Case> cases = all_cases(kPresets);
  std::size_t ran = 0;
  for (const Case& c : cases) {
    const Outcome o = over_http(c.route == "presets" ? preset_path(c.body) : "/api/v1/" + c.route, c);
    check(c, o);
    ++ran;
  }
  EXPECT_GE(ran, 200u);
  std::printf("bad-input matrix: %zu cases\n", ran);
}

// Query and path parameters, taken from the OpenAPI document so a newly documented one is covered too:
// hostile values each end as a 4xx naming the parameter. Preset names and static paths have their own
// cases (above, and the attack suite's traversal variants).
TEST_F(BadInputMatrix, EveryDocumentedParameterRefusesHostileValuesNamingIt) {
  auto client = server_->client();
  client.set_read_timeout(60, 0);
  auto started = client.Post("/api/v1/preview", R"({"preset": "oscillator", "frames": 2, "size": "32x18", "wait": true})",
                             "application/json");
  ASSERT_TRUE(started && started->status == 200);
  const std::string id = json::parse(started->body)["id"];
  const std::map<std::string, std::string> bodies = {
      {"/api/v1/accuracy", R"({"frequency_hz": 5, "damping_ratio": 0.5, "effective_mass": 1, "step_rates": [60],
                              "soft_substeps": [1], "timing_repeats": 1, "box2d": false})"},
      {"/api/v1/stability", R"({"methods": ["soft"], "frequency_ratios": [0.1], "stiffnesses": [100],
                               "damping_ratios": [0], "masses": [1], "steps": [0.01], "observe_steps": 1000,
                               "chain": false})"},
      {"/api/v1/identify", R"({"time_s": [0, 0.1, 0.2], "probes": {"x": [1, 0.5, 0.2]}})"}};
  const std::vector<std::string> hostile = {"xml", "JSON", "json%00", "%00", "..%2f..%2fetc", "%ff%fe", "1e999", "-1",
                                            "NaN", "0x1", "+1", "%201", "99999999999999999999", std::string(4000, 'a')};
  std::size_t ran = 0;
  for (const auto& [pattern, item] : http::testing::openapi_document()["paths"].items()) {
    for (const auto& [method, op] : item.items()) {
      for (const auto& param : op.value("parameters", json::array())) {
        const std::string name = param["name"];
        if (name == "name" || name == "path") continue;
        for (const std::string& value : hostile) {
          std::string url = pattern;
          if (param["in"] == "query") {
            url += "?" + name + "=" + value;
          } else {
            url.replace(url.find("{" + name + "}"), name.size() + 2, value);
          }
          if (auto at = url.find("{id}"); at != std::string::npos) url.replace(at, 4, id);
          if (auto at = url.find("{n}"); at != std::string::npos) url.replace(at, 3, "0");
          SCOPED_TRACE(method + " " + url.substr(0, 200));
          auto res = method == "get"      ? client.Get(url.c_str())
                     : method == "delete" ? client.Delete(url.c_str())
                                          : client.Post(url.c_str(), bodies.at(pattern), "application/json");
          ASSERT_TRUE(res);
          EXPECT_GE(res->status, 400);
          EXPECT_LT(res->status, 500);
          const json problem = json::parse(res->body, nullptr, false);
          ASSERT_TRUE(problem.is_object() && problem.contains("field")) << res->body.substr(0, 300);
          // A path trick in a path parameter is refused by the router for the whole path, before any route.
          const bool whole_path = param["in"] == "path" && problem["field"] == "path";
          EXPECT_TRUE(problem["field"] == name || whole_path) << res->body.substr(0, 300);
          ++ran;
        }
      }
    }
  }
  EXPECT_GE(ran, 6 * hostile.size());
  std::printf("bad-input matrix: %zu parameter cases\n", ran);
}

// Issue 17's hostile requests, each with the answer the API owes it: requests over the cost budget (422
// naming the fields that drive the cost), conditional GETs (RFC 9110 13.1.2), query parameters that are
// unknown or repeated, numbers that overflow a double, preview ids and frame numbers that are not in
// their one valid form, and duplicated framing headers.
TEST_F(BadInputMatrix, CostQueryConditionalAndIdCasesEndAsTheRfcAndTheBudgetAsk) {
  auto client = server_->client();
  client.set_read_timeout(60, 0);
  struct Expect {
    std::string method, path, body;
    int status;
    std::string field;  // "" for an answer without a problem
  };
  const std::string sweep = R"({"methods": ["soft"], "frequency_ratios": [0.1], "stiffnesses": [100], "damping_ratios": [0],
                                "masses": [1], "steps": [0.01], "chain": false})";
  std::vector<Expect> cases = {
      {"POST", "/api/v1/stability", R"({"observe_steps": 91835})", 422, "observe_steps"},
      {"POST", "/api/v1/stability", R"({"observe_steps": 100000, "chain": false, "include_cases": false})", 422, "observe_steps"},
      {"POST", "/api/v1/stability", R"({"chain": {"iterations": [256, 255, 254, 253, 252, 251, 250, 249, 248, 247]}})", 422, "chain.iterations"},
      {"POST", "/api/v1/accuracy", R"({"frequency_hz": 1, "oscillation": "some", "effective_mass": 1, "step_rates": [10000, 20000],
                                     "soft_substeps": [1], "duration_s": 50, "timing_repeats": 51})", 422, "*"},
      {"POST", "/api/v1/verify", R"({"frequency_hz": 2, "damping_ratio": 0.1, "effective_mass": 1, "fps": 4000,
                                   "engines": ["box2d_v2_4", "ode", "bullet", "mujoco"], "duration_s": 50})", 422, "*"},
      {"POST", "/api/v1/stability?bogus=1", sweep, 422, "bogus"},
      {"POST", "/api/v1/stability?format=svg&format=json", sweep, 422, "format"},
      {"POST", "/api/v1/tune?x=1", R"({"frequency_hz": 5, "damping_ratio": 0.5, "effective_mass": 1})", 422, "x"},
      {"GET", "/api/v1/health?a=1", "", 422, "a"},
      {"POST", "/api/v1/tune", R"({"frequency_hz": 1e309, "damping_ratio": 0.5, "effective_mass": 1})", 422, "frequency_hz"},
      {"POST", "/api/v1/tune", R"({"frequency_hz": 5, "damping_ratio": 0.5, "constraint": {"anchor_a": [0, -1e309]}})", 422, "constraint.anchor_a.1"},
      {"GET", "/api/v1/preview/" + std::string(5000, 'a'), "", 404, "id"},
      {"GET", "/api/v1/preview/" + std::string(64, 'A') + "/0.png", "", 404, "id"},
      {"GET", "/api/v1/preview/" + std::string(63, 'a') + "/filmstrip.png", "", 404, "id"},
      // The job routes: the synchronous routes' checks, the job budget, and ids in their one form.
      {"POST", "/api/v1/stability/jobs", R"({"observe_steps": 100000, "masses": [1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16]})", 422, "*"},
      {"POST", "/api/v1/stability/jobs", R"({"methods": ["soft", "rk4"]})", 422, "methods.1"},
      {"POST", "/api/v1/stability/jobs", R"({"observe_steps": 1e309})", 422, "observe_steps"},
      {"POST", "/api/v1/stability/jobs?format=svg", sweep, 422, "format"},
      {"POST", "/api/v1/check/jobs", R"({"presets": ["mouse"], "format": "junit"})", 422, "format"},
      {"POST", "/api/v1/check/jobs", R"({"presets": ["mouse"], "fps": [0]})", 422, "fps.0"},
      {"POST", "/api/v1/check/jobs", R"({"presets": ["mouse"], "bogus": 1})", 422, "bogus"},
      {"POST", "/api/v1/check/jobs", R"({"fps": [30, 60, 120, 144, 240, 480, 500, 600, 700, 800, 900, 960, 1000, 1100, 1200, 1440], "substeps": [1, 2, 4, 8, 16, 32, 64]})", 422, "presets, scenes, fps, substeps"},
      {"GET", "/api/v1/jobs/" + std::string(5000, 'a'), "", 404, "id"},
      {"DELETE", "/api/v1/jobs/J0123456789ABCDEF", "", 404, "id"},
      {"GET", "/api/v1/jobs/j0123456789abcdef0", "", 404, "id"},
      {"GET", "/api/v1/jobs/j0123456789abcdef", "", 404, "id"},
  };
  // A finished preview for the conditional and frame-number cases.
  auto started = client.Post("/api/v1/preview", R"({"preset": "oscillator", "frames": 2, "size": "32x18", "wait": true})",
                             "application/json");
  ASSERT_TRUE(started && started->status == 200);
  const std::string id = json::parse(started->body)["id"];
  cases.push_back({"GET", "/api/v1/preview/" + id + "/00.png", "", 404, "n"});
  cases.push_back({"GET", "/api/v1/preview/" + id + "/+1.png", "", 422, "n"});
  cases.push_back({"GET", "/api/v1/preview/" + id + "/0.png", "", 200, ""});
  std::size_t ran = 0;
  for (const Expect& e : cases) {
    SCOPED_TRACE(e.method + " " + e.path.substr(0, 120) + " " + e.body.substr(0, 120));
    auto res = e.method == "GET"      ? client.Get(e.path.c_str())
               : e.method == "DELETE" ? client.Delete(e.path.c_str())
                                      : client.Post(e.path.c_str(), e.body, "application/json");
    ASSERT_TRUE(res);
    EXPECT_EQ(res->status, e.status) << res->body.substr(0, 300);
    EXPECT_LT(res->body.size(), 2000u) << "a refusal echoes no more than the valid form";
    if (res->status >= 400) {
      const std::string method = e.method == "GET" ? "get" : e.method == "DELETE" ? "delete" : "post";
      EXPECT_EQ(http::testing::conformance_error(documented_pattern(e.path), method, res->status, "application/problem+json",
                                                 json::parse(res->body, nullptr, false)), "");
    }
    if (!e.field.empty()) {
      const json problem = json::parse(res->body, nullptr, false);
      ASSERT_TRUE(problem.is_object()) << res->body.substr(0, 300);
      if (e.field != "*") {
        EXPECT_EQ(problem.value("field", ""), e.field) << res->body.substr(0, 300);
      }
      EXPECT_FALSE(problem.value("field", "").starts_with("/")) << "a dotted path, never a JSON pointer";
    }
    ++ran;
  }
  // Conditional GET: the PNG's tag, weak, in a list, or "*" is a 304 without a Content-Type line.
  const std::string png = "/api/v1/preview/" + id + "/0.png";
  auto first = client.Get(png.c_str());
  ASSERT_TRUE(first && first->status == 200);
  const std::string etag = first->get_header_value("ETag");
  for (const std::string& tags : {etag, "W/" + etag, "\"x\", " + etag, std::string("*"), " \"x\" ,W/" + etag}) {
    SCOPED_TRACE("If-None-Match: " + tags);
    auto res = client.Get(png.c_str(), httplib::Headers{{"If-None-Match", tags}});
    ASSERT_TRUE(res);
    EXPECT_EQ(res->status, 304);
    EXPECT_FALSE(res->has_header("Content-Type"));
    ++ran;
  }
  for (const std::string& tags : {std::string("\"x\""), std::string("W/\"y\", \"z\""), std::string("garbage")}) {
    auto res = client.Get(png.c_str(), httplib::Headers{{"If-None-Match", tags}});
    ASSERT_TRUE(res);
    EXPECT_EQ(res->status, 200) << tags;
    ++ran;
  }
  std::printf("bad-input matrix: %zu issue-17 cases\n", ran);
}

}  // namespace
}  // namespace softtune::security
