// docs/preset-ci.md's examples work: the studio preset (crane_hook.json) is valid against presets/schema.json
// and passes at each of the eight rates it declares, and the baseline example is a baseline document.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "app/check_app.h"
#include "app/preset_store.h"
#include "codec/json_reader.h"

namespace softtune::app {
namespace {

// The ```json block after the marker "<!-- preset-ci: NAME -->".
nlohmann::json doc_block(const std::string& name) {
  std::ifstream in(SOFTTUNE_SOURCE_DIR "/docs/preset-ci.md");
  std::stringstream text;
  text << in.rdbuf();
  const std::string doc = text.str(), marker = "<!-- preset-ci: " + name + " -->\n```json\n";
  const auto start = doc.find(marker);
  if (start == std::string::npos) throw std::runtime_error("no block " + name);
  const auto begin = start + marker.size();
  return codec::parse_json(doc.substr(begin, doc.find("```", begin) - begin));
}

TEST(PresetCiDoc, TheStudioPresetPassesAtEveryRateItDeclares) {
  const nlohmann::json preset = doc_block("crane_hook.json");
  validate_preset(preset, load_schema(SOFTTUNE_SOURCE_DIR "/presets"), "docs/preset-ci.md");
  const CheckReport r = run_checks({{"crane_hook", preset, std::nullopt}}, {});
  ASSERT_EQ(r.cases.size(), 8u);
  for (const CaseResult& c : r.cases) {
    EXPECT_TRUE(c.passed) << case_key(c.preset, c.rate) << ": " << (failure_messages(c).empty() ? "" : failure_messages(c)[0]);
    EXPECT_EQ(c.expectations.size(), c.rate.fps == 60 ? 7u : 6u);  // settle_frames is stated for 60 fps
  }
}

TEST(PresetCiDoc, TheBaselineExampleIsABaseline) {
  const Baseline b = decode_baseline(doc_block("baseline.json"), "");
  EXPECT_EQ(tolerance_for(b, "cable.settle_frames").absolute, 3.0);
  EXPECT_EQ(tolerance_for(b, "crate_y.settle_frames").absolute, 1.0);  // the default
  EXPECT_TRUE(b.cases.contains("crane_hook@60x1"));
}

}  // namespace
}  // namespace softtune::app
