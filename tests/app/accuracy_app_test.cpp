// The accuracy use case (accuracy_app.cpp): every field of the report, the Box2D row and stage only when it ran,
// the recommendation within the budget, no NaN/infinity, CSV and SVG.
#include "app/accuracy_app.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "box2d_spring.h"

namespace softtune::codec {
namespace {

using app::accuracy_csv;
using app::accuracy_svg;
using app::run_accuracy;
using app::run_accuracy_report;

using nlohmann::json;

json ten_hz_free() {
  return {{"frequency_hz", 10.0}, {"oscillation", "free"}, {"effective_mass", 1.0}, {"fps", 60.0}};
}

// Every number in the document is finite (json cannot hold NaN, but nlohmann would store it as a float).
void expect_all_finite(const json& j) {
  if (j.is_number_float()) {
    EXPECT_TRUE(std::isfinite(j.get<double>()));
  }
  if (j.is_structured()) {
    for (const json& e : j) expect_all_finite(e);
  }
}

TEST(AccuracyCodec, DefaultRequestHasEveryField) {
  const EngineRunner box2d{kBox2DRowName, run_box2d_spring};
  const json out = run_accuracy(ten_hz_free(), box2d);
  EXPECT_NEAR(out.at("duration_s").get<double>(), 0.3, 1e-12);
  EXPECT_EQ(out.at("error_budget"), 0.05);
  // 5 rates (60 is among them) x (3 + 2 x 4) + one Box2D row per rate.
  ASSERT_EQ(out.at("rows").size(), 5u * 12u);
  for (const json& row : out.at("rows")) {
    for (const char* key : {"method", "fps", "substeps", "max_error", "rms_error", "achieved_frequency_hz",
                            "achieved_damping_ratio", "blew_up", "cpu_seconds_per_sim_second"}) {
      EXPECT_TRUE(row.contains(key)) << key;
    }
    EXPECT_TRUE(row.at("achieved_frequency_hz").contains("poles"));
    EXPECT_TRUE(row.at("achieved_frequency_hz").contains("trajectory"));
    // Errors are null exactly when the run blew up.
    EXPECT_EQ(row.at("max_error").is_null(), row.at("blew_up").get<bool>());
  }
  const json& rec = out.at("recommendation");
  EXPECT_TRUE(rec.at("reason").is_string());
  ASSERT_FALSE(rec.at("row").is_null());
  EXPECT_LE(out.at("rows").at(rec.at("row").get<std::size_t>()).at("max_error").get<double>(), 0.05);
  const json stages = out.at("stages");
  EXPECT_NE(std::find(stages.begin(), stages.end(), "box2d_distance_joint"), stages.end());
  expect_all_finite(out);
}

TEST(AccuracyCodec, Box2DStageOnlyWhenItRan) {
  json request = ten_hz_free();
  request["step_rates"] = {60};
  const json without_runner = run_accuracy(request);
  const json stages = without_runner.at("stages");
  EXPECT_EQ(std::find(stages.begin(), stages.end(), "box2d_distance_joint"), stages.end());
  request["box2d"] = false;
  const json off = run_accuracy(request, EngineRunner{kBox2DRowName, run_box2d_spring});
  for (const json& row : off.at("rows")) EXPECT_NE(row.at("method"), kBox2DRowName);
}

TEST(AccuracyCodec, NoConfigurationMeetsATinyBudget) {
  json request = ten_hz_free();
  request["error_budget"] = 1e-9;
  request["step_rates"] = {30};
  const json out = run_accuracy(request);
  EXPECT_TRUE(out.at("recommendation").at("row").is_null());
  EXPECT_NE(out.at("recommendation").at("reason").get<std::string>().find("no configuration"), std::string::npos);
}

TEST(AccuracyCodec, NoSpringRunsOneSecond) {
  json request = ten_hz_free();
  request["frequency_hz"] = 0.0;
  request["step_rates"] = {60};
  const json out = run_accuracy(request);
  EXPECT_EQ(out.at("duration_s"), 1.0);
  for (const json& row : out.at("rows")) EXPECT_NEAR(row.at("max_error").get<double>(), 0.0, 1e-15);
  expect_all_finite(out);
}

TEST(AccuracyCodec, CsvHasAHeaderAndOneLinePerRow) {
  json request = ten_hz_free();
  request["step_rates"] = {60, 120};
  const json out = run_accuracy(request);
  const std::string csv = accuracy_csv(out);
  EXPECT_EQ(csv.rfind("method,fps,substeps,h,frames,max_error,rms_error,achieved_frequency_hz_poles,", 0), 0u);
  std::size_t lines = 0;
  for (char c : csv) lines += c == '\n';
  EXPECT_EQ(lines, 1 + out.at("rows").size());
  EXPECT_NE(csv.find("explicit_euler,60,1,"), std::string::npos);
  EXPECT_NE(csv.find(",true,"), std::string::npos);  // explicit Euler blew up
}

TEST(AccuracyCodec, SvgHasTheFourPlots) {
  const AccuracyRequest q = decode_accuracy_request(ten_hz_free());
  const std::string svg = accuracy_svg(q, run_accuracy_report(q, EngineRunner{kBox2DRowName, run_box2d_spring}));
  for (const char* text : {"<svg", "Response at 60 fps", "Error over time", "Work-precision", "Stability map",
                           "box2d_distance_joint", "soft_exact x8 substeps", "CPU time per simulated second (s)"}) {
    EXPECT_NE(svg.find(text), std::string::npos) << text;
  }
  EXPECT_EQ(svg.find("nan"), std::string::npos);
  EXPECT_EQ(svg.find("inf"), std::string::npos);
}

}  // namespace
}  // namespace softtune::codec
