// The stability contract: a custom sweep, its fields, and Problems naming the field.
#include "codec/stability_codec.h"
#include "app/stability_app.h"

#include <gtest/gtest.h>

#include "codec/problem.h"

namespace softtune::codec {
namespace {

using app::run_stability;
using app::stability_svg;

using nlohmann::json;

json small_sweep() {
  return {{"methods", {"explicit_euler", "soft"}},
          {"frequency_ratios", {0.01, 0.3, 2.0}},
          {"stiffnesses", {1e12}},
          {"damping_ratios", {0.0, 1.0}},
          {"masses", {1e-6, 1.0}},
          {"steps", {1e-3, 0.1}},
          {"chain", {{"mass_ratios", {1, 1000}}, {"iterations", {1, 4}}, {"frequency_ratios", {0.01, 0.1, 1.0}}}}};
}

TEST(StabilityCodec, CustomSweepHasEveryField) {
  const json out = run_stability(small_sweep());
  const json& s = out.at("summary");
  EXPECT_EQ(s.at("cases"), out.at("cases").size());
  EXPECT_EQ(s.at("mismatches"), 0);
  EXPECT_EQ(s.at("soft_blowups"), 0);
  EXPECT_TRUE(s.at("passed").get<bool>());
  for (const json& c : out.at("cases")) {
    for (const char* key : {"method", "frequency_ratio", "damping_ratio", "mass", "stiffness", "h", "spectral_radius",
                            "predicted_stable", "observed_stable", "warnings"}) {
      EXPECT_TRUE(c.contains(key)) << key;
    }
    EXPECT_EQ(c.at("predicted_stable"), c.at("observed_stable"));
    if (c.at("method") == "soft") {
      EXPECT_TRUE(c.at("observed_stable").get<bool>());
    }
  }
  const json& chain = out.at("chain");
  EXPECT_EQ(chain.at("limits").size(), 2u * 2u * 2u);  // ratios x iterations x warm start
  EXPECT_EQ(chain.at("mismatches"), 0);
  const json stages = out.at("stages");
  EXPECT_NE(std::find(stages.begin(), stages.end(), "sequential_impulse_chain"), stages.end());
}

TEST(StabilityCodec, ChainCanBeLeftOut) {
  json request = small_sweep();
  request["chain"] = false;
  request["include_cases"] = false;
  const json out = run_stability(request);
  EXPECT_FALSE(out.contains("chain"));
  EXPECT_FALSE(out.contains("cases"));
}

TEST(StabilityCodec, BadFieldsNameTheField) {
  auto expect_problem = [](const char* key, json value, const std::string& field) {
    json r = small_sweep();
    r[key] = std::move(value);
    try {
      run_stability(r);
      ADD_FAILURE() << "accepted " << key;
    } catch (const Problem& p) {
      EXPECT_EQ(p.status, 422);
      EXPECT_EQ(p.field, field);
    }
  };
  expect_problem("methods", {"soft", "rk4"}, "methods[1]");
  expect_problem("masses", {0.0}, "masses[0]");
  expect_problem("steps", {1.0 / 60, 5.0}, "steps[1]");
  expect_problem("observe_steps", 10, "observe_steps");
  expect_problem("chain", {{"iterations", {0}}}, "chain.iterations[0]");
  expect_problem("frequency_ratios", json::array(), "frequency_ratios");
  expect_problem("colour", 1, "colour");
}

TEST(StabilityCodec, SvgHasMapsAndChain) {
  json request = small_sweep();
  request["include_cases"] = false;
  const std::string svg = stability_svg(run_stability(request));
  for (const char* text : {"Stability map at zeta = 0:", "Stability map at zeta = 10:", "highest stable f h",
                           "1 iterations, warm start", "semi_implicit_euler"}) {
    EXPECT_NE(svg.find(text), std::string::npos) << text;
  }
}

}  // namespace
}  // namespace softtune::codec
