// The accuracy contract: fields, validation Problems naming the field, no NaN/infinity, CSV and SVG.
#include "codec/accuracy_codec.h"
#include "app/accuracy_app.h"

#include <gtest/gtest.h>

#include "box2d_spring.h"
#include "codec/problem.h"

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

void expect_problem(json request, const std::string& field) {
  try {
    decode_accuracy_request(request);
    ADD_FAILURE() << "accepted " << request.dump();
  } catch (const Problem& p) {
    EXPECT_EQ(p.status, 422);
    EXPECT_EQ(p.field, field) << p.detail;
    EXPECT_FALSE(p.detail.empty());
  }
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

TEST(AccuracyCodec, RequestFpsAndSubstepsJoinTheGrid) {
  json request = ten_hz_free();
  request["fps"] = 50.0;
  request["substeps"] = 3;
  request["step_rates"] = {60, 120};
  const AccuracyRequest q = decode_accuracy_request(request);
  EXPECT_EQ(q.settings.step_rates_hz, (std::vector<double>{50, 60, 120}));
  EXPECT_EQ(q.settings.soft_substeps, (std::vector<int>{1, 2, 3, 4, 8}));
}

TEST(AccuracyCodec, NoConfigurationMeetsATinyBudget) {
  json request = ten_hz_free();
  request["error_budget"] = 1e-9;
  request["step_rates"] = {30};
  const json out = run_accuracy(request);
  EXPECT_TRUE(out.at("recommendation").at("row").is_null());
  EXPECT_NE(out.at("recommendation").at("reason").get<std::string>().find("no configuration"), std::string::npos);
}

TEST(AccuracyCodec, BadFieldsNameTheField) {
  auto with = [](const char* key, json value) {
    json r = ten_hz_free();
    r[key] = std::move(value);
    return r;
  };
  expect_problem(with("error_budget", -1), "error_budget");
  expect_problem(with("error_budget", "5%"), "error_budget");
  expect_problem(with("step_rates", json::array()), "step_rates");
  expect_problem(with("step_rates", {60, -5}), "step_rates[1]");
  expect_problem(with("soft_substeps", {2, 0}), "soft_substeps[1]");
  expect_problem(with("duration_s", 0.1), "duration_s");  // shorter than 3 periods of 10 Hz
  expect_problem(with("duration_s", 1e6), "duration_s");  // too many steps
  expect_problem(with("timing_repeats", 0), "timing_repeats");
  expect_problem(with("box2d", "yes"), "box2d");
  expect_problem(with("error_budjet", 0.1), "error_budjet");  // unknown fields are refused
  expect_problem(with("fps", 0), "fps");                       // the tune part is validated too
  json slow = ten_hz_free();
  slow["frequency_hz"] = 1e-4;  // 3 periods = 30000 s: too many steps
  expect_problem(slow, "frequency_hz");
  json fast = ten_hz_free();
  fast["frequency_hz"] = 0.5;
  fast["fps"] = 100000.0;  // the request's own rate is the top one
  expect_problem(fast, "fps");
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

namespace softtune::codec {
namespace {

// 45 Hz at 30 fps: 3 periods would be 2 frames; the default covers 8 frames of the lowest rate.
TEST(AccuracyCodec, FastSpringAtLowRateGetsEnoughFrames) {
  json request = {{"frequency_hz", 45.0}, {"oscillation", "free"}, {"effective_mass", 1.0}, {"fps", 60.0}};
  const AccuracyRequest q = decode_accuracy_request(request);
  EXPECT_NEAR(q.settings.duration_s, 8.0 / 30.0, 1e-12);
  request["duration_s"] = 0.1;  // 4.5 periods: allowed when asked for
  EXPECT_NEAR(decode_accuracy_request(request).settings.duration_s, 0.1, 1e-12);
}

}  // namespace
}  // namespace softtune::codec
