// The bad-input matrix: generated hostile variants of a valid request for every field of every JSON
// route (tune, simulate, accuracy, stability, preview, presets). Each case must end as a 4xx Problem
// naming the field (or, where a value is legal, a 2xx answer), never as a 5xx, an escaped exception or a
// non-finite number. tune and preview go over HTTP to an in-process server (content type, empty and
// non-UTF-8 bodies included); simulate, accuracy, stability and presets go through the codec functions
// their routes call (the same JSON in, the same Problem out).
#include <gtest/gtest.h>

#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "bad_input_cases.h"
#include "codec/accuracy_codec.h"
#include "codec/json_reader.h"
#include "codec/preview_service.h"
#include "codec/problem.h"
#include "codec/scene_codec.h"
#include "codec/stability_codec.h"
#include "codec/tune_codec.h"
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

/// A codec contract as a route runs it: parse the body strictly, run, turn a Problem into its status.
/// Any other exception is what a route would turn into a 500.
Outcome through_codec(const std::function<json(const json&)>& contract, const std::string& body) {
  try {
    return {200, "", contract(codec::parse_json(body))};
  } catch (const codec::Problem& p) {
    return {p.status, p.field, codec::problem_json(p)};
  } catch (const std::exception& e) {
    return {500, "", json{{"exception", e.what()}}};
  }
}

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
  static void SetUpTestSuite() { server_ = new http::testing::TestServer(); }
  static void TearDownTestSuite() {
    delete server_;
    server_ = nullptr;
  }

  /// POSTs over HTTP; a 2xx tune answer must also conform to the OpenAPI document.
  static Outcome over_http(const std::string& path, const Case& c) {
    auto client = server_->client();
    auto res = client.Post(path.c_str(), c.body, c.content_type.c_str());
    if (!res) return {599, "", json{{"error", "no answer"}}};
    Outcome o{res->status, "", json()};
    o.body = json::parse(res->body, nullptr, false);
    if (res->status >= 400) {
      EXPECT_EQ(res->get_header_value("Content-Type").rfind("application/problem+json", 0), 0u) << c.name;
      if (o.body.is_object() && o.body.contains("field")) o.field = o.body["field"].get<std::string>();
    } else if (path == "/api/v1/tune") {
      EXPECT_EQ(http::testing::conformance_error(path, "post", res->status, "application/json", o.body), "") << c.name;
    }
    return o;
  }

  static http::testing::TestServer* server_;
};

http::testing::TestServer* BadInputMatrix::server_ = nullptr;

// Plans only: the frames of a legal variant are not rendered (the render pool has its own tests).
json plan(const json& doc) {
  const codec::PreviewPlan p = codec::plan_preview(doc, kPresets);
  return json{{"canonical", p.canonical}, {"warnings", p.warnings}};
}

TEST_F(BadInputMatrix, EveryCaseEndsAs4xxNamingTheFieldOrAFiniteAnswer) {
  const std::vector<Case> cases = all_cases(kPresets);
  std::size_t ran = 0;
  for (const Case& c : cases) {
    Outcome o;
    if (c.route == "tune") {
      o = over_http("/api/v1/tune", c);
    } else if (c.route == "preview") {
      o = c.content_type == "application/json" ? through_codec(plan, c.body) : over_http("/api/v1/preview", c);
    } else if (c.route == "simulate") {
      o = through_codec([](const json& d) { return codec::run_simulate(d, kPresets); }, c.body);
    } else if (c.route == "accuracy") {
      o = through_codec([](const json& d) { return codec::run_accuracy(d); }, c.body);
    } else if (c.route == "stability") {
      // Decoding is the whole of the validation; a legal variant runs with the case list left out.
      o = through_codec([](const json& d) {
        codec::StabilityRequest q = codec::decode_stability_request(d);
        q.run_chain = false;
        return codec::run_stability(q);
      }, c.body);
    } else if (c.route == "presets") {
      try {
        o = {200, "", codec::preset_document(kPresets, c.body)};
      } catch (const codec::Problem& p) {
        o = {p.status, p.field, codec::problem_json(p)};
      }
    } else {
      ADD_FAILURE() << "unknown route " << c.route;
      continue;
    }
    check(c, o);
    ++ran;
  }
  EXPECT_GE(ran, 200u);
  std::printf("bad-input matrix: %zu cases\n", ran);
}

}  // namespace
}  // namespace softtune::security
