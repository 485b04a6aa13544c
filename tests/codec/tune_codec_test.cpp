#include "codec/tune_codec.h"

#include "app/tune_app.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "codec/problem.h"

using nlohmann::json;
using namespace softtune::codec;

namespace {

using softtune::app::run_tune;

json base() { return json::parse(R"({"response_frames": 12, "oscillation": "some", "effective_mass": 2})"); }

// The Problem's (status, field) for a request, or (0, "") when it is accepted.
std::pair<int, std::string> problem_of(const json& doc) {
  try {
    run_tune(doc);
    return {0, ""};
  } catch (const Problem& p) {
    return {p.status, p.field};
  }
}

std::pair<int, std::string> with(const std::function<void(json&)>& change) {
  json doc = base();
  change(doc);
  return problem_of(doc);
}

// Every number anywhere in the document is finite (nlohmann writes NaN/inf as null, so check before dump).
bool all_finite(const json& j) {
  if (j.is_number()) return std::isfinite(j.get<double>());
  if (j.is_structured()) {
    for (const auto& e : j) {
      if (!all_finite(e)) return false;
    }
  }
  return true;
}

}  // namespace

TEST(TuneCodec, ResponseHasTheContractFields) {
  const json r = run_tune(base());
  for (const char* key : {"h", "frequency_hz", "omega", "damping_ratio", "effective_mass", "k", "c", "gamma", "beta",
                          "erp", "cfm", "gamma_impulse", "box2d_v3", "achieved", "stability", "engines", "warnings",
                          "stages"}) {
    EXPECT_TRUE(r.contains(key)) << key;
  }
  for (const char* key : {"bias_rate", "mass_scale", "impulse_scale"}) EXPECT_TRUE(r["box2d_v3"].contains(key)) << key;
  for (const char* key : {"frequency_hz", "damping_ratio", "spectral_radius"}) EXPECT_TRUE(r["achieved"].contains(key));
  for (const char* m : {"explicit_euler", "semi_implicit_euler", "implicit_euler", "soft", "soft_exact"}) {
    EXPECT_TRUE(r["stability"].contains(m)) << m;
  }
  EXPECT_DOUBLE_EQ(r["frequency_hz"].get<double>(), 5.0);
  EXPECT_DOUBLE_EQ(r["erp"].get<double>(), r["beta"].get<double>());
  EXPECT_DOUBLE_EQ(r["cfm"].get<double>(), r["gamma"].get<double>());
  EXPECT_DOUBLE_EQ(r["gamma_impulse"].get<double>(), r["gamma"].get<double>() / r["h"].get<double>());
  EXPECT_TRUE(all_finite(r));
}

TEST(TuneCodec, UnrepresentableGammaIsNullNotInfinity) {
  json doc = base();
  doc["oscillation"] = "free";
  doc["mode"] = "exact";
  const json r = run_tune(doc);
  EXPECT_TRUE(r["gamma"].is_null());
  EXPECT_TRUE(r["cfm"].is_null());
  EXPECT_TRUE(r["k"].is_number());
  EXPECT_EQ(r["warnings"][0]["code"], "gamma_unrepresentable");
  EXPECT_TRUE(all_finite(r));
}

TEST(TuneCodec, ConstraintForms) {
  json doc = base();
  doc.erase("effective_mass");
  doc["constraint"] = json::parse(R"({"dimension": 2, "type": "linear", "body_a": "static",
      "body_b": {"mass": 4, "inertia": 1.3333333333333333, "position": [0, 0]},
      "anchor_a": [1, 1], "anchor_b": [1, 0], "axis": [0, 1]})");
  const json r = run_tune(doc);
  EXPECT_NEAR(r["effective_mass"].get<double>(), 1.0, 1e-12);
  EXPECT_NEAR(r["effective_mass_check"]["unit_impulse"].get<double>(), 1.0, 1e-12);
  doc["constraint"] = json::parse(R"({"dimension": 3, "type": "angular", "body_a": "static",
      "body_b": {"mass": 1, "inertia": [[2, 0, 0], [0, 3, 0], [0, 0, 4]], "orientation": [1, 0, 0, 0]},
      "axis": [0, 0, 1]})");
  EXPECT_NEAR(run_tune(doc)["effective_mass"].get<double>(), 4.0, 1e-12);
}

