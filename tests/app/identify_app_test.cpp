// The identify use case end to end on JSON and CSV requests: bad series are 422s naming the row and column,
// and a recording of a known oscillator answers its frequency, damping ratio, the error against the request
// and the correction (the modelled engine's exact, and the scaled values for any engine).
#include "app/identify_app.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <sstream>

#include "codec/identify_codec.h"
#include "codec/problem.h"
#include "softtune/analytic.h"

namespace softtune::app {
namespace {

using nlohmann::json;

// The analytic oscillator at f Hz, ratio zeta, sampled at 60 Hz for `rows` rows, as CSV.
std::string oscillator_csv(double f, double zeta, int rows) {
  std::ostringstream out;
  out.precision(12);
  out << "time,x\n";
  for (int n = 0; n < rows; ++n) {
    out << n / 60.0 << "," << analytic_state({0.01, 0.0}, 2.0 * std::numbers::pi * f, zeta, n / 60.0).x << "\n";
  }
  return out.str();
}

std::string identify_problem(const json& request) {
  try {
    run_identify(request);
  } catch (const codec::Problem& p) {
    return std::to_string(p.status) + " " + p.field + ": " + p.detail;
  }
  return "no problem";
}

TEST(IdentifyApp, CsvRecordingAgainstItsRequest) {
  const json answer = run_identify({{"csv", oscillator_csv(4.3, 0.61, 240)},
                                    {"request", {{"frequency_hz", 5}, {"damping_ratio", 0.5}, {"effective_mass", 2}}},
                                    {"engine", "godot"}});
  EXPECT_NEAR(answer["frequency_hz"].get<double>(), 4.3, 1e-6);
  EXPECT_NEAR(answer["damping_ratio"].get<double>(), 0.61, 1e-6);
  EXPECT_NEAR(answer["error"]["frequency"].get<double>(), 4.3 / 5 - 1, 1e-6);
  EXPECT_EQ(answer["verdict"], "ok");
  EXPECT_FALSE(answer["modelled"].get<bool>());
  // Scaled: f' = 5 x 5 / 4.3; zeta' = 0.5 + 0.5 - 0.61; k = m (2 pi f')^2.
  const json& next = answer["correction"]["next"];
  EXPECT_NEAR(next["frequency_hz"].get<double>(), 25.0 / 4.3, 1e-5);
  EXPECT_NEAR(next["damping_ratio"].get<double>(), 0.39, 1e-6);
  EXPECT_NEAR(next["k"].get<double>(), 2.0 * std::pow(2 * std::numbers::pi * 25.0 / 4.3, 2), 1e-2);
  EXPECT_TRUE(answer["exact"].is_null());
}

TEST(IdentifyApp, ModelledEngineAnswersItsExactAndTheCorrectedExport) {
  const json answer = run_identify({{"csv", oscillator_csv(4.3, 0.65, 240)},
                                    {"request", {{"frequency_hz", 5}, {"damping_ratio", 0.5}, {"effective_mass", 2}}},
                                    {"engine", "box2d_v2_4"}});
  EXPECT_TRUE(answer["modelled"].get<bool>());
  EXPECT_TRUE(answer["exact"].contains("b2DistanceJointDef::stiffness"));
  EXPECT_TRUE(answer["correction"]["parameters"].contains("b2DistanceJointDef::stiffness"));
}

TEST(IdentifyApp, SecondRecordingIteratesBySecant) {
  const json answer = run_identify({{"csv", oscillator_csv(4.8, 0.52, 240)},
                                    {"request", {{"frequency_hz", 5}, {"damping_ratio", 0.5}, {"effective_mass", 2}}},
                                    {"typed", {{"frequency_hz", 5.6}, {"damping_ratio", 0.45}}},
                                    {"previous", json::array({{{"measured", {{"frequency_hz", 4.3}, {"damping_ratio", 0.61}}},
                                                               {"typed", {{"frequency_hz", 5}, {"damping_ratio", 0.5}}}}})}});
  EXPECT_EQ(answer["correction"]["method"], "secant");
  EXPECT_EQ(answer["correction"]["rounds"], 2);
}

// A recording within 1 % / 0.02 of the request: the rounds are met, and next keeps what was typed.
TEST(IdentifyApp, CorrectionSaysWhenTheRequestIsMet) {
  const json answer = run_identify({{"csv", oscillator_csv(5.03, 0.51, 240)},
                                    {"request", {{"frequency_hz", 5}, {"damping_ratio", 0.5}, {"effective_mass", 2}}}});
  const json& c = answer["correction"];
  EXPECT_EQ(c["verdict"], "met");
  EXPECT_EQ(c["best_round"], 0);
  EXPECT_DOUBLE_EQ(c["next"]["frequency_hz"].get<double>(), 5.0);
  EXPECT_NEAR(c["expected"]["frequency_hz"].get<double>(), 5.03, 1e-3);
  EXPECT_FALSE(c["message"].get<std::string>().empty());
}

// Typed with no damping, the engine still damped 0.45 where 0.3 was asked (an implicit step's own damping):
// the correction types a negative ratio, down to -omega h / 4 at the recording's 60 Hz, unless the engine
// is said not to take one.
TEST(IdentifyApp, NegativeDampingOnlyWhereTheEngineTakesIt) {
  json request = {{"csv", oscillator_csv(8.0, 0.45, 240)},
                  {"request", {{"frequency_hz", 8}, {"damping_ratio", 0.3}, {"effective_mass", 2}}},
                  {"typed", {{"frequency_hz", 8}, {"damping_ratio", 0}}}};
  const json allowed = run_identify(request)["correction"];
  EXPECT_LT(allowed["next"]["damping_ratio"].get<double>(), 0.0);
  EXPECT_GE(allowed["next"]["damping_ratio"].get<double>(), -0.25 * 2.0 * std::numbers::pi * 8.0 / 60.0 - 1e-9);
  EXPECT_LT(allowed["next"]["c"].get<double>(), 0.0);
  request["negative_damping"] = false;
  EXPECT_EQ(run_identify(request)["correction"]["next"]["damping_ratio"].get<double>(), 0.0);
}

// The same rounds on Jolt (8 Hz / 0.3, its implicit collision step damps by itself): next's negative ratio
// is what Jolt takes (damping + h stiffness = m omega (2 zeta + omega h) > 0 down to -omega h / 4), so the
// correction gives it in Jolt's own fields, next itself: mFrequency = next Hz, mDamping = next's ratio,
// and what Jolt then does, its implicit-Euler step on k = m omega^2, c = 2 m zeta omega.
TEST(IdentifyApp, NegativeNextIsGivenInTheEnginesFieldsWhereItTakesIt) {
  const json answer = run_identify({{"csv", oscillator_csv(8.0, 0.45, 240)},
                                    {"request", {{"frequency_hz", 8}, {"damping_ratio", 0.3}, {"effective_mass", 2},
                                                 {"mode", "exact"}}},
                                    {"typed", {{"frequency_hz", 8}, {"damping_ratio", 0}}},
                                    {"engine", "jolt"}});
  const json& c = answer["correction"];
  const double f = c["next"]["frequency_hz"].get<double>(), zeta = c["next"]["damping_ratio"].get<double>();
  ASSERT_LT(zeta, 0.0);
  const double h = 1.0 / 60.0, omega = 2.0 * std::numbers::pi * f;
  ASSERT_GT(2.0 * zeta + omega * h, 0.0);  // Jolt takes it
  ASSERT_TRUE(c["parameters"].is_object()) << c.dump();
  EXPECT_EQ(c["parameters"]["SpringSettings::mMode"], "FrequencyAndDamping");
  EXPECT_NEAR(c["parameters"]["SpringSettings::mFrequency"].get<double>(), f, 1e-9 * f);
  EXPECT_NEAR(c["parameters"]["SpringSettings::mDamping"].get<double>(), zeta, 1e-9);
  // Jolt's collision step (linear damping 0.05 1/s) on m = 2, k = m omega^2, c = 2 m zeta omega: implicit
  // Euler, (m + h c + h^2 k) v1 = m a v0 - h k x0, x1 = x0 + h v1, a = 1 - 0.05 h; its poles read as
  // s = ln(z) / h.
  const double m = 2.0, k = m * omega * omega, cd = 2.0 * m * zeta * omega, a = 1.0 - 0.05 * h;
  const double d = m + h * cd + h * h * k;
  const double s10 = -h * k / d, s11 = m * a / d, s00 = 1.0 + h * s10, s01 = h * s11;
  const double tr = s00 + s11, det = s00 * s11 - s01 * s10;
  ASSERT_LT(tr * tr, 4.0 * det);  // a complex pair
  const double r = std::sqrt(det), theta = std::acos(tr / (2.0 * r));
  const double sr = std::log(r) / h, si = theta / h, w = std::hypot(sr, si);
  const json& p = c["parameters_predicted"];
  EXPECT_NEAR(p["frequency_hz"].get<double>(), w / (2.0 * std::numbers::pi), 1e-6);
  EXPECT_NEAR(p["damping_ratio"].get<double>(), -sr / w, 1e-6);
  EXPECT_TRUE(p["stable"].get<bool>());
}

TEST(IdentifyApp, BadSeriesNameRowAndColumn) {
  EXPECT_EQ(identify_problem({{"csv", "time,x\n0,1\n0.1,abc\n"}}).substr(0, 21), "422 csv.rows.1.x: lin");
  EXPECT_EQ(identify_problem({{"csv", "time,x\n0,1\n0.1,2,3\n"}}).substr(0, 20), "422 csv.rows.1: line");
  EXPECT_EQ(identify_problem({{"csv", "time,x\n0,1\n0,2\n"}}).substr(0, 22), "422 csv.rows.1.time: c");
  EXPECT_EQ(identify_problem({{"csv", "0,1\n0.1,2\n"}}).substr(0, 15), "422 csv.header:");
  EXPECT_EQ(identify_problem({{"time_s", {0, 0.1, 0.2}}, {"probes", {{"x", {1, 2}}}}}).substr(0, 17), "422 probes.x.2: m");
  EXPECT_EQ(identify_problem({{"time_s", {0, 0.1, 0.2}}, {"probes", {{"x", {1, "a", 3}}}}}).substr(0, 18), "422 probes.x.1: mu");
  EXPECT_EQ(identify_problem({{"time_s", {0, 0.1}}, {"probes", {{"x", {1, 2}}}}, {"typed", {{"k", 1}, {"c", 1}}}}).substr(0, 12),
            "422 request:");
  EXPECT_EQ(identify_problem({{"time_s", {0, 0.1}}, {"probes", {{"x", {1, 2}}}}, {"engine", "a b"}}).substr(0, 10), "422 engine");
  EXPECT_EQ(identify_problem({{"time_s", {0, 0.1}}, {"probes", {{"x", {1, 2}}}}, {"bogus", 1}}).substr(0, 9), "422 bogus");
}

// Mutated recordings (bytes flipped, rows cut, values made huge): each is an answer without NaN or a 4xx,
// never a crash or another exception.
TEST(IdentifyApp, MutatedCsvIsAnAnswerOrAProblem) {
  const std::string good = oscillator_csv(3.0, 0.2, 120);
  const char noise[] = {',', '\n', '-', 'e', '9', '.', 'x', '\0', ';', '\t'};
  unsigned state = 19;
  auto next = [&] { return state = state * 1103515245u + 12345u; };
  for (int i = 0; i < 200; ++i) {
    std::string csv = good;
    for (int k = 0; k < 1 + i % 5; ++k) csv[next() % csv.size()] = noise[next() % sizeof(noise)];
    if (i % 7 == 0) csv.resize(next() % csv.size());
    try {
      const json answer = run_identify({{"csv", csv}});
      EXPECT_EQ(answer.dump().find("NaN"), std::string::npos);
    } catch (const codec::Problem& p) {
      EXPECT_GE(p.status, 400);
      EXPECT_LT(p.status, 500);
    }
  }
}

}  // namespace
}  // namespace softtune::app
