#pragma once
// The conformance grid shared by the engine tests that build their cases first and run them after (in process
// or batched into another program, as Godot's are): issue 15's grid, each case's tune answer, the runs it
// types into the real engine (`parameters`, then `exact`), and the check of the fitted runs against
// `predicted` (1 % frequency, 0.02 damping ratio) and, for `exact`, against the request, with the table each
// test prints.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "softtune/engines/engine_run.h"
#include "softtune/response_fit.h"
#include "softtune/tune.h"

namespace softtune::engines::conformance {

inline constexpr double kFrequencyBand = 0.01, kDampingBand = 0.02;

/// One engine setting combination the grid cycles through, indexed like the model's settings.
struct Variant {
  std::string name;
  SettingValues settings;
};

/// One grid point: the tune request, its answer's report for the engine, and the runs to make.
struct Case {
  std::string label;
  EngineReport report;
  double asked_hz = 0.0, asked_zeta = 0.0;
  EngineRun run;                      ///< with no parameters; `plain` and `exact` say what to type
  bool plain = false, exact = false;  ///< which runs to make (present and stable)
  bool fit_plain = false, fit_exact = false;  ///< which of them a fit can read (fittable)
};

inline std::size_t model_index_of(const EngineModel& model) {
  const auto models = engine_models();
  std::size_t i = 0;
  while (i < models.size() && models[i] != &model) ++i;
  return i;
}

/// A motion that falls below fit_response's floor within a dozen samples cannot be fitted (it needs 8
/// samples above kFitFloor of the largest deviation), nor can an over-damped motion's fast pole that is
/// gone within four samples (the fit then reads round-off for it): such a run is not fitted; the test holds
/// it to the model's own trajectory where it can compute one, and counts it.
inline bool fittable(const Prediction& p, double h) {
  if (!p.stable || !p.frequency_hz || !p.damping_ratio || !(std::pow(p.spectral_radius, 12.0) > kFitFloor)) return false;
  const double omega = 2.0 * std::numbers::pi * *p.frequency_hz, zeta = *p.damping_ratio;
  if (zeta <= 1.0) return true;
  const double fast = std::exp(-omega * (zeta + std::sqrt(zeta * zeta - 1.0)) * h);
  return std::pow(fast, 4.0) > kFitFloor;
}

/// Enough steps for six periods of the slowest motion (or six time constants when it decays sooner).
inline int steps_for(double hz, double zeta, double dt) {
  const double omega = 2.0 * std::numbers::pi * hz;
  const double slow = zeta > 1.0 ? omega * (zeta - std::sqrt(zeta * zeta - 1.0)) : omega * std::max(zeta, 0.05);
  const double seconds = std::min(6.0 / hz, 6.0 / slow);
  return std::clamp(static_cast<int>(seconds / dt), 300, 3000);
}

/// The target tune() hands the models (core/src/tune.cpp export_to_engines), for a model not registered.
inline Target target_of(const TuneResult& result) {
  Target t;
  t.effective_mass = result.effective_mass;
  t.omega = result.omega;
  t.damping_ratio = result.damping_ratio;
  t.dt = result.h;
  t.spring = result.spring;
  t.box2d_reduced_mass = result.box2d_reduced_mass;
  return t;
}

/// Issue 15's grid at 60 fps: f/fps 0.02 to 0.3, zeta 0 to 2, the masses, substeps 1, 3 and 8, both modes,
/// a point body and the rotating plank, cycling through the variants; x0 is the initial stretch (m).
inline std::vector<Case> build_cases(const EngineModel& model, const std::vector<Variant>& variants,
                                     std::initializer_list<double> masses, double x0) {
  const std::size_t index = model_index_of(model);
  std::vector<Case> out;
  std::size_t at = 0;
  for (double ratio : {0.02, 0.08, 0.17, 0.3}) {
    for (double zeta : {0.0, 0.1, 0.5, 1.0, 2.0}) {
      for (double mass : masses) {
        for (int substeps : {1, 3, 8}) {
          for (SoftMode mode : {SoftMode::standard, SoftMode::exact}) {
            for (RunBody body : {RunBody::point, RunBody::rotating_plank}) {
              const Variant& v = variants[at++ % variants.size()];
              TuneRequest request;
              request.fps = 60.0;
              request.substeps = substeps;
              request.frequency_hz = ratio * request.fps;
              request.damping_ratio = zeta;
              request.mode = mode;
              request.effective_mass = mass;
              if (index < engine_models().size()) {
                request.engine_settings.resize(index + 1);
                request.engine_settings[index] = v.settings;
              }
              const TuneResult result = tune(request);
              Case c;
              char label[200];
              std::snprintf(label, sizeof label, "%s f/fps %.2f zeta %.1f m %.0e sub %d %s %s", v.name.c_str(), ratio,
                            zeta, mass, substeps, mode == SoftMode::exact ? "exact" : "std",
                            body == RunBody::point ? "point" : "plank");
              c.label = label;
              c.report = index < result.engine_reports.size() ? result.engine_reports[index]
                                                              : model.report(target_of(result), v.settings);
              c.asked_hz = result.omega / (2.0 * std::numbers::pi);
              c.asked_zeta = result.damping_ratio;
              c.run.effective_mass = mass;
              c.run.settings = v.settings;
              c.run.dt = result.h;
              c.run.steps = steps_for(c.asked_hz, zeta, result.h);
              c.run.body = body;
              c.run.x0 = x0;
              c.plain = !c.report.parameters.empty() && c.report.predicted.stable;
              c.exact = c.report.exact && c.report.exact_predicted && c.report.exact_predicted->stable;
              c.fit_plain = c.plain && fittable(c.report.predicted, result.h);
              c.fit_exact = c.exact && fittable(*c.report.exact_predicted, result.h);
              out.push_back(std::move(c));
            }
          }
        }
      }
    }
  }
  return out;
}

struct Worst {
  int runs = 0;
  double frequency = 0.0, damping = 0.0;
  void add(double f, double z) {
    ++runs;
    frequency = std::max(frequency, f);
    damping = std::max(damping, z);
  }
};

/// The trajectories of one case's runs (empty when the run was not made).
struct CaseRuns {
  RunTrajectory plain, exact;
};

/// The model's own trajectory of a run (x over x0 from 1 at rest, steps + 1 samples), for the runs no fit can
/// read; empty when the model has none to give.
using ModelTrajectory = std::function<RunTrajectory(const Case&, const Parameters&)>;

/// The trajectory of a linear step map from x = 1 at rest (steps + 1 samples): a model's own run.
inline RunTrajectory step_map_trajectory(const Eigen::Matrix2d& a, int steps) {
  RunTrajectory x{1.0};
  Eigen::Vector2d s(1.0, 0.0);
  for (int i = 0; i < steps; ++i) {
    s = a * s;
    x.push_back(s(0));
  }
  return x;
}

/// Within this of x0 at every sample, a run no fit can read follows the model's own trajectory.
inline constexpr double kTrajectoryBand = 2e-3;

/// Checks every case's runs and prints the table under `title`: the fitted ones, `parameters` vs
/// `predicted`, `exact` vs `exact_predicted` and vs the request; the others against `model` (when given)
/// sample by sample; a refused plain export must carry engine_refuses, a null `exact` engine_inexact.
inline void check_cases(const char* title, std::string_view engine, const std::vector<Case>& cases,
                        const std::vector<CaseRuns>& runs, const ModelTrajectory& model = {}) {
  ASSERT_EQ(cases.size(), runs.size());
  Worst plain_vs_predicted, exact_vs_predicted, exact_vs_request;
  int refused = 0, inexact = 0, skipped = 0, held = 0;
  double worst_held = 0.0;
  // A run no fit can read: held to the model's trajectory where there is one.
  auto hold = [&](const Case& c, const Parameters& p, const RunTrajectory& x, const char* which) {
    ++skipped;
    if (!model) return;
    const RunTrajectory expected = model(c, p);
    if (expected.empty()) return;
    const double x0 = x.empty() ? 1.0 : x.front();
    ASSERT_EQ(x.size(), expected.size()) << c.label << " " << which;
    double worst = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) worst = std::max(worst, std::abs(x[i] / x0 - expected[i]));
    EXPECT_LE(worst, kTrajectoryBand) << c.label << " " << which << ": off the model's trajectory";
    worst_held = std::max(worst_held, worst);
    ++held;
  };
  auto has = [&](const EngineReport& r, WarningCode code) {
    return std::any_of(r.warnings.begin(), r.warnings.end(),
                       [&](const Warning& w) { return w.code == code && w.engine == engine; });
  };
  auto fit = [](const RunTrajectory& x, double dt) -> std::optional<std::pair<double, double>> {
    if (x.empty() || !std::all_of(x.begin(), x.end(), [](double v) { return std::isfinite(v); })) return std::nullopt;
    const ResponseFit f = fit_response(x, dt);
    if (!f.frequency_hz || !f.damping_ratio) return std::nullopt;
    return std::pair{*f.frequency_hz, *f.damping_ratio};
  };
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const Case& c = cases[i];
    const EngineReport& r = c.report;
    if (r.parameters.empty()) {
      EXPECT_TRUE(has(r, WarningCode::engine_refuses)) << c.label;
      ++refused;
    } else if (c.fit_plain) {
      const auto m = fit(runs[i].plain, c.run.dt);
      EXPECT_TRUE(m) << c.label << ": no fit of the run";
      if (!m) continue;
      const double fe = std::abs(m->first / *r.predicted.frequency_hz - 1.0);
      const double ze = std::abs(m->second - *r.predicted.damping_ratio);
      EXPECT_LE(fe, kFrequencyBand) << c.label << " measured " << m->first << " predicted " << *r.predicted.frequency_hz;
      EXPECT_LE(ze, kDampingBand) << c.label << " measured " << m->second << " predicted " << *r.predicted.damping_ratio;
      plain_vs_predicted.add(fe, ze);
    } else if (c.plain) {
      hold(c, r.parameters, runs[i].plain, "plain");
    } else {
      ++skipped;
    }
    if (!r.exact) {
      EXPECT_TRUE(has(r, WarningCode::engine_inexact)) << c.label;
      ++inexact;
      continue;
    }
    if (!c.fit_exact) {
      if (c.exact) {
        hold(c, *r.exact, runs[i].exact, "exact");
      } else {
        ++skipped;
      }
      continue;
    }
    const auto m = fit(runs[i].exact, c.run.dt);
    EXPECT_TRUE(m) << c.label << ": no fit of the exact run";
    if (!m) continue;
    const double fe = std::abs(m->first / *r.exact_predicted->frequency_hz - 1.0);
    const double ze = std::abs(m->second - *r.exact_predicted->damping_ratio);
    EXPECT_LE(fe, kFrequencyBand) << c.label << " exact measured " << m->first;
    EXPECT_LE(ze, kDampingBand) << c.label << " exact measured " << m->second;
    exact_vs_predicted.add(fe, ze);
    const double re = std::abs(m->first / c.asked_hz - 1.0), rz = std::abs(m->second - c.asked_zeta);
    EXPECT_LE(re, kFrequencyBand) << c.label << " exact vs request " << m->first;
    EXPECT_LE(rz, kDampingBand) << c.label << " exact vs request " << m->second;
    exact_vs_request.add(re, rz);
  }
  std::printf("%s conformance: %zu cases (%d plain exports refused, %d exact null, %d runs no fit can read: %d of "
              "them held to the model's trajectory, worst %.2g of x0)\n",
              title, cases.size(), refused, inexact, skipped, held, worst_held);
  std::printf("  %-28s %6s %16s %16s\n", "run", "runs", "worst freq err", "worst zeta err");
  auto row = [](const char* name, const Worst& w) {
    std::printf("  %-28s %6d %15.3g%% %16.3g\n", name, w.runs, 100.0 * w.frequency, w.damping);
  };
  row("parameters vs predicted", plain_vs_predicted);
  row("exact vs exact_predicted", exact_vs_predicted);
  row("exact vs request", exact_vs_request);
}

}  // namespace softtune::engines::conformance
