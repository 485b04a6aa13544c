// Baselines: a retuned preset drifts and the message names the figure, its baseline and its new value; an
// unchanged one matches itself exactly; tolerances as documented; the file format round-trips.
#include "app/check_baseline.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "app/check_app.h"
#include "app/preset_store.h"
#include "codec/problem.h"

namespace softtune::app {
namespace {

using nlohmann::json;

// The bar of issue 18: a copy of the mouse preset retuned from 30 frames (2 Hz) to 24 frames (2.5 Hz)
// still passes its own expectations (they are relative to the request), but its baseline comparison fails
// on the frequency with a message naming the figure, the 2 Hz baseline and the new 2.5 Hz.
TEST(CheckBaseline, ARetunedPresetDriftsFromItsBaseline) {
  const json original = load_preset(SOFTTUNE_PRESETS_DIR, "mouse");
  json retuned = original;
  ASSERT_EQ(retuned["joints"][0]["response_frames"], 30);
  retuned["joints"][0]["response_frames"] = 24;

  const Baseline recorded = updated_baseline(run_checks({{"mouse", original, std::nullopt}}, {}), {});
  ASSERT_TRUE(recorded.cases.contains("mouse@60x1"));
  EXPECT_NEAR(*recorded.cases.at("mouse@60x1").at("drag.frequency_hz"), 2.0, 1e-4);

  CheckOptions o;
  o.baseline = &recorded;
  const CheckReport same = run_checks({{"mouse", original, std::nullopt}}, o);
  EXPECT_TRUE(same.passed);
  EXPECT_TRUE(same.cases.at(0).drift.empty());
  EXPECT_TRUE(same.cases.at(0).in_baseline);

  const CheckReport changed = run_checks({{"mouse", retuned, std::nullopt}}, o);
  const CaseResult& c = changed.cases.at(0);
  EXPECT_FALSE(changed.passed);
  for (const json& e : c.expectations) EXPECT_TRUE(e["passed"].get<bool>()) << e.dump();
  const auto drift = std::find_if(c.drift.begin(), c.drift.end(), [](const Drift& d) { return d.figure == "drag.frequency_hz"; });
  ASSERT_NE(drift, c.drift.end());
  EXPECT_NEAR(*drift->baseline, 2.0, 1e-4);
  EXPECT_NEAR(*drift->value, 2.5, 1e-4);
  const std::string message = drift_message(*drift);
  EXPECT_EQ(message.rfind("drag.frequency_hz: baseline 2, now 2.5", 0), 0u) << message;
  const auto messages = failure_messages(c);
  EXPECT_NE(std::find(messages.begin(), messages.end(), "drift " + message), messages.end());
}

TEST(CheckBaseline, ToleranceIsAbsolutePlusRelative) {
  Baseline b;
  b.cases["p@60x1"] = {{"x.frequency_hz", 3.0}, {"x.settle_frames", 40.0}, {"finite", 1.0}, {"x.overshoot", std::nullopt}};
  // default: frequency 1 % (+1e-6), settle 1 frame, finite exact
  EXPECT_TRUE(compare_with_baseline(b, "p@60x1", {{"x.frequency_hz", 3.029}, {"x.settle_frames", 41.0}, {"finite", 1.0}, {"x.overshoot", std::nullopt}}).empty());
  auto d = compare_with_baseline(b, "p@60x1", {{"x.frequency_hz", 2.7}, {"x.settle_frames", 42.0}, {"finite", 0.0}, {"x.overshoot", 0.1}});
  ASSERT_EQ(d.size(), 4u);
  EXPECT_EQ(d[0].figure, "x.frequency_hz");  // in the order measured
  EXPECT_EQ(drift_message(d[0]), "x.frequency_hz: baseline 3, now 2.7 (tolerance 0.030001)");
  EXPECT_EQ(drift_message(d[3]), "x.overshoot: baseline undefined, now 0.1");
  // a studio's own tolerance: by kind, and for one figure by its full name
  b.tolerances["frequency_hz"] = {0.0, 0.2};
  b.tolerances["x.settle_frames"] = {5.0, 0.0};
  d = compare_with_baseline(b, "p@60x1", {{"x.frequency_hz", 2.7}, {"x.settle_frames", 44.0}});
  ASSERT_EQ(d.size(), 2u);  // within the new tolerances; finite and x.overshoot are no longer measured
  EXPECT_TRUE(d[0].missing && d[1].missing);
  // a probe that is gone is a drift; a case without an entry has nothing to compare
  d = compare_with_baseline(b, "p@60x1", {});
  EXPECT_EQ(d.size(), 4u);
  EXPECT_TRUE(d[0].missing);
  EXPECT_TRUE(compare_with_baseline(b, "q@60x1", {{"finite", 0.0}}).empty());
}

TEST(CheckBaseline, TheFileRoundTripsAndBadDocumentsNameTheField) {
  Baseline b;
  b.cases["mouse@60x1"] = {{"drag.frequency_hz", 2.0}, {"drag.settle_frames", std::nullopt}};
  b.tolerances["drag.frequency_hz"] = {0.001, 0.05};
  const json doc = encode_baseline(b);
  EXPECT_EQ(doc["tolerances"]["settle_frames"]["absolute"], 1.0);  // the defaults in use are written out
  const Baseline back = decode_baseline(doc, "");
  EXPECT_EQ(back.cases, b.cases);
  EXPECT_EQ(back.tolerances.at("drag.frequency_hz").relative, 0.05);

  const auto path = std::filesystem::temp_directory_path() / "softtune_check_baseline_test.json";
  write_baseline_file(path.string(), b);
  EXPECT_EQ(read_baseline_file(path.string()).cases, b.cases);
  std::filesystem::remove(path);

  auto field_of = [](const json& d) {
    try {
      decode_baseline(d, "baseline");
    } catch (const codec::Problem& p) {
      return p.field;
    }
    return std::string("(accepted)");
  };
  EXPECT_EQ(field_of({{"cases", json::object()}}), "baseline.softtune_baseline");
  EXPECT_EQ(field_of({{"softtune_baseline", 1}, {"cases", {{"m@60x1", {{"f", "x"}}}}}}), "baseline.cases.m@60x1.f");
  EXPECT_EQ(field_of({{"softtune_baseline", 1}, {"tolerances", {{"f", {{"relative", -1}}}}}}), "baseline.tolerances.f.relative");
  EXPECT_EQ(field_of({{"softtune_baseline", 1}, {"extra", 1}}), "baseline.extra");
  EXPECT_THROW(read_baseline_file("/nonexistent/baseline.json"), codec::Problem);
}

}  // namespace
}  // namespace softtune::app
