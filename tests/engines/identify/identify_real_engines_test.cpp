// Recordings taken from the real engines (Box2D 2.4.1, ODE, Bullet, MuJoCo, linked in process): each run
// with the engine's plain export is identified and held against the response fit of the same run (within
// 0.5 % frequency, 0.01 damping ratio), then corrected once and run again, which must meet the request
// within 1 % / 0.02 -- with the model's `exact`, and with the black-box correction (correct_response, as for
// an engine softtune does not model: the measured ratio scales what was typed, re-exported in the engine's
// fields). Prints the table of identified against measured and requested values.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "softtune/engines/verify.h"
#include "softtune/identify.h"
#include "softtune/identify_correction.h"
#include "softtune/response_fit.h"
#include "softtune/tune.h"

namespace softtune::engines {
namespace {

constexpr double kSameRunFrequency = 0.005, kSameRunDamping = 0.01;
constexpr double kCorrectedFrequency = 0.01, kCorrectedDamping = 0.02;
constexpr int kRounds = 3;

struct Case {
  double frequency_hz, damping_ratio;
};
constexpr Case kCases[] = {{2.0, 0.1}, {5.0, 0.5}, {8.0, 0.3}, {12.0, 0.7}};

TuneRequest request_for(double f, double zeta) {
  TuneRequest q;
  q.frequency_hz = f;
  q.damping_ratio = zeta;
  q.effective_mass = 2.0;
  return q;
}

RunTrajectory run_report(const RealEngine& engine, const Parameters& parameters, const TuneRequest& q,
                         const TuneResult& tuned, std::size_t index) {
  EngineRun run;
  run.effective_mass = tuned.effective_mass;
  run.settings = engine_settings_for(q, index);
  run.dt = tuned.h;
  run.steps = 360;
  run.parameters = parameters;
  return engine.run(run);
}

Identification identify_run(const RunTrajectory& x, double dt) {
  Recording r;
  for (std::size_t n = 0; n < x.size(); ++n) r.time_s.push_back(static_cast<double>(n) * dt);
  r.probes.push_back(x);
  return identify(r);
}

TEST(IdentifyRealEngines, MatchesTheFitAndOneCorrectionMeetsTheRequest) {
  std::printf("  %-11s %-9s | %-17s | %-17s | %-17s | %-17s | %-17s | %-17s\n", "engine", "asked", "fit of the run",
              "identified", "after exact", "black box 1", "black box 2", "black box 3");
  double worst_f = 0, worst_z = 0, worst_exact_f = 0, worst_exact_z = 0;
  for (const RealEngine* engine : real_engines()) {
    const std::size_t index = model_index(engine->name);
    ASSERT_LT(index, engine_models().size());
    for (const Case& c : kCases) {
      const TuneRequest q = request_for(c.frequency_hz, c.damping_ratio);
      const TuneResult tuned = tune(q);
      const EngineReport& report = tuned.engine_reports[index];
      const RunTrajectory x = run_report(*engine, report.parameters, q, tuned, index);
      const ResponseFit fit = fit_response(x, tuned.h);
      const Identification id = identify_run(x, tuned.h);
      ASSERT_TRUE(fit.frequency_hz && id.joint.frequency_hz) << engine->name;
      if (!report.predicted.stable) {
        // The plain export blows up in this engine (as its model predicts): no linear motion explains the
        // run, and identify says so rather than agreeing with a fit that explains none of it.
        EXPECT_FALSE(id.verdicts.empty()) << engine->name << " " << c.frequency_hz;
        continue;
      }
      const double df = std::abs(*id.joint.frequency_hz / *fit.frequency_hz - 1.0);
      const double dz = std::abs(*id.joint.damping_ratio - *fit.damping_ratio);
      EXPECT_LT(df, kSameRunFrequency) << engine->name << " " << c.frequency_hz;
      EXPECT_LT(dz, kSameRunDamping) << engine->name << " " << c.frequency_hz;
      worst_f = std::max(worst_f, df), worst_z = std::max(worst_z, dz);

      // The modelled engine's correction: its exact parameters.
      double exact_f = NAN, exact_z = NAN;
      if (report.exact) {
        const Identification after = identify_run(run_report(*engine, *report.exact, q, tuned, index), tuned.h);
        exact_f = after.joint.frequency_hz.value_or(NAN), exact_z = after.joint.damping_ratio.value_or(NAN);
        EXPECT_LT(std::abs(exact_f / c.frequency_hz - 1.0), kCorrectedFrequency) << engine->name;
        EXPECT_LT(std::abs(exact_z - c.damping_ratio), kCorrectedDamping) << engine->name;
        worst_exact_f = std::max(worst_exact_f, std::abs(exact_f / c.frequency_hz - 1.0));
        worst_exact_z = std::max(worst_exact_z, std::abs(exact_z - c.damping_ratio));
      }

      // The black-box correction, as for an engine softtune does not model: what was typed (first the
      // request) corrected by what was identified, re-exported in the engine's fields, recorded again.
      const ResponseValues asked{c.frequency_hz, c.damping_ratio};
      std::vector<CorrectionRound> rounds = {{asked, {*id.joint.frequency_hz, *id.joint.damping_ratio}}};
      double after_f[kRounds] = {}, after_z[kRounds] = {};
      for (int i = 0; i < kRounds; ++i) {
        const ResponseValues next = correct_response(asked, rounds).next;
        const TuneRequest q2 = request_for(next.frequency_hz, next.damping_ratio);
        const TuneResult tuned2 = tune(q2);
        const Identification after =
            identify_run(run_report(*engine, tuned2.engine_reports[index].parameters, q2, tuned2, index), tuned2.h);
        after_f[i] = after.joint.frequency_hz.value_or(NAN), after_z[i] = after.joint.damping_ratio.value_or(NAN);
        rounds.push_back({next, {after_f[i], after_z[i]}});
      }
      // A black box that starts within 25 % of the request at f/fps <= 1/12 reaches it in three recordings.
      if (c.frequency_hz <= 5.0 && std::abs(*id.joint.frequency_hz / c.frequency_hz - 1.0) < 0.25) {
        EXPECT_LT(std::abs(after_f[kRounds - 1] / c.frequency_hz - 1.0), kCorrectedFrequency) << engine->name;
        EXPECT_LT(std::abs(after_z[kRounds - 1] - c.damping_ratio), kCorrectedDamping) << engine->name;
      }
      std::printf("  %-11.*s %4.1f/%.2f | %7.4f Hz %.4f | %7.4f Hz %.4f | %7.4f Hz %.4f | %7.4f Hz %.4f | %7.4f Hz %.4f | %7.4f Hz %.4f\n",
                  static_cast<int>(engine->name.size()), engine->name.data(), c.frequency_hz, c.damping_ratio,
                  *fit.frequency_hz, *fit.damping_ratio, *id.joint.frequency_hz, *id.joint.damping_ratio, exact_f,
                  exact_z, after_f[0], after_z[0], after_f[1], after_z[1], after_f[2], after_z[2]);
    }
  }
  std::printf("  worst: identified vs fit %.3g %% / %.3g; after exact %.3g %% / %.3g\n", 100 * worst_f, worst_z,
              100 * worst_exact_f, worst_exact_z);
}

}  // namespace
}  // namespace softtune::engines
