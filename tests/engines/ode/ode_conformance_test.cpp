// ODE 0.16 in the loop (docs/engines.md): for each case softtune::tune() answers, the ODE report's `parameters` and
// then its `exact` are typed into the real engine (engines/ode), the trajectory is fitted (fit_response), and
// the fit is held against the model: within 1 % frequency and 0.02 damping ratio of `predicted`, and for
// `exact` also of the request. Grid: f/fps 0.02 to 0.3 at 60 fps, zeta 0 to 2, mass 1e-3 to 1e3, substeps 1
// to 8, standard and exact mode, a point body and a rotating plank, over both steppers and the three joints.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <thread>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "ode_engine.h"
#include "softtune/engines/ode.h"
#include "softtune/response_fit.h"
#include "softtune/tune.h"

namespace softtune::engines {
namespace {

constexpr double kFrequencyBand = 0.01, kDampingBand = 0.02;

std::size_t ode_index() {
  const auto models = engine_models();
  for (std::size_t i = 0; i < models.size(); ++i) {
    if (models[i] == &kOdeModel) return i;
  }
  return models.size();
}

struct Variant {
  const char* name;
  double stepper, iterations, w, joint;
};
// dWorldStep and dWorldQuickStep at its defaults, one over-relaxed sweep, a few under-relaxed ones, on the
// dball, the ball and the slider.
constexpr Variant kVariants[] = {
    {"step dball", 0, 20, 1.3, 0},       {"quick20 dball", 1, 20, 1.3, 0}, {"step ball", 0, 20, 1.3, 1},
    {"quick1 ball", 1, 1, 1.3, 1},       {"step slider", 0, 20, 1.3, 2},   {"quick3 w0.7 dball", 1, 3, 0.7, 0},
    {"quick2 slider", 1, 2, 1.3, 2},     {"quick1 w0.5 dball", 1, 1, 0.5, 0},
};

struct Worst {
  int runs = 0;
  double frequency = 0.0, damping = 0.0;
  void add(double f, double z) {
    ++runs;
    frequency = std::max(frequency, f);
    damping = std::max(damping, z);
  }
};

struct Measured {
  double frequency_hz, damping_ratio;
};

// A motion that falls below fit_response's floor within a dozen samples cannot be fitted (it needs 8 samples
// above kFitFloor of the largest deviation): such a run is counted, not measured.
bool fittable(const Prediction& p) { return std::pow(p.spectral_radius, 12.0) > kFitFloor; }

std::optional<Measured> measure(const EngineRun& run) {
  const RunTrajectory x = kOdeEngine.run(run);
  if (x.empty()) return std::nullopt;
  const ResponseFit fit = fit_response(x, run.dt);
  if (!fit.frequency_hz || !fit.damping_ratio) return std::nullopt;
  return Measured{*fit.frequency_hz, *fit.damping_ratio};
}

// Enough steps for several periods of the slowest motion, within a budget.
int steps_for(double hz, double zeta, double dt) {
  const double omega = 2.0 * std::numbers::pi * hz;
  const double slow = zeta > 1.0 ? omega * (zeta - std::sqrt(zeta * zeta - 1.0)) : omega * std::max(zeta, 0.05);
  // Six periods, or six time constants of the slowest pole when it decays sooner.
  const double seconds = std::min(6.0 / hz, 6.0 / slow);
  return std::clamp(static_cast<int>(seconds / dt), 300, 3000);
}

TEST(OdeConformance, RealEngineMatchesTheModel) {
  const std::size_t index = ode_index();
  ASSERT_LT(index, engine_models().size());
  Worst standard_vs_predicted, exact_vs_predicted, exact_vs_request;
  int cases = 0, refused = 0, inexact = 0, skipped = 0, variant_at = 0;
  for (double ratio : {0.02, 0.08, 0.17, 0.3}) {
    for (double zeta : {0.0, 0.1, 0.5, 1.0, 2.0}) {
      for (double mass : {1e-3, 1.0, 1e3}) {
        for (int substeps : {1, 3, 8}) {
          for (SoftMode mode : {SoftMode::standard, SoftMode::exact}) {
            for (RunBody body : {RunBody::point, RunBody::rotating_plank}) {
              // Cycle through the variants; the slider cannot carry the rotating plank.
              Variant v = kVariants[variant_at++ % std::size(kVariants)];
              if (body == RunBody::rotating_plank && v.joint == 2) v.joint = 1;
              TuneRequest request;
              request.fps = 60.0;
              request.substeps = substeps;
              request.frequency_hz = ratio * request.fps;
              request.damping_ratio = zeta;
              request.mode = mode;
              request.effective_mass = mass;
              request.engine_settings.resize(index + 1);
              request.engine_settings[index] = {v.stepper, v.iterations, v.w, v.joint};
              const TuneResult result = tune(request);
              ASSERT_EQ(result.engine_reports.size(), engine_models().size());
              const EngineReport& report = result.engine_reports[index];
              ++cases;
              const std::string label = std::string(v.name) + " f/fps " + std::to_string(ratio) + " zeta " +
                                        std::to_string(zeta) + " m " + std::to_string(mass) + " sub " +
                                        std::to_string(substeps) + (mode == SoftMode::exact ? " exact" : " std") +
                                        (body == RunBody::point ? " point" : " plank");
              auto has = [&](WarningCode code) {
                return std::any_of(report.warnings.begin(), report.warnings.end(),
                                   [&](const Warning& w) { return w.code == code && w.engine == "ode"; });
              };
              const double asked_hz = result.omega / (2.0 * std::numbers::pi);
              EngineRun run;
              run.effective_mass = mass;
              run.settings = request.engine_settings[index];
              run.dt = result.h;
              run.steps = steps_for(asked_hz, zeta, result.h);
              run.body = body;
              run.x0 = 1e-3;  // m: the plank turns 2 mrad, so its rotation stays linear to 1e-6

              if (report.parameters.empty()) {
                EXPECT_TRUE(has(WarningCode::engine_refuses)) << label;
                ++refused;
              } else if (report.predicted.stable && report.predicted.frequency_hz && fittable(report.predicted)) {
                run.parameters = report.parameters;
                const std::optional<Measured> m = measure(run);
                ASSERT_TRUE(m) << label;
                const double fe = std::abs(m->frequency_hz / *report.predicted.frequency_hz - 1.0);
                const double ze = std::abs(m->damping_ratio - *report.predicted.damping_ratio);
                EXPECT_LE(fe, kFrequencyBand) << label << " measured " << m->frequency_hz;
                EXPECT_LE(ze, kDampingBand) << label << " measured " << m->damping_ratio;
                standard_vs_predicted.add(fe, ze);
              } else {
                ++skipped;
              }

              if (!report.exact) {
                EXPECT_TRUE(has(WarningCode::engine_inexact)) << label;
                ++inexact;
                continue;
              }
              ASSERT_TRUE(report.exact_predicted) << label;
              if (!fittable(*report.exact_predicted)) {
                ++skipped;
                continue;
              }
              run.parameters = *report.exact;
              const std::optional<Measured> m = measure(run);
              ASSERT_TRUE(m) << label;
              const double fe = std::abs(m->frequency_hz / *report.exact_predicted->frequency_hz - 1.0);
              const double ze = std::abs(m->damping_ratio - *report.exact_predicted->damping_ratio);
              EXPECT_LE(fe, kFrequencyBand) << label << " exact measured " << m->frequency_hz;
              EXPECT_LE(ze, kDampingBand) << label << " exact measured " << m->damping_ratio;
              exact_vs_predicted.add(fe, ze);
              const double re = std::abs(m->frequency_hz / asked_hz - 1.0);
              const double rz = std::abs(m->damping_ratio - result.damping_ratio);
              EXPECT_LE(re, kFrequencyBand) << label << " exact vs request " << m->frequency_hz;
              EXPECT_LE(rz, kDampingBand) << label << " exact vs request " << m->damping_ratio;
              exact_vs_request.add(re, rz);
            }
          }
        }
      }
    }
  }
  std::printf("ODE %.*s conformance: %d cases (%d plain exports refused, %d exact null, %d runs decay too fast "
              "to fit)\n",
              static_cast<int>(kOdeEngine.version.size()), kOdeEngine.version.data(), cases, refused, inexact, skipped);
  std::printf("  %-28s %6s %16s %16s\n", "run", "runs", "worst freq err", "worst zeta err");
  auto row = [](const char* name, const Worst& w) {
    std::printf("  %-28s %6d %15.3g%% %16.3g\n", name, w.runs, 100.0 * w.frequency, w.damping);
  };
  row("parameters vs predicted", standard_vs_predicted);
  row("exact vs exact_predicted", exact_vs_predicted);
  row("exact vs request", exact_vs_request);
  EXPECT_GE(cases, 60);
}

}  // namespace
}  // namespace softtune::engines

namespace softtune::engines {
namespace {

// softtune verify serves runs from several HTTP workers at once: two threads running ODE together must
// each get the trajectory one thread alone gets (two concurrent verify requests once crashed inside libode).
TEST(OdeConcurrency, RunsOnTwoThreadsAtOnceMatchOneRunAlone) {
  EngineRun run;
  run.effective_mass = 2.0;
  run.parameters = {{"dParamERP", 0.2}, {"dParamCFM", 1e-4}};
  run.settings = default_settings_of(kOdeModel);
  run.steps = 200;
  const RunTrajectory alone = kOdeEngine.run(run);
  ASSERT_EQ(alone.size(), 201u);
  std::atomic<int> mismatches{0};
  auto worker = [&] {
    for (int i = 0; i < 20; ++i) {
      if (kOdeEngine.run(run) != alone) ++mismatches;
    }
  };
  std::thread a(worker), b(worker);
  a.join();
  b.join();
  EXPECT_EQ(mismatches.load(), 0);
}

}  // namespace
}  // namespace softtune::engines
