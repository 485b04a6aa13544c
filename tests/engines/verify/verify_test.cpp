// The verify runner (engines/verify/verify.cpp) without a real engine: measure() recovers a damped
// oscillation's frequency and damping ratio from its samples (x(t) = e^{-zeta omega t} (cos omega_d t +
// zeta omega / omega_d sin omega_d t)); verify_engine() types the engine's report into a run of the requested
// length, step and stretch, once with `parameters` and once with `exact`.
#include "softtune/engines/verify.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace softtune::engines {
namespace {

RunTrajectory damped(double f, double zeta, double dt, int steps, double x0) {
  const double w = 2.0 * M_PI * f, wd = w * std::sqrt(1.0 - zeta * zeta);
  RunTrajectory x;
  for (int n = 0; n <= steps; ++n) {
    const double t = n * dt;
    x.push_back(x0 * std::exp(-zeta * w * t) * (std::cos(wd * t) + zeta * w / wd * std::sin(wd * t)));
  }
  return x;
}

TEST(Verify, MeasureRecoversFrequencyAndDamping) {
  const Measured m = measure(damped(3.0, 0.15, 1.0 / 60.0, 360, 0.01), 1.0 / 60.0);
  ASSERT_TRUE(m.frequency_hz && m.damping_ratio);
  EXPECT_NEAR(*m.frequency_hz, 3.0, 0.03);
  EXPECT_NEAR(*m.damping_ratio, 0.15, 0.01);
  EXPECT_LT(*m.residual, 0.01);
  EXPECT_TRUE(m.finite);
  RunTrajectory blown = damped(3.0, 0.15, 1.0 / 60.0, 60, 0.01);
  blown[30] = std::numeric_limits<double>::quiet_NaN();
  const Measured bad = measure(blown, 1.0 / 60.0);
  EXPECT_FALSE(bad.finite);
  EXPECT_FALSE(bad.frequency_hz);
}

TEST(Verify, ModelIndexFindsTheModelByName) {
  const auto models = engine_models();
  for (std::size_t i = 0; i < models.size(); ++i) EXPECT_EQ(model_index(models[i]->name), i);
  EXPECT_EQ(model_index("havok"), models.size());
}

// A stand-in engine: records each run it is given and moves as the request asks.
std::vector<EngineRun> g_runs;
RunTrajectory recording_run(const EngineRun& run) {
  g_runs.push_back(run);
  return damped(2.0, 0.2, run.dt, run.steps, run.x0);
}

TEST(Verify, TheReportIsTypedIntoARunOfTheRequestedShape) {
  TuneRequest q;
  q.frequency_hz = 2.0;
  q.damping_ratio = 0.2;
  q.effective_mass = 3.0;
  q.mode = SoftMode::exact;
  const TuneResult tuned = tune(q);
  const RealEngine fake{"ode", "test", recording_run};
  VerifyOptions options;
  options.duration_s = 5.0;
  options.x0 = 0.02;
  g_runs.clear();
  const EngineVerification v = verify_engine(fake, tuned, q, options);
  const EngineReport& report = tuned.engine_reports[model_index("ode")];
  ASSERT_EQ(g_runs.size(), report.exact ? 2u : 1u);
  EXPECT_EQ(g_runs[0].steps, 300);  // ceil(5 s / (1/60 s))
  EXPECT_DOUBLE_EQ(g_runs[0].dt, 1.0 / 60.0);
  EXPECT_DOUBLE_EQ(g_runs[0].x0, 0.02);
  EXPECT_DOUBLE_EQ(g_runs[0].effective_mass, 3.0);
  ASSERT_EQ(g_runs[0].parameters.size(), report.parameters.size());
  for (std::size_t i = 0; i < report.parameters.size(); ++i) EXPECT_EQ(g_runs[0].parameters[i].value, report.parameters[i].value);
  EXPECT_EQ(v.engine, &fake);
  ASSERT_EQ(v.trajectory.size(), 301u);
  EXPECT_NEAR(*v.measured.frequency_hz, 2.0, 0.02);
  if (report.exact) {
    ASSERT_TRUE(v.exact_measured);
    EXPECT_EQ(g_runs[1].parameters.size(), report.exact->size());
  }
  // An engine without a model gets no run.
  g_runs.clear();
  const EngineVerification none = verify_engine(RealEngine{"havok", "", recording_run}, tuned, q, options);
  EXPECT_TRUE(g_runs.empty());
  EXPECT_TRUE(none.trajectory.empty());
}

}  // namespace
}  // namespace softtune::engines
