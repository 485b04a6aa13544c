// MuJoCo 2.2.2 in the loop (docs/engines.md, issue 15): for each case softtune::tune() answers, the mujoco
// report's `parameters` and then its `exact` are typed into the real engine (kMujocoEngine: MJCF in memory,
// one soft joint or tendon equality), the trajectory is fitted (fit_response), and
//   parameters: measured within 1 % frequency and 0.02 damping ratio of `predicted` (or, predicted
//               unstable, the engine blows up: NaN, |x| > 10 x0, or mj_checkAcc's reset to qpos0);
//   exact:      measured within 1 % / 0.02 of the request; a null `exact` carries engine_inexact.
// Prints the table.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <complex>
#include <optional>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include <mujoco/mujoco.h>

#include "mujoco_engine.h"
#include "softtune/discrete_analysis.h"
#include "softtune/engines/mujoco.h"
#include "softtune/response_fit.h"
#include "softtune/tune.h"

namespace softtune::engines {
namespace {

struct Case {
  double fps = 60.0;
  int substeps = 1;
  double f_over_fps = 0.1;
  double zeta = 0.0;
  double mass = 1.0;
  SoftMode mode = SoftMode::standard;
  RunBody body = RunBody::point;
  MujocoIntegrator integrator = MujocoIntegrator::euler;
};

std::size_t mujoco_index() {
  const auto models = engine_models();
  for (std::size_t i = 0; i < models.size(); ++i) {
    if (models[i]->name == "mujoco") return i;
  }
  return models.size();
}

// The grid: every f/fps, zeta, mass, substeps, mode, body and integrator value appears, combined by
// co-prime cycles so that the 96 cases mix them rather than repeat one corner.
std::vector<Case> grid() {
  constexpr std::array<double, 5> kFOverFps = {0.01, 0.05, 0.1, 0.2, 0.3};
  constexpr std::array<double, 7> kZeta = {0.0, 0.05, 0.2, 0.5, 1.0, 1.5, 2.0};
  constexpr std::array<double, 4> kMass = {1e-3, 1.0, 20.0, 1e3};
  constexpr std::array<int, 4> kSubsteps = {1, 2, 4, 8};
  constexpr std::array<MujocoIntegrator, 3> kIntegrators = {MujocoIntegrator::euler, MujocoIntegrator::implicit,
                                                            MujocoIntegrator::rk4};
  std::vector<Case> out;
  for (int i = 0; i < 96; ++i) {
    Case c;
    c.f_over_fps = kFOverFps[i % kFOverFps.size()];
    c.zeta = kZeta[(i / 2) % kZeta.size()];
    c.mass = kMass[(i / 3) % kMass.size()];
    c.substeps = kSubsteps[(i / 5) % kSubsteps.size()];
    c.mode = i % 2 == 0 ? SoftMode::standard : SoftMode::exact;
    c.body = (i / 7) % 2 == 0 ? RunBody::point : RunBody::rotating_plank;
    c.integrator = kIntegrators[(i / 11) % kIntegrators.size()];
    c.fps = (i / 13) % 2 == 0 ? 60.0 : 120.0;
    out.push_back(c);
  }
  return out;
}

bool blew_up(const RunTrajectory& x, double x0) {
  for (std::size_t i = 1; i < x.size(); ++i) {
    if (!std::isfinite(x[i]) || std::abs(x[i]) > 10.0 * std::abs(x0)) return true;
    // mj_checkAcc: a bad qacc resets mjData, qpos = qpos0, and the stretch stays exactly 0.
    if (x[i] == 0.0 && x.back() == 0.0) return true;
  }
  return false;
}

struct Measured {
  std::optional<double> frequency_hz, damping_ratio;
};

// fit_response, and where the motion decays below its fit floor within 8 samples (a pole of a few
// percent, e.g. critically damped at 0.3 fps), the same order-2 linear prediction x[n] = a1 x[n-1] + a2 x[n-2]
// with each equation scaled by 1 / |x[n-1]|, over the samples above kFallbackFloor x0 (below it the plank's
// second-order geometry, which does not decay with the spring, is a visible part of the stretch).
constexpr double kFallbackFloor = 1e-5;
Measured measure(const RunTrajectory& x, double h) {
  const ResponseFit fit = fit_response(x, h);
  if (fit.frequency_hz && fit.damping_ratio) return {fit.frequency_hz, fit.damping_ratio};
  double s00 = 0, s01 = 0, s11 = 0, r0 = 0, r1 = 0;
  int rows = 0;
  for (std::size_t n = 2; n < x.size() && std::abs(x[n]) > kFallbackFloor * std::abs(x[0]); ++n) {
    const double w = 1.0 / std::max(std::abs(x[n - 1]), std::abs(x[n - 2]));
    const double p = x[n - 1] * w, q = x[n - 2] * w, y = x[n] * w;
    s00 += p * p, s01 += p * q, s11 += q * q, r0 += p * y, r1 += q * y;
    ++rows;
  }
  const double det = s00 * s11 - s01 * s01;
  if (rows < 2 || !(std::abs(det) > 0.0)) return {};
  const double a1 = (r0 * s11 - r1 * s01) / det, a2 = (s00 * r1 - s01 * r0) / det;
  const std::complex<double> root = std::sqrt(std::complex<double>(a1 * a1 + 4.0 * a2));
  double frequency = 0.0, zeta = 0.0;
  if (!achieved_from_poles(0.5 * (a1 + root), 0.5 * (a1 - root), h, frequency, zeta)) return {};
  return {frequency, zeta};
}

struct Worst {
  int cases = 0;
  double frequency = 0.0, damping = 0.0;
  std::string frequency_case, damping_case;
  void add(double f, double d, const std::string& label) {
    ++cases;
    if (std::abs(f) > frequency) frequency = std::abs(f), frequency_case = label;
    if (std::abs(d) > damping) damping = std::abs(d), damping_case = label;
  }
};

TEST(MujocoConformance, RealEngineDoesWhatTheModelSays) {
  const std::size_t index = mujoco_index();
  ASSERT_LT(index, engine_models().size());
  Worst predicted, exact;
  int unstable = 0, inexact = 0, replaced = 0, runs = 0;
  for (const Case& c : grid()) {
    TuneRequest request;
    request.fps = c.fps;
    request.substeps = c.substeps;
    request.frequency_hz = c.f_over_fps * c.fps;
    request.damping_ratio = c.zeta;
    request.mode = c.mode;
    request.effective_mass = c.mass;
    request.engine_settings.resize(engine_models().size());
    SettingValues settings = default_settings(kMujocoModel);
    settings[kMujocoIntegrator] = static_cast<double>(c.integrator);
    request.engine_settings[index] = settings;
    const TuneResult result = tune(request);
    const EngineReport& report = result.engine_reports[index];
    const std::string label = "fps " + std::to_string(c.fps) + " substeps " + std::to_string(c.substeps) +
                              " f/fps " + std::to_string(c.f_over_fps) + " zeta " + std::to_string(c.zeta) +
                              " mass " + std::to_string(c.mass) +
                              (c.mode == SoftMode::exact ? " exact" : " standard") +
                              (c.body == RunBody::point ? " point" : " plank") + " integrator " +
                              std::to_string(static_cast<int>(c.integrator));
    for (const Warning& w : report.warnings) replaced += w.code == WarningCode::engine_refuses;

    EngineRun run;
    run.effective_mass = c.mass;
    run.settings = settings;
    run.dt = result.h;
    run.body = c.body;
    run.x0 = 1e-3;  // the plank's geometry departs from linear as x0^2: 1 mm keeps it below 1e-4
    // At least four periods of the slower motion, at most 6000 steps.
    const double hz = std::max(1e-9, result.frequency_hz);
    run.steps = std::clamp(static_cast<int>(4.0 / (hz * result.h)), 300, 6000);

    // The plain export against the prediction.
    run.parameters = report.parameters;
    const RunTrajectory plain = kMujocoEngine.run(run);
    ++runs;
    ASSERT_EQ(plain.size(), static_cast<std::size_t>(run.steps) + 1) << label;
    if (!report.predicted.stable) {
      ++unstable;
      EXPECT_TRUE(blew_up(plain, run.x0)) << label;
    } else if (report.predicted.frequency_hz && report.predicted.damping_ratio) {
      const Measured fit = measure(plain, result.h);
      ASSERT_TRUE(fit.frequency_hz && fit.damping_ratio) << label;
      const double ef = *fit.frequency_hz / *report.predicted.frequency_hz - 1.0;
      const double ed = *fit.damping_ratio - *report.predicted.damping_ratio;
      predicted.add(ef, ed, label);
      EXPECT_LT(std::abs(ef), 0.01) << label << " measured " << *fit.frequency_hz << " predicted "
                                    << *report.predicted.frequency_hz;
      EXPECT_LT(std::abs(ed), 0.02) << label << " measured " << *fit.damping_ratio << " predicted "
                                    << *report.predicted.damping_ratio;
    }

    // `exact` against the request.
    if (!report.exact) {
      ++inexact;
      bool said = false;
      for (const Warning& w : report.warnings) said |= w.code == WarningCode::engine_inexact && w.engine == "mujoco";
      EXPECT_TRUE(said) << label;
      std::printf("  exact null: %s\n", label.c_str());
      continue;
    }
    run.parameters = *report.exact;
    const RunTrajectory tuned = kMujocoEngine.run(run);
    ++runs;
    const Measured fit = measure(tuned, result.h);
    ASSERT_TRUE(fit.frequency_hz && fit.damping_ratio) << label;
    const double ef = *fit.frequency_hz / result.frequency_hz - 1.0;
    const double ed = *fit.damping_ratio - result.damping_ratio;
    exact.add(ef, ed, label);
    EXPECT_LT(std::abs(ef), 0.01) << label << " measured " << *fit.frequency_hz << " asked " << result.frequency_hz;
    EXPECT_LT(std::abs(ed), 0.02) << label << " measured " << *fit.damping_ratio << " asked " << result.damping_ratio;
  }
  std::printf("\n%s conformance (%d engine runs)\n", kMujocoEngine.version.data(), runs);
  std::printf("  %-34s %6s %14s %14s\n", "", "cases", "worst freq", "worst zeta");
  std::printf("  %-34s %6d %13.4f%% %14.4f\n", "parameters vs predicted", predicted.cases,
              100.0 * predicted.frequency, predicted.damping);
  std::printf("  %-34s %6d %13.4f%% %14.4f\n", "exact vs request", exact.cases, 100.0 * exact.frequency,
              exact.damping);
  std::printf("  predicted unstable (and blew up): %d, exact null (engine_inexact): %d, "
              "plain exports MuJoCo replaces (engine_refuses): %d\n",
              unstable, inexact, replaced);
  std::printf("  worst cases: predicted f %s; zeta %s\n               exact f %s; zeta %s\n",
              predicted.frequency_case.c_str(), predicted.damping_case.c_str(), exact.frequency_case.c_str(),
              exact.damping_case.c_str());
}

// MuJoCo's default solimp (0.9 0.95 0.001 0.5 2) is not flat: the impedance runs from solimp[0] at rest to
// solimp[1] beyond `width`. Typed with the export's solref, the response is the model's (imp = solimp[1])
// while the motion stays far outside the width, and the linearisation at imp = solimp[0] when it stays far
// inside; near the width it is neither (printed, not asserted).
TEST(MujocoConformance, DefaultSolimpHoldsTheModelInTwoRegimes) {
  const std::size_t index = mujoco_index();
  std::printf("\nMuJoCo default solimp 0.9 0.95 0.001 0.5 2 with the export's solref (5 Hz, 60 fps):\n");
  for (double zeta : {0.0, 0.2, 0.5}) {
    TuneRequest request;
    request.frequency_hz = 5.0;
    request.damping_ratio = zeta;
    request.effective_mass = 1.0;
    const TuneResult result = tune(request);
    const EngineReport& report = result.engine_reports[index];
    EngineRun run;
    run.settings = default_settings(kMujocoModel);
    run.dt = result.h;
    run.parameters = report.parameters;
    for (Parameter& p : run.parameters) {
      if (p.name == "solimp[0]") p.value = 0.9;
    }
    const double s0 = *parameter_value(report.parameters, "solref[0]");
    const double s1 = *parameter_value(report.parameters, "solref[1]");
    const MujocoGains at_rest = mujoco_gains(s0, s1, 0.9, 0.95, result.h, true);
    const Prediction inside = predict_from_step_map(
        mujoco_step_map(MujocoIntegrator::euler, at_rest.beta, at_rest.kappa, result.h), result.h);
    for (double x0 : {1e-4, 1e-3, 1e-1}) {
      run.x0 = x0;
      const Measured m = measure(kMujocoEngine.run(run), result.h);
      ASSERT_TRUE(m.frequency_hz && m.damping_ratio);
      const Prediction& want = x0 < 1e-3 ? inside : report.predicted;
      std::printf("  zeta %.1f x0 %-6g measured %.4f Hz %.4f; flat model %.4f Hz %.4f, imp = solimp[0] %.4f Hz %.4f\n",
                  zeta, x0, *m.frequency_hz, *m.damping_ratio, *report.predicted.frequency_hz,
                  *report.predicted.damping_ratio, *inside.frequency_hz, *inside.damping_ratio);
      if (x0 == 1e-3) continue;  // at the width itself the impedance changes within each swing
      EXPECT_LT(std::abs(*m.frequency_hz / *want.frequency_hz - 1.0), 0.01) << zeta << " " << x0;
      EXPECT_LT(std::abs(*m.damping_ratio - *want.damping_ratio), 0.02) << zeta << " " << x0;
    }
  }
}

// A connect equality on the rotating plank (planar: slide x, slide y, hinge z): MuJoCo's diagonal for it is
// body_invweight0 = (1/mass + 1/mass + 0) / 3, the anchor's 1/m_eff = 2/mass, so diag_ratio = 3. Told so, the
// model predicts the plain export and its exact solref compensates; the runner does not build connect (it
// builds the rows where the ratio is 1), so this test writes its own MJCF.
RunTrajectory run_connect(const Parameters& p, double m_eff, double h, const std::string& integrator, int steps) {
  const PlankGeometry g = rotating_plank(m_eff);
  char xml[2000];
  std::snprintf(xml, sizeof(xml),
                "<mujoco><option timestep=\"%.17g\" gravity=\"0 0 0\" integrator=\"%s\"/><worldbody>"
                "<body name=\"b\"><joint type=\"slide\" axis=\"1 0 0\"/><joint type=\"slide\" axis=\"0 1 0\"/>"
                "<joint type=\"hinge\" axis=\"0 0 1\"/><inertial pos=\"0 0 0\" mass=\"%.17g\" "
                "diaginertia=\"%.17g %.17g %.17g\"/></body></worldbody><equality><connect body1=\"b\" "
                "anchor=\"0 %.17g 0\" solref=\"%.17g %.17g\" solimp=\"%.17g %.17g %.17g %.17g %.17g\"/>"
                "</equality></mujoco>",
                h, integrator.c_str(), g.mass, g.inertia, g.inertia, g.inertia, -g.offset,
                *parameter_value(p, "solref[0]"), *parameter_value(p, "solref[1]"), *parameter_value(p, "solimp[0]"),
                *parameter_value(p, "solimp[1]"), *parameter_value(p, "solimp[2]"), *parameter_value(p, "solimp[3]"),
                *parameter_value(p, "solimp[4]"));
  static const bool quiet = (mju_user_warning = [](const char*) {}, true);  // as kMujocoEngine does
  (void)quiet;
  auto vfs = std::make_unique<mjVFS>();
  mj_defaultVFS(vfs.get());
  const std::size_t size = std::strlen(xml);
  mj_makeEmptyFileVFS(vfs.get(), "connect.xml", static_cast<int>(size));
  std::memcpy(vfs->filedata[mj_findFileVFS(vfs.get(), "connect.xml")], xml, size);
  char error[500] = "";
  mjModel* m = mj_loadXML("connect.xml", vfs.get(), error, sizeof(error));
  mj_deleteVFS(vfs.get());
  if (!m) return {};
  mjData* d = mj_makeData(m);
  d->qpos[0] = 1e-3;
  RunTrajectory x;
  auto anchor_x = [&] { return d->qpos[0] + g.offset * std::sin(d->qpos[2]); };
  x.push_back(anchor_x());
  for (int i = 0; i < steps; ++i) {
    mj_step(m, d);
    x.push_back(anchor_x());
  }
  mj_deleteData(d);
  mj_deleteModel(m);
  return x;
}

TEST(MujocoConformance, ConnectOnAnOffCentreAnchorWithItsDiagRatio) {
  const std::size_t index = mujoco_index();
  Worst predicted, exact, assumed_one;
  for (double fps : {60.0, 120.0}) {
    for (double zeta : {0.0, 0.2, 1.0}) {
      for (double f_over_fps : {0.05, 0.2}) {
        for (SoftMode mode : {SoftMode::standard, SoftMode::exact}) {
          for (MujocoIntegrator integrator : {MujocoIntegrator::euler, MujocoIntegrator::rk4}) {
            TuneRequest request;
            request.fps = fps;
            request.frequency_hz = f_over_fps * fps;
            request.damping_ratio = zeta;
            request.mode = mode;
            request.effective_mass = 2.0;
            SettingValues settings = default_settings(kMujocoModel);
            settings[kMujocoIntegrator] = static_cast<double>(integrator);
            settings[kMujocoDiagRatio] = 3.0;
            request.engine_settings.resize(engine_models().size());
            request.engine_settings[index] = settings;
            const TuneResult result = tune(request);
            const EngineReport& r = result.engine_reports[index];
            const std::string name(kMujocoModel.settings[kMujocoIntegrator].choices[static_cast<int>(integrator)]);
            const std::string label = name + " fps " + std::to_string(fps) + " zeta " + std::to_string(zeta) +
                                      " f/fps " + std::to_string(f_over_fps) +
                                      (mode == SoftMode::exact ? " exact" : " standard");
            const int steps = std::clamp(static_cast<int>(4.0 / (result.frequency_hz * result.h)), 300, 6000);
            if (r.predicted.stable && r.predicted.frequency_hz) {
              const Measured m = measure(run_connect(r.parameters, 2.0, result.h, name, steps), result.h);
              ASSERT_TRUE(m.frequency_hz && m.damping_ratio) << label;
              predicted.add(*m.frequency_hz / *r.predicted.frequency_hz - 1.0,
                            *m.damping_ratio - *r.predicted.damping_ratio, label);
              // What the model would say with the ratio left at 1.
              TuneRequest one = request;
              one.engine_settings[index][kMujocoDiagRatio] = 1.0;
              const EngineReport r1 = tune(one).engine_reports[index];
              if (r1.predicted.frequency_hz) {
                assumed_one.add(*m.frequency_hz / *r1.predicted.frequency_hz - 1.0,
                                *m.damping_ratio - *r1.predicted.damping_ratio, label);
              }
            }
            if (!r.exact) continue;
            const Measured m = measure(run_connect(*r.exact, 2.0, result.h, name, steps), result.h);
            ASSERT_TRUE(m.frequency_hz && m.damping_ratio) << label;
            exact.add(*m.frequency_hz / result.frequency_hz - 1.0, *m.damping_ratio - result.damping_ratio, label);
          }
        }
      }
    }
  }
  std::printf("\nconnect on the rotating plank, diag_ratio 3, solimp[1] 0.95:\n");
  std::printf("  parameters vs predicted: %d cases, worst %.4f%% / %.4f\n", predicted.cases, 100 * predicted.frequency,
              predicted.damping);
  std::printf("  exact vs request:        %d cases, worst %.4f%% / %.4f\n", exact.cases, 100 * exact.frequency,
              exact.damping);
  std::printf("  (predicted with diag_ratio 1: worst %.4f%% / %.4f)\n", 100 * assumed_one.frequency,
              assumed_one.damping);
  EXPECT_LT(predicted.frequency, 0.01) << predicted.frequency_case;
  EXPECT_LT(predicted.damping, 0.02) << predicted.damping_case;
  EXPECT_LT(exact.frequency, 0.01) << exact.frequency_case;
  EXPECT_LT(exact.damping, 0.02) << exact.damping_case;
  EXPECT_GE(exact.cases, 20);
}

}  // namespace
}  // namespace softtune::engines
