// The accuracy request decode (accuracy_codec.cpp): the step-rate grid, the default duration, Problems naming the field.
#include "codec/accuracy_codec.h"

#include <gtest/gtest.h>

#include "codec/problem.h"

namespace softtune::codec {
namespace {

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

TEST(AccuracyCodec, RequestFpsAndSubstepsJoinTheGrid) {
  json request = ten_hz_free();
  request["fps"] = 50.0;
  request["substeps"] = 3;
  request["step_rates"] = {60, 120};
  const AccuracyRequest q = decode_accuracy_request(request);
  EXPECT_EQ(q.settings.step_rates_hz, (std::vector<double>{50, 60, 120}));
  EXPECT_EQ(q.settings.soft_substeps, (std::vector<int>{1, 2, 3, 4, 8}));
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
  expect_problem(with("step_rates", {60, -5}), "step_rates.1");
  expect_problem(with("soft_substeps", {2, 0}), "soft_substeps.1");
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
