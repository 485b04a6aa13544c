// Writing core types as JSON (json_writer.cpp): no NaN or infinity reaches the output (null instead),
// warnings carry their code and message, stages their names in order, engine values their kind.
#include "codec/json_writer.h"

#include <gtest/gtest.h>

#include <limits>

using nlohmann::json;
using namespace softtune;
using namespace softtune::codec;

TEST(JsonWriter, NonFiniteNumbersAreNull) {
  EXPECT_EQ(number_or_null(1.5), json(1.5));
  EXPECT_TRUE(number_or_null(std::numeric_limits<double>::quiet_NaN()).is_null());
  EXPECT_TRUE(number_or_null(std::numeric_limits<double>::infinity()).is_null());
  EXPECT_TRUE(number_or_null(-std::numeric_limits<double>::infinity()).is_null());
  EXPECT_TRUE(number_or_null(std::optional<double>()).is_null());
  EXPECT_EQ(number_or_null(std::optional<double>(-2.0)), json(-2.0));
  // Dumped, a document with a NaN in it is still valid JSON.
  EXPECT_NO_THROW(json::parse(json{{"k", number_or_null(std::nan(""))}}.dump()));
}

TEST(JsonWriter, WarningsCarryCodeMessageAndEngine) {
  const json w = warnings_json({{WarningCode::no_constraint}, {WarningCode::engine_note, 0, 0, "ode"}});
  ASSERT_EQ(w.size(), 2u);
  EXPECT_EQ(w[0]["code"], "no_constraint");
  EXPECT_TRUE(w[0]["message"].is_string());
  EXPECT_FALSE(w[0].contains("engine"));
  EXPECT_EQ(w[1]["engine"], "ode");
  EXPECT_TRUE(warnings_json({}).is_array());
  EXPECT_TRUE(warnings_json({}).empty());
}

TEST(JsonWriter, StagesInTheOrderTheyRan) {
  StageList stages;
  stages.add(Stage::validate);
  stages.add(Stage::designer_mapping);
  const json s = stages_json(stages);
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[0], "validate");
  EXPECT_EQ(s[1], "designer_mapping");
}

TEST(JsonWriter, EngineValuesAreNumbersChoicesOrSwitches) {
  const engines::Parameters values = {
      {"erp", 0.2}, {"solver", 0.0, {}, "pgs"}, {"warm_start", 0.0, {}, "true"}, {"split", 0.0, {}, "false"},
      {"cfm", std::numeric_limits<double>::infinity()}};
  const json v = engine_values_json(values);
  EXPECT_EQ(v["erp"], json(0.2));
  EXPECT_EQ(v["solver"], "pgs");
  EXPECT_EQ(v["warm_start"], json(true));
  EXPECT_EQ(v["split"], json(false));
  EXPECT_TRUE(v["cfm"].is_null());
  engines::Prediction p;
  p.frequency_hz = 5.0;
  p.stable = true;
  const json pj = engine_prediction_json(p);
  EXPECT_EQ(pj["frequency_hz"], json(5.0));
  EXPECT_TRUE(pj["damping_ratio"].is_null());
  EXPECT_EQ(pj["stable"], json(true));
}
