// The identify answer's `correction` object (server/codec/correction_codec.cpp): every figure typed or to
// type comes as frequency and ratio and as the k, c of the spring they are on the request's mass
// (k = m omega^2, c = 2 m zeta omega: the talk's spring), a verdict by name with its sentence, and no NaN.
#include "codec/correction_codec.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

namespace softtune::codec {
namespace {

constexpr double kTwoPiC = 2.0 * std::numbers::pi;

TEST(CorrectionCodec, EachResponseIsAlsoTheSpringOnTheRequestsMass) {
  const nlohmann::json j = response_json({2.0, 0.1}, 2.0);
  const double omega = kTwoPiC * 2.0;
  EXPECT_DOUBLE_EQ(j["frequency_hz"].get<double>(), 2.0);
  EXPECT_DOUBLE_EQ(j["damping_ratio"].get<double>(), 0.1);
  EXPECT_NEAR(j["k"].get<double>(), 2.0 * omega * omega, 1e-9);
  EXPECT_NEAR(j["c"].get<double>(), 2.0 * 2.0 * 0.1 * omega, 1e-12);
  // A negative ratio to type (a step's numerical damping cancelled) is a negative c, not a clamp.
  EXPECT_LT(response_json({8.0, -0.02}, 2.0)["c"].get<double>(), 0.0);
  // Nothing measured is null, never NaN in the JSON.
  const nlohmann::json none = response_json({std::numeric_limits<double>::quiet_NaN(), 0.5}, 2.0);
  EXPECT_TRUE(none["frequency_hz"].is_null());
  EXPECT_TRUE(none["k"].is_null());
}

TEST(CorrectionCodec, EveryVerdictHasItsNameAndASentenceThatStartsWithIt) {
  for (const auto& [verdict, name] : {std::pair{CorrectionVerdict::converging, "converging"}, std::pair{CorrectionVerdict::met, "met"},
                                     std::pair{CorrectionVerdict::beyond_reach, "beyond_reach"},
                                     std::pair{CorrectionVerdict::stalled, "stalled"}}) {
    EXPECT_EQ(correction_verdict_name(verdict), name);
    const std::string message = correction_verdict_message(verdict);
    std::string words(name);
    for (char& ch : words) ch = ch == '_' ? ' ' : ch;
    EXPECT_EQ(message.rfind(words + ":", 0), 0u) << message;
  }
}

TEST(CorrectionCodec, TheObjectCarriesTheRoundsTheVerdictAndWhatToTypeNext) {
  Correction c;
  c.next = {5.2, 0.45};
  c.method = CorrectionMethod::secant;
  c.verdict = CorrectionVerdict::met;
  c.expected = {5.0, 0.5};
  c.best_round = 1;
  c.trust_radius = 35.0;
  const nlohmann::json j = correction_json(c, {5.0, 0.5}, 3, 2.0, std::nullopt);
  EXPECT_EQ(j["method"], "secant");
  EXPECT_EQ(j["rounds"], 3);
  EXPECT_EQ(j["verdict"], "met");
  EXPECT_EQ(j["message"], correction_verdict_message(CorrectionVerdict::met));
  EXPECT_EQ(j["best_round"], 1);
  EXPECT_DOUBLE_EQ(j["trust_radius"].get<double>(), 35.0);
  EXPECT_EQ(j["typed"], response_json({5.0, 0.5}, 2.0));
  EXPECT_EQ(j["next"], response_json({5.2, 0.45}, 2.0));
  EXPECT_DOUBLE_EQ(j["expected"]["frequency_hz"].get<double>(), 5.0);
  // An engine without a model: no engine fields to type, null rather than absent.
  EXPECT_TRUE(j["parameters"].is_null());
  EXPECT_TRUE(j["parameters_predicted"].is_null());
  EXPECT_EQ(correction_json(Correction{}, {5.0, 0.5}, 1, 2.0, std::nullopt)["method"], "scaled");
}

}  // namespace
}  // namespace softtune::codec