TEST(TuneCodec, BadInputNamesTheField) {
  EXPECT_EQ(with([](json& d) { d["fps"] = "sixty"; }), std::make_pair(422, std::string("fps")));
  EXPECT_EQ(with([](json& d) { d["fps"] = -60; }), std::make_pair(422, std::string("fps")));
  EXPECT_EQ(with([](json& d) { d["substeps"] = 2.5; }), std::make_pair(422, std::string("substeps")));
  EXPECT_EQ(with([](json& d) { d["substeps"] = 0; }), std::make_pair(422, std::string("substeps")));
  EXPECT_EQ(with([](json& d) { d["response_frames"] = 0; }), std::make_pair(422, std::string("response_frames")));
  EXPECT_EQ(with([](json& d) { d["oscillation"] = "lots"; }), std::make_pair(422, std::string("oscillation")));
  EXPECT_EQ(with([](json& d) { d["mode"] = "magic"; }), std::make_pair(422, std::string("mode")));
  EXPECT_EQ(with([](json& d) { d["effective_mass"] = -1; }), std::make_pair(422, std::string("effective_mass")));
  EXPECT_EQ(with([](json& d) { d["effective_mass"] = nullptr; }), std::make_pair(422, std::string("effective_mass")));
  EXPECT_EQ(with([](json& d) { d["damping_ration"] = 0.5; }), std::make_pair(422, std::string("damping_ration")));
  EXPECT_EQ(with([](json& d) { d["frequency_hz"] = 5; }), std::make_pair(422, std::string("response_frames")));
  EXPECT_EQ(with([](json& d) { d["constraint"] = json::object(); }), std::make_pair(422, std::string("constraint.dimension")));
  EXPECT_EQ(with([](json& d) {
              d.erase("effective_mass");
              d["constraint"] = json::parse(R"({"dimension": 2, "body_a": "static", "body_b": {"mass": -2},
                                                 "anchor_a": [0, 0], "anchor_b": [0, 0], "axis": [1, 0]})");
            }),
            std::make_pair(422, std::string("constraint.body_b.mass")));
  EXPECT_EQ(with([](json& d) {
              d.erase("effective_mass");
              d["constraint"] = json::parse(R"({"dimension": 2, "body_a": "static", "body_b": {"mass": 2},
                                                 "anchor_a": [0, 0], "anchor_b": [0, 0], "axis": [1]})");
            }),
            std::make_pair(422, std::string("constraint.axis")));
  EXPECT_EQ(problem_of(json::array()).first, 422);
}

// The chain question: each named solver answers with its limit and the fewest counts; bad fields are named.
TEST(TuneCodec, ChainAnswersPerSolverAndNamesBadFields) {
  json doc = base();
  doc["chain"] = {{"mass_ratio", 1000}, {"solvers", {"box2d_v2_4", "rapier"}}};
  doc["engine_settings"] = {{"box2d_v2_4", {{"velocityIterations", 1}}}};
  const json out = run_tune(doc);
  const json& chain = out.at("chain");
  EXPECT_EQ(chain.at("solvers").size(), 2u);
  const json& b = chain.at("solvers").at("box2d_v2_4");
  EXPECT_EQ(b.at("count"), 1);  // the request's velocityIterations
  EXPECT_EQ(b.at("count_name"), "velocityIterations");
  EXPECT_TRUE(b.at("confirmed").get<bool>());
  EXPECT_DOUBLE_EQ(chain.at("margin").get<double>(), 1.25);
  EXPECT_FALSE(base().contains("chain"));
  EXPECT_FALSE(run_tune(base()).contains("chain"));
  EXPECT_EQ(with([](json& d) { d["chain"] = {{"margin", 2}}; }), std::make_pair(422, std::string("chain.mass_ratio")));
  EXPECT_EQ(with([](json& d) { d["chain"] = {{"mass_ratio", 0.5}}; }), std::make_pair(422, std::string("chain.mass_ratio")));
  EXPECT_EQ(with([](json& d) { d["chain"] = {{"mass_ratio", 10}, {"margin", 11}}; }), std::make_pair(422, std::string("chain.margin")));
  EXPECT_EQ(with([](json& d) { d["chain"] = {{"mass_ratio", 10}, {"solvers", {"ode"}}}; }),
            std::make_pair(422, std::string("chain.solvers.0")));
  EXPECT_EQ(with([](json& d) { d["chain"] = {{"mass_ratio", 10}, {"links", 3}}; }), std::make_pair(422, std::string("chain.links")));
}
