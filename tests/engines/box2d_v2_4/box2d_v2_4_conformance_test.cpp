// Box2D 2.4.1 in the loop (docs/engines.md): for each case softtune::tune() answers a TuneRequest, the box2d_v2_4
// report's `parameters` and then its `exact` are typed into the real engine (engines/box2d_v2_4), the
// trajectory is fitted (fit_response), and the fit is held against the report: measured within 1 % frequency
// and 0.02 damping ratio of `predicted`, and, for `exact`, of the request. Where `exact` is empty the model
// must say why (engine_inexact); where `parameters` are refused it must say so (engine_refuses).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "box2d_v2_4_run.h"
#include "softtune/engines/box2d_v2_4.h"
#include "softtune/response_fit.h"
#include "softtune/tune.h"

namespace softtune::engines {
namespace {

constexpr std::array<const char*, 3> kJointNames = {"distance", "wheel", "mouse"};

struct Case {
  int joint = 0;  // the model's `joint` setting: distance, wheel, mouse
  RunBody body = RunBody::point;
  double fps = 60.0;
  double f_over_fps = 0.05;
  double zeta = 0.0;
  double mass = 1.0;
  int substeps = 1;
  SoftMode mode = SoftMode::standard;
};

std::string describe(const Case& c) {
  char buf[200];
  std::snprintf(buf, sizeof buf, "%s %s f/fps %.3g zeta %.3g m %.3g substeps %d %s", kJointNames[c.joint],
                c.body == RunBody::point ? "point" : "plank", c.f_over_fps, c.zeta, c.mass, c.substeps,
                c.mode == SoftMode::exact ? "exact" : "standard");
  return buf;
}

// The grid: every value of each axis meets every other often, by strides coprime to the axis sizes.
std::vector<Case> grid() {
  const std::vector<double> ratios = {0.01, 0.03, 0.08, 0.15, 0.3};
  const std::vector<double> zetas = {0.0, 0.05, 0.3, 0.7, 1.0, 2.0};
  const std::vector<double> masses = {1e-3, 0.1, 1.0, 30.0, 1e3};
  const std::vector<int> substeps = {1, 2, 3, 4, 8};
  std::vector<Case> out;
  for (int i = 0; i < 180; ++i) {
    Case c;
    c.joint = i % 3;
    c.body = (i / 3) % 2 == 0 ? RunBody::point : RunBody::rotating_plank;
    c.mode = (i / 6) % 2 == 0 ? SoftMode::standard : SoftMode::exact;
    c.f_over_fps = ratios[(i * 7 + i / 12) % ratios.size()];
    c.zeta = zetas[(i * 5 + i / 12) % zetas.size()];
    c.mass = masses[(i * 3 + i / 13) % masses.size()];
    c.substeps = substeps[(i * 11 + i / 17) % substeps.size()];
    out.push_back(c);
  }
  return out;
}

std::size_t model_index() {
  const auto models = engine_models();
  for (std::size_t i = 0; i < models.size(); ++i) {
    if (models[i] == &kBox2DV24Model) return i;
  }
  return models.size();
}

TuneRequest request_of(const Case& c) {
  TuneRequest r;
  r.fps = c.fps;
  r.substeps = c.substeps;
  r.frequency_hz = c.f_over_fps * c.fps;
  r.damping_ratio = c.zeta;
  r.mode = c.mode;
  r.effective_mass = c.mass;
  r.engine_settings.resize(engine_models().size());
  SettingValues s = default_settings(kBox2DV24Model);
  s[0] = c.joint;
  // The rotating plank carries half its inverse effective mass in rotation (engine_run.h), which the
  // mouse joint's angular damping acts on.
  if (s.size() > 2) s[2] = c.body == RunBody::rotating_plank ? 0.5 : 0.0;
  r.engine_settings[model_index()] = s;
  return r;
}

struct Measured {
  double frequency_hz = 0.0, damping_ratio = 0.0;
  bool ok = false;
  double trajectory_error = 0.0;  // max |x_engine - x_model| / x0 over the first two periods
};

double parameter(const Parameters& p, const char* suffix) {
  for (const Parameter& q : p) {
    if (std::string_view(q.name).ends_with(suffix)) return q.value;
  }
  return 0.0;
}

// The model's own trajectory for the same run: its step map applied to (x0, 0[, 0]).
std::vector<double> model_trajectory(const Case& c, const Parameters& p, double dt, int steps, double x0) {
  const double k = parameter(p, "::stiffness"), d = parameter(p, "::damping");
  Eigen::Matrix3d a = Eigen::Matrix3d::Zero();
  if (c.joint == 2 && c.body == RunBody::rotating_plank) {
    a = box2d_v2_4_mouse_step_map(c.mass, k, d, dt, 0.5);
  } else {
    a.topLeftCorner<2, 2>() = box2d_v2_4_step_map(c.mass, k, d, dt);
  }
  Eigen::Vector3d s(x0, 0.0, 0.0);
  std::vector<double> x{x0};
  for (int i = 0; i < steps; ++i) {
    s = a * s;
    x.push_back(s(0));
  }
  return x;
}

// Long enough to see the motion: three periods of the slower of the asked and the predicted response (the
// slow pole of an over-damped one), at least 120 steps, at most 5000.
int steps_for(double hz, double zeta, double dt) {
  double rate = 2.0 * M_PI * hz;  // rad/s
  if (zeta > 1.0) rate *= zeta - std::sqrt(zeta * zeta - 1.0);
  else if (zeta > 0.3) rate *= 0.5;
  const double seconds = 3.0 * 2.0 * M_PI / std::max(rate, 1e-9);
  return std::clamp(static_cast<int>(seconds / dt), 120, 5000);
}

EngineRun run_of(const Case& c, const Parameters& parameters, const SettingValues& settings, double dt, int steps) {
  EngineRun run;
  run.effective_mass = c.mass;
  run.parameters = parameters;
  run.settings = settings;
  run.dt = dt;
  run.steps = steps;
  // Small enough that the plank's rotation stays linear (0.04 rad) and 2 m per step is never reached; large
  // enough against float's 3e-8 m near the distance joint's 0.25 m rest length.
  run.x0 = c.body == RunBody::rotating_plank ? 0.02 : 0.05;
  run.body = c.body;
  return run;
}

RunTrajectory run_engine(const Case& c, const Parameters& parameters, const SettingValues& settings, double dt,
                         int steps) {
  return kBox2DV24Engine.run(run_of(c, parameters, settings, dt, steps));
}

Measured measure(const Case& c, const Parameters& parameters, const SettingValues& settings, double dt, int steps,
                 double hz) {
  const EngineRun run = run_of(c, parameters, settings, dt, steps);
  const RunTrajectory x = kBox2DV24Engine.run(run);
  const ResponseFit fit = fit_response(x, dt);
  Measured m;
  if (fit.frequency_hz && fit.damping_ratio) {
    m = {*fit.frequency_hz, *fit.damping_ratio, true};
  }
  const std::vector<double> model = model_trajectory(c, parameters, dt, steps, run.x0);
  // Two periods (at most 100 samples): later, an undamped plank's phase carries its geometric nonlinearity
  // (a frequency shift of ~theta^2 / 8, 5e-5 at 0.02 rad) and float's drift; the fit holds the response.
  const std::size_t window = static_cast<std::size_t>(std::clamp(2.0 / (hz * dt), 20.0, 100.0));
  for (std::size_t i = 0; i < x.size() && i <= window; ++i) m.trajectory_error = std::max(m.trajectory_error, std::abs(x[i] - model[i]) / run.x0);
  return m;
}

// Sample by sample against the model's step map: float for the point; the plank's geometry (its anchor
// turning through ~0.02 rad, the wheel's perpendicular row correcting the anchor's second-order drift) is
// linear only to second order, a few 1e-3 of x0 over two undamped periods.
double trajectory_tolerance(const Case& c) { return c.body == RunBody::rotating_plank ? 1e-2 : 2e-3; }

bool has_note(const Warnings& w) {
  return std::any_of(w.begin(), w.end(), [&](const Warning& x) { return x.code == WarningCode::engine_note && x.engine == "box2d_v2_4"; });
}

bool has(const Warnings& w, WarningCode code) {
  return std::any_of(w.begin(), w.end(), [&](const Warning& x) { return x.code == code && x.engine == "box2d_v2_4"; });
}

struct Worst {
  double frequency = 0.0, damping = 0.0;
  int cases = 0;
  void add(double f_rel, double d_abs) {
    frequency = std::max(frequency, std::abs(f_rel));
    damping = std::max(damping, std::abs(d_abs));
    ++cases;
  }
};

// A refused plain export run in the engine: where the model predicts the joint rigid (m_gamma = 0 in
// float) the stretch must hold; where it predicts the spring that float rounding leaves, the run must follow
// the model's step map and fit its prediction (1 % / 0.02).
struct RefusedTally {
  int rigid = 0, third_mode = 0;
  Worst fitted;
  void print() const {
    std::printf("refused plain exports run in the engine: %d predicted rigid and held, %d predicted as the spring "
                "float rounding leaves and fitted (worst %.3e frequency, %.3e damping ratio against predicted), "
                "%d with the mouse joint's third mode held to the model's trajectory\n",
                rigid, fitted.cases, fitted.frequency, fitted.damping, third_mode);
  }
};

void hold_refused(const Case& c, const EngineReport& r, const SettingValues& settings, double dt, RefusedTally& tally) {
  if (!r.predicted.frequency_hz || !r.predicted.damping_ratio) {
    // Held, or creeping by no more than the map's real pole near 1 says (the wheel joint's un-inverted
    // gamma: spectral radius 1 + 4e-8 for d + h k a few ulp below 0).
    const RunTrajectory x = run_engine(c, r.parameters, settings, dt, 240);
    double moved = 0.0;
    for (double v : x) moved = std::max(moved, std::isfinite(v) ? std::abs(v - x[0]) : INFINITY);
    const double creep = std::pow(r.predicted.spectral_radius, 240) - 1.0;
    ASSERT_LT(creep, 1e-3);
    EXPECT_LE(moved, (1e-3 + creep) * std::abs(x[0])) << "refused, predicted rigid: the stretch moved";
    ++tally.rigid;
    return;
  }
  const double pf = *r.predicted.frequency_hz, pz = *r.predicted.damping_ratio;
  // Eight periods: an undamped plank (nothing damps its free sideways swing) trades energy with it over
  // longer runs, which the linear model of the stretch leaves out.
  const int steps = std::min(steps_for(pf, pz, dt), std::max(24, static_cast<int>(std::ceil(8.0 / (pf * dt)))));
  const Measured m = measure(c, r.parameters, settings, dt, steps, pf);
  EXPECT_LE(m.trajectory_error, trajectory_tolerance(c)) << "refused: trajectory off the model's";
  ASSERT_TRUE(m.ok) << "refused: the run could not be fitted";
  if (has_note(r.warnings)) {
    ++tally.third_mode;  // the mouse joint's third mode on the plank: held to the model's trajectory only
    return;
  }
  EXPECT_LE(std::abs(m.frequency_hz / pf - 1.0), 0.01) << "refused: measured " << m.frequency_hz << " Hz predicted " << pf;
  EXPECT_LE(std::abs(m.damping_ratio - pz), 0.02) << "refused: measured zeta " << m.damping_ratio << " predicted " << pz;
  tally.fitted.add(m.frequency_hz / pf - 1.0, m.damping_ratio - pz);
}

TEST(Box2DV24Conformance, RealEngineMeetsTheModel) {
  const std::vector<Case> cases = grid();
  ASSERT_GE(cases.size(), 60u);
  Worst predicted, exact;
  std::array<Worst, 3> by_joint_pred{}, by_joint_exact{};
  int refused = 0, inexact = 0, unfittable = 0, not_second_order = 0;
  RefusedTally refused_tally;
  Worst nearest;
  std::array<double, 2> worst_trajectory{};  // point, plank
  for (const Case& c : cases) {
    SCOPED_TRACE(describe(c));
    const TuneResult result = tune(request_of(c));
    const EngineReport& r = result.engine_reports[model_index()];
    const double dt = 1.0 / (c.fps * c.substeps);
    const double asked = result.frequency_hz;
    SettingValues settings = request_of(c).engine_settings[model_index()];

    const bool refused_export = has(r.warnings, WarningCode::engine_refuses);
    if (refused_export) {
      ++refused;
      hold_refused(c, r, settings, dt, refused_tally);
    } else if (r.predicted.frequency_hz && r.predicted.damping_ratio) {
      const Measured m = measure(c, r.parameters, settings, dt, steps_for(*r.predicted.frequency_hz, *r.predicted.damping_ratio, dt),
                                *r.predicted.frequency_hz);
      EXPECT_LE(m.trajectory_error, trajectory_tolerance(c)) << "parameters: trajectory off the model's";
      worst_trajectory[c.body == RunBody::rotating_plank] = std::max(worst_trajectory[c.body == RunBody::rotating_plank], m.trajectory_error);
      const bool third_mode = has_note(r.warnings);
      if (!m.ok) {
        // Only a response gone within 8 steps is too fast to fit.
        EXPECT_LT(std::pow(r.predicted.spectral_radius, 8), 1e-2) << "parameters: the fit failed";
        ++unfittable;
      } else if (third_mode) {
        ++not_second_order;  // the model says the motion has a third mode: held to its trajectory only
      } else {
        const double fe = m.frequency_hz / *r.predicted.frequency_hz - 1.0, de = m.damping_ratio - *r.predicted.damping_ratio;
        EXPECT_LE(std::abs(fe), 0.01) << "parameters: measured " << m.frequency_hz << " Hz predicted " << *r.predicted.frequency_hz;
        EXPECT_LE(std::abs(de), 0.02) << "parameters: measured zeta " << m.damping_ratio << " predicted " << *r.predicted.damping_ratio;
        predicted.add(fe, de);
        by_joint_pred[c.joint].add(fe, de);
      }
    } else {
      ADD_FAILURE() << "no prediction without engine_refuses";
    }

    if (r.exact && has(r.warnings, WarningCode::engine_inexact)) {
      // The nearest legal value: predicted within 1 % / 0.02 of the request, and run as predicted.
      ASSERT_TRUE(r.exact_predicted && r.exact_predicted->frequency_hz && r.exact_predicted->damping_ratio);
      const double pf = *r.exact_predicted->frequency_hz, pz = *r.exact_predicted->damping_ratio;
      EXPECT_LE(std::abs(pf / asked - 1.0), 0.01) << "nearest exact: predicted " << pf << " Hz";
      EXPECT_LE(std::abs(pz - c.zeta), 0.02) << "nearest exact: predicted zeta " << pz;
      const Measured m = measure(c, *r.exact, settings, dt, steps_for(pf, pz, dt), pf);
      EXPECT_LE(m.trajectory_error, trajectory_tolerance(c)) << "nearest exact: trajectory off the model's";
      if (m.ok) {
        EXPECT_LE(std::abs(m.frequency_hz / pf - 1.0), 0.01) << "nearest exact: measured " << m.frequency_hz;
        EXPECT_LE(std::abs(m.damping_ratio - pz), 0.02) << "nearest exact: measured zeta " << m.damping_ratio;
        nearest.add(m.frequency_hz / pf - 1.0, m.damping_ratio - pz);
      }
    } else if (r.exact) {
      ASSERT_TRUE(r.exact_predicted);
      const Measured m = measure(c, *r.exact, settings, dt, steps_for(asked, c.zeta, dt), asked);
      const double tolerance = trajectory_tolerance(c);
      EXPECT_LE(m.trajectory_error, tolerance) << "exact: trajectory off the model's";
      worst_trajectory[c.body == RunBody::rotating_plank] = std::max(worst_trajectory[c.body == RunBody::rotating_plank], m.trajectory_error);
      if (!m.ok) {
        EXPECT_LT(std::pow(r.exact_predicted->spectral_radius, 8), 1e-2) << "exact: the fit failed";
        ++unfittable;
      } else {
        const double fe = m.frequency_hz / asked - 1.0, de = m.damping_ratio - c.zeta;
        EXPECT_LE(std::abs(fe), 0.01) << "exact: measured " << m.frequency_hz << " Hz asked " << asked;
        EXPECT_LE(std::abs(de), 0.02) << "exact: measured zeta " << m.damping_ratio << " asked " << c.zeta;
        exact.add(fe, de);
        by_joint_exact[c.joint].add(fe, de);
      }
    } else {
      EXPECT_TRUE(has(r.warnings, WarningCode::engine_inexact)) << "exact empty without engine_inexact";
      ++inexact;
    }
  }
  std::printf("\nBox2D 2.4.1 conformance: %zu cases; %d plain exports refused, %d without exact (engine_inexact), "
              "%d runs too fast to fit, %d plain runs with a third mode (mouse joint, rotating plank);\n"
              "worst trajectory error against the model's step map over two periods: point %.2e, plank %.2e of x0\n",
              cases.size(), refused, inexact, unfittable, not_second_order, worst_trajectory[0], worst_trajectory[1]);
  refused_tally.print();
  std::printf("nearest legal exact (engine_inexact, predicted within 1 %% / 0.02): %d runs, worst %.3e frequency, "
              "%.3e damping ratio against their prediction\n", nearest.cases, nearest.frequency, nearest.damping);
  std::printf("%-10s %6s %14s %14s %6s %14s %14s\n", "joint", "runs", "pred |df/f|", "pred |dzeta|", "exact",
              "req |df/f|", "req |dzeta|");
  for (int j = 0; j < 3; ++j) {
    std::printf("%-10s %6d %14.3e %14.3e %6d %14.3e %14.3e\n", kJointNames[j], by_joint_pred[j].cases,
                by_joint_pred[j].frequency, by_joint_pred[j].damping, by_joint_exact[j].cases,
                by_joint_exact[j].frequency, by_joint_exact[j].damping);
  }
  std::printf("%-10s %6d %14.3e %14.3e %6d %14.3e %14.3e\n", "all", predicted.cases, predicted.frequency,
              predicted.damping, exact.cases, exact.frequency, exact.damping);
}

// Exact mode at zeta 0 types d = -h k: d + h k is 0 but for float rounding. Every joint, both bodies, the
// grid's masses, ratios and steps: each refused export runs in the engine as its `predicted` says.
TEST(Box2DV24Conformance, RefusedExportsRunAsPredicted) {
  const std::vector<double> ratios = {0.01, 0.03, 0.08, 0.15, 0.3};
  const std::vector<double> masses = {1e-3, 0.1, 1.0, 30.0, 1e3};
  const std::vector<int> substeps = {1, 2, 3, 4, 8};
  RefusedTally tally;
  int refused = 0;
  for (int i = 0; i < 36; ++i) {
    Case c;
    c.joint = i % 3;
    c.body = (i / 3) % 2 == 0 ? RunBody::point : RunBody::rotating_plank;
    c.mode = SoftMode::exact;
    c.zeta = 0.0;
    c.f_over_fps = ratios[(i * 7 + i / 6) % ratios.size()];
    c.mass = masses[(i * 3 + i / 5) % masses.size()];
    c.substeps = substeps[(i * 11 + i / 7) % substeps.size()];
    c.fps = i % 4 == 1 ? 120.0 : 60.0;
    SCOPED_TRACE(describe(c));
    const TuneRequest q = request_of(c);
    const TuneResult result = tune(q);
    const EngineReport& r = result.engine_reports[model_index()];
    if (!has(r.warnings, WarningCode::engine_refuses)) continue;
    ++refused;
    hold_refused(c, r, q.engine_settings[model_index()], 1.0 / (c.fps * c.substeps), tally);
  }
  std::printf("\nBox2D 2.4.1, exact mode at zeta 0: %d of 36 plain exports refused\n", refused);
  tally.print();
  EXPECT_GE(refused, 30);
  // d + h k a few ulp below 0 in float: the wheel joint inverts m_gamma only when it is > 0, so m_gamma stays
  // h (d + h k), the soft mass ~m and the bias ~0: the model predicts it rigid (where the distance joint's
  // inverted gamma would be an undamped spring), and it holds.
  Case wheel;
  wheel.joint = 1;
  Target t;
  t.effective_mass = 1.0;
  t.omega = 2.0 * M_PI * 5.0;
  t.dt = 1.0 / 64.0;
  t.spring = {1024.0, -16.00001};
  ASSERT_LT(static_cast<float>(-16.00001) + static_cast<float>(1.0 / 64.0) * 1024.0f, 0.0f);
  SettingValues settings = default_settings(kBox2DV24Model);
  settings[0] = 1;
  const EngineReport r = kBox2DV24Model.report(t, settings);
  ASSERT_TRUE(has(r.warnings, WarningCode::engine_refuses));
  ASSERT_FALSE(r.predicted.frequency_hz);
  RefusedTally held;
  hold_refused(wheel, r, settings, t.dt, held);
  EXPECT_EQ(held.rigid, 1);
}

// A few runs for valgrind memcheck (every b2Vec2 the runner hands Box2D must be set).
TEST(Box2DV24Runner, EveryJointAndBodyRuns) {
  for (int joint = 0; joint < 3; ++joint) {
    for (RunBody body : {RunBody::point, RunBody::rotating_plank}) {
      EngineRun run;
      run.effective_mass = 2.0;
      const char* def = joint == 1 ? "b2WheelJointDef" : joint == 2 ? "b2MouseJointDef" : "b2DistanceJointDef";
      run.parameters = {{std::string_view(joint == 1 ? "b2WheelJointDef::stiffness" : joint == 2 ? "b2MouseJointDef::stiffness" : "b2DistanceJointDef::stiffness"), 2.0 * 400.0},
                        {std::string_view(joint == 1 ? "b2WheelJointDef::damping" : joint == 2 ? "b2MouseJointDef::damping" : "b2DistanceJointDef::damping"), 0.0}};
      (void)def;
      run.settings = default_settings(kBox2DV24Model);
      run.settings[0] = joint;
      run.dt = 1.0 / 60.0;
      run.steps = 120;
      run.x0 = 0.02;
      run.body = body;
      const RunTrajectory x = kBox2DV24Engine.run(run);
      ASSERT_EQ(x.size(), 121u);
      for (double v : x) ASSERT_TRUE(std::isfinite(v));
      EXPECT_NEAR(x[0], 0.02, 1e-6);
      // 20 rad/s at 60 fps: implicit Euler, about 3.1 Hz.
      const ResponseFit fit = fit_response(x, run.dt);
      ASSERT_TRUE(fit.frequency_hz);
      EXPECT_NEAR(*fit.frequency_hz, 20.0 / (2.0 * M_PI), 0.1) << joint;
    }
  }
}

}  // namespace
}  // namespace softtune::engines
