// The check use case: which rates a preset runs at, shards, the thread pool's order, and the physics of a
// preset moved to another rate (the tuning is in seconds, so the same motion at every fps).
#include "app/check_app.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "app/preset_store.h"
#include "codec/problem.h"
#include "codec/scene_codec.h"

namespace softtune::app {
namespace {

using nlohmann::json;

CheckInput preset_input(const std::string& name) { return {name, load_preset(SOFTTUNE_PRESETS_DIR, name), std::nullopt}; }

std::optional<double> figure(const CaseResult& c, const std::string& name) {
  for (const Figure& f : c.figures) {
    if (f.name == name) return f.value;
  }
  ADD_FAILURE() << "no figure " << name;
  return std::nullopt;
}

TEST(CheckApp, RatesComeFromTheOptionsElseThePresetElseItsWorld) {
  scene::Scene s = codec::decode_scene(load_preset(SOFTTUNE_PRESETS_DIR, "stiff"));
  ASSERT_TRUE(s.rates.fps.empty());
  auto rates = check_rates(s, {});
  ASSERT_EQ(rates.size(), 1u);
  EXPECT_EQ(rates[0].fps, s.world.fps);
  EXPECT_EQ(rates[0].substeps, s.world.substeps);

  s.rates.fps = {30, 60};
  s.rates.substeps = {1, 4};
  rates = check_rates(s, {});
  ASSERT_EQ(rates.size(), 4u);  // fps-major: 30x1, 30x4, 60x1, 60x4
  EXPECT_EQ(rates[1].fps, 30);
  EXPECT_EQ(rates[1].substeps, 4);
  EXPECT_EQ(rates[2].fps, 60);

  CheckOptions o;
  o.fps = {144, 144, 120};  // a repeated rate is checked once
  rates = check_rates(s, o);
  ASSERT_EQ(rates.size(), 4u);
  EXPECT_EQ(rates[0].fps, 144);
  EXPECT_EQ(rates[2].fps, 120);
}

// The mouse drag is tuned 30 frames of 60 fps = 2 Hz, zeta 0.5, exact mode. At every rate the measured
// frequency is the request, and the 2 % settle time is the continuous one, -ln(0.02 sqrt(1 - zeta^2)) /
// (zeta omega) = 0.6455 s, to within a frame: the preset means the same motion at 30 and at 144 fps.
TEST(CheckApp, APresetAtAnotherRateKeepsItsMotionInSeconds) {
  CheckOptions o;
  o.fps = {30, 144};
  const CheckReport r = run_checks({preset_input("mouse")}, o);
  ASSERT_EQ(r.cases.size(), 2u);
  const double zeta = 0.5, omega = 2.0 * std::numbers::pi * 2.0;
  const double settle = -std::log(0.02 * std::sqrt(1 - zeta * zeta)) / (zeta * omega);
  for (const CaseResult& c : r.cases) {
    SCOPED_TRACE(case_key(c.preset, c.rate));
    EXPECT_TRUE(c.passed);
    EXPECT_NEAR(*figure(c, "drag.frequency_hz"), 2.0, 1e-4);
    EXPECT_NEAR(*figure(c, "drag.damping_ratio"), 0.5, 1e-4);
    EXPECT_NEAR(*figure(c, "drag.settle_s"), settle, 1.0 / c.rate.fps + 1e-9);
    // settle_frames counts frames of the rate it ran at
    EXPECT_NEAR(*figure(c, "drag.settle_frames"), *figure(c, "drag.settle_s") * c.rate.fps, 1e-9);
  }
  EXPECT_EQ(r.cases[0].rate.fps, 30);
  EXPECT_EQ(case_key("mouse", r.cases[1].rate), "mouse@144x1");
}

// The chain's pins stretch as h^2 (docs/scenes.md): at 30 fps it is four times the stretch at 60 and fails
// the 3 cm bound that 60 fps meets; the report names the expectation and the figure.
TEST(CheckApp, ThePresetThatPassesAt60FailsAt30) {
  CheckOptions o;
  o.fps = {30, 60};
  const CheckReport r = run_checks({preset_input("chain")}, o);
  ASSERT_EQ(r.cases.size(), 2u);
  EXPECT_FALSE(r.passed);
  EXPECT_FALSE(r.cases[0].passed);
  EXPECT_TRUE(r.cases[1].passed);
  const double e30 = *figure(r.cases[0], "max_constraint_error"), e60 = *figure(r.cases[1], "max_constraint_error");
  EXPECT_NEAR(e30 / e60, 4.0, 1.0);
  const auto messages = failure_messages(r.cases[0]);
  ASSERT_EQ(messages.size(), 1u);
  EXPECT_NE(messages[0].find("max_constraint_error = "), std::string::npos) << messages[0];
  EXPECT_NE(messages[0].find("above max 0.03"), std::string::npos) << messages[0];
}

TEST(CheckApp, AnExpectationStatedForOneRateIsCheckedOnlyThere) {
  CheckOptions o;
  o.fps = {30, 60};
  const CheckReport r = run_checks({preset_input("oscillator")}, o);
  ASSERT_EQ(r.cases.size(), 2u);
  auto has_soft = [](const CaseResult& c) {
    for (const json& e : c.expectations) {
      if (e["probe"] == "soft") return true;
    }
    return false;
  };
  EXPECT_FALSE(has_soft(r.cases[0]));  // implicit Euler's 5.4 % is a 60 fps figure
  EXPECT_TRUE(has_soft(r.cases[1]));
  EXPECT_TRUE(r.passed);
}

TEST(CheckApp, ShardsSplitThePresetsByNameWhateverTheInputOrder) {
  std::vector<CheckInput> inputs;
  for (const char* n : {"g", "c", "a", "f", "b", "e", "d"}) inputs.push_back({n, json(), std::nullopt});
  std::vector<std::string> seen;
  for (int i = 1; i <= 3; ++i) {
    for (const CheckInput& in : shard_inputs(inputs, {i, 3})) seen.push_back(in.name);
  }
  EXPECT_EQ(seen, (std::vector<std::string>{"a", "d", "g", "b", "e", "c", "f"}));
  std::reverse(inputs.begin(), inputs.end());
  EXPECT_EQ(shard_inputs(inputs, {2, 3}).size(), 2u);
  EXPECT_EQ(shard_inputs(inputs, {2, 3})[0].name, "b");
}

// Two threads give the very same report as one (every figure bit for bit, in the same order), and a
// preset that cannot be read fails its own case without stopping the others.
TEST(CheckApp, ThePoolKeepsTheOrderAndABrokenPresetFailsAlone) {
  std::vector<CheckInput> inputs = {preset_input("oscillator"), preset_input("mouse")};
  inputs.push_back({"broken", json(), json{{"detail", "presets/broken.json: /world is required"}}});
  CheckOptions o;
  o.fps = {30, 60};
  const CheckReport one = run_checks(inputs, o);
  o.jobs = 2;
  const CheckReport two = run_checks(inputs, o);
  json a = check_report_json(one), b = check_report_json(two);
  EXPECT_EQ(a.dump(), b.dump());
  ASSERT_EQ(one.cases.size(), 5u);
  EXPECT_EQ(one.cases[0].preset, "broken");  // sorted by name
  EXPECT_FALSE(one.cases[0].passed);
  EXPECT_EQ(failure_messages(one.cases[0]).at(0), "presets/broken.json: /world is required");
  EXPECT_EQ(case_key("broken", one.cases[0].rate), "broken");
  for (std::size_t i = 1; i < one.cases.size(); ++i) EXPECT_TRUE(one.cases[i].passed) << i;
  EXPECT_FALSE(one.passed);
}

TEST(CheckApp, PathsAreDirectoriesOrFiles) {
  const auto all = presets_from_paths({SOFTTUNE_PRESETS_DIR}, SOFTTUNE_PRESETS_DIR);
  EXPECT_EQ(all.size(), list_presets(SOFTTUNE_PRESETS_DIR).size());
  const auto one = presets_from_paths({std::string(SOFTTUNE_PRESETS_DIR) + "/mouse.json"}, SOFTTUNE_PRESETS_DIR);
  ASSERT_EQ(one.size(), 1u);
  EXPECT_EQ(one[0].name, "mouse");
  EXPECT_FALSE(one[0].problem);
  EXPECT_THROW(presets_from_paths({SOFTTUNE_PRESETS_DIR, std::string(SOFTTUNE_PRESETS_DIR) + "/mouse.json"}, SOFTTUNE_PRESETS_DIR),
               codec::Problem);  // mouse twice
  EXPECT_THROW(presets_from_paths({"/nonexistent/presets"}, SOFTTUNE_PRESETS_DIR), codec::Problem);
}

}  // namespace
}  // namespace softtune::app
