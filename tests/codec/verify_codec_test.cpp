// The verify contract (verify_codec.cpp): the engines list refused entry by entry naming its index (not a name,
// not an engine, modelled but not linked, named twice), duration, body and x0 bounds, and the answer's figures
// from the runs: relative frequency and absolute damping errors, trajectories strided to at most 1000 samples.
#include "codec/verify_codec.h"

#include <gtest/gtest.h>

#include <cmath>

#include "codec/problem.h"
#include "softtune/engines/verify.h"

namespace softtune::codec {
namespace {

using nlohmann::json;

json request() { return {{"frequency_hz", 3.0}, {"damping_ratio", 0.15}, {"effective_mass", 2.5}}; }

// The (field, detail) of the Problem decoding `doc` throws.
std::pair<std::string, std::string> refused(const json& doc) {
  try {
    decode_verify_request(doc);
  } catch (const Problem& p) {
    EXPECT_EQ(p.status, 422);
    return {p.field, p.detail};
  }
  return {"(accepted)", ""};
}

json with(const char* key, json value) {
  json r = request();
  r[key] = std::move(value);
  return r;
}

TEST(VerifyCodec, DecodesEnginesInTheOrderAsked) {
  EXPECT_TRUE(decode_verify_request(request()).engines.empty());  // none asked: none runs
  const VerifyRequest q = decode_verify_request(with("engines", {"ode", "box2d_v2_4"}));
  ASSERT_EQ(q.engines.size(), 2u);
  EXPECT_EQ(q.engines[0]->name, "ode");
  EXPECT_EQ(q.engines[1]->name, "box2d_v2_4");
  EXPECT_DOUBLE_EQ(q.tune.effective_mass.value_or(0.0), 2.5);
}

TEST(VerifyCodec, RefusesEachBadEntryByIndex) {
  EXPECT_EQ(refused(with("engines", "ode")).first, "engines");
  EXPECT_EQ(refused(with("engines", {"ode", 3})).first, "engines.1");
  const auto unknown = refused(with("engines", {"havok"}));
  EXPECT_EQ(unknown.first, "engines.0");
  EXPECT_NE(unknown.second.find("is not an engine"), std::string::npos) << unknown.second;
  const auto modelled = refused(with("engines", {"box2d_v3"}));  // a model in core, no engine linked
  EXPECT_EQ(modelled.first, "engines.0");
  EXPECT_NE(modelled.second.find("not linked"), std::string::npos) << modelled.second;
  EXPECT_EQ(refused(with("engines", {"ode", "ode"})).first, "engines.1");
  EXPECT_EQ(refused(with("engines", json(std::vector<std::string>(17, "ode")))).first, "engines");
}

TEST(VerifyCodec, RunOptionsHaveBounds) {
  EXPECT_EQ(refused(with("duration_s", 0)).first, "duration_s");
  EXPECT_EQ(refused(with("duration_s", 61)).first, "duration_s");
  EXPECT_EQ(refused(with("body", "cube")).first, "body");
  EXPECT_EQ(refused(with("x0", 0)).first, "x0");
  EXPECT_EQ(refused(with("x0", 2)).first, "x0");
  json long_run = with("duration_s", 60);
  long_run["fps"] = 5000;  // 60 s x 5000 fps = 3e5 steps, over 2e5
  EXPECT_EQ(refused(long_run).first, "duration_s");
  EXPECT_EQ(refused(with("enginez", json::array())).first, "enginez");
  const VerifyRequest q = decode_verify_request(with("body", "rotating_plank"));
  EXPECT_EQ(q.options.body, engines::RunBody::rotating_plank);
}

TEST(VerifyCodec, AnswerFiguresComeFromTheRuns) {
  const VerifyRequest q = decode_verify_request(with("engines", {"box2d_v2_4"}));
  const TuneResult tuned = tune(q.tune);
  const std::size_t index = engines::model_index("box2d_v2_4");
  const double predicted_hz = *tuned.engine_reports[index].predicted.frequency_hz;
  engines::EngineVerification run;
  run.engine = q.engines[0];
  run.trajectory.assign(2500, 0.25);
  run.measured.frequency_hz = predicted_hz * 1.02;
  run.measured.damping_ratio = 0.2;
  const json out = encode_verify_result(q, tuned, {run});
  EXPECT_NEAR(out["requested"]["frequency_hz"].get<double>(), 3.0, 1e-12);
  EXPECT_NEAR(out["requested"]["damping_ratio"].get<double>(), 0.15, 1e-12);
  const json& e = out["engines"]["box2d_v2_4"];
  EXPECT_NEAR(e["measured_vs_predicted"]["frequency"].get<double>(), 0.02, 1e-12);
  EXPECT_NEAR(e["measured_vs_requested"]["damping_ratio"].get<double>(), 0.2 - 0.15, 1e-12);
  // 2500 samples strided by ceil(2500 / 1000) = 3: 834 samples, 3 steps apart.
  EXPECT_EQ(e["trajectory"]["stride"], 3);
  EXPECT_EQ(e["trajectory"]["x"].size(), 834u);
  EXPECT_NEAR(e["trajectory"]["dt"].get<double>(), 3.0 / 60.0, 1e-12);
  const json& stages = out["stages"];
  EXPECT_EQ(stages[stages.size() - 2], "engine_box2d_v2_4");
  EXPECT_EQ(stages.back(), "response_fit");
  // A run whose fit failed has no errors, written as null.
  run.measured = {};
  EXPECT_TRUE(encode_verify_result(q, tuned, {run})["engines"]["box2d_v2_4"]["measured_vs_predicted"]["frequency"].is_null());
}

}  // namespace
}  // namespace softtune::codec
