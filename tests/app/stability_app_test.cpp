// The stability use case (stability_app.cpp): a custom sweep with every field, predicted = observed, the chain
// left out when asked, and the SVG maps.
#include "app/stability_app.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "../codec/stability_sweeps.h"

namespace softtune::codec {
namespace {

using app::run_stability;
using app::stability_svg;

using nlohmann::json;

using test::small_sweep;

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
  EXPECT_EQ(chain.at("limits").size(), 4u * 2u * 2u * 2u);  // solvers x ratios x iterations x warm start
  EXPECT_EQ(chain.at("mismatches"), 0);
  EXPECT_EQ(chain.at("unconfirmed_limits"), 0);
  for (const json& l : chain.at("limits")) {
    // A found limit is a bracket no wider than the tolerance, confirmed by simulating both sides.
    if (l.at("limit") != "found") continue;
    const double lo = l.at("highest_stable_frequency_ratio"), hi = l.at("lowest_unstable_frequency_ratio");
    EXPECT_LE(hi / lo - 1.0, chain.at("limit_relative_tolerance").get<double>());
    EXPECT_EQ(l.at("observed_unstable_side"), "unstable");
    EXPECT_NE(l.at("observed_stable_side"), "unstable");
  }
  // Semi-implicit Euler's limit from the step limits: omega h = 2 at zeta 0 (explicit_euler is not asked).
  bool soft_seen = false;
  for (const json& l : out.at("step_limits").at("limits")) {
    EXPECT_NE(l.at("method"), "semi_implicit_euler");
    if (l.at("method") == "soft") {
      EXPECT_EQ(l.at("limit"), "none_in_range");
      soft_seen = true;
    }
  }
  EXPECT_TRUE(soft_seen);
  const json stages = out.at("stages");
  EXPECT_NE(std::find(stages.begin(), stages.end(), json("sequential_impulse_chain")), stages.end()) << stages.dump();
}

TEST(StabilityCodec, ChainCanBeLeftOut) {
  json request = small_sweep();
  request["chain"] = false;
  request["include_cases"] = false;
  const json out = run_stability(request);
  EXPECT_FALSE(out.contains("chain"));
  EXPECT_FALSE(out.contains("cases"));
}

TEST(StabilityCodec, SvgHasMapsAndChain) {
  json request = small_sweep();
  request["include_cases"] = false;
  const std::string svg = stability_svg(run_stability(request));
  for (const char* text : {"Stability map at zeta = 0:", "Stability map at zeta = 10:", "highest stable f h",
                           "1 iterations, warm start", "semi_implicit_euler",
                           "Chain in box2d_v3", "4 substeps, warm start"}) {
    EXPECT_NE(svg.find(text), std::string::npos) << text;
  }
}

}  // namespace
}  // namespace softtune::codec
