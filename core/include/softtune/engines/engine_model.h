#pragma once
// A real engine's step, modelled (docs/engines.md): how one engine turns the numbers a user types into the
// motion of one soft 1-D constraint on an effective mass, with the engine's own defaults and the settings a
// user may change. One file per engine (core/src/engines/<engine>.cpp) cites, at its top, the engine version
// and the files and functions it mirrors; each step of the model names the engine line it follows.
//
// Every model is linear: one engine step (the dt the user passes to the engine's step call) maps the
// engine's state -- position error x, velocity v, then any state the engine carries from step to step, such
// as a warm-started impulse -- by a square matrix. The eigenvalue pair of largest modulus is the motion the
// engine shows; s = ln(z) / dt reads its natural frequency and damping ratio (achieved_from_poles, as the
// discrete analysis does for softtune's own integrators).

#include <Eigen/Core>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "softtune/softness.h"
#include "softtune/warnings.h"

namespace softtune::engines {

/// A setting that changes the engine's step (substeps, iterations, integrator...). A numeric setting has an
/// inclusive range; a setting with choices takes one of them, and its value is the choice's index.
struct SettingSpec {
  std::string_view name;          ///< the engine's own name, e.g. "subStepCount", "integrator"
  double default_value = 0.0;     ///< the engine's default
  double min = 0.0, max = 0.0;    ///< legal range (choices: 0 .. choices.size() - 1)
  bool integer = false;
  std::span<const std::string_view> choices = {};  ///< empty for a numeric setting
  std::string_view unit = {};
  std::string_view meaning = {};  ///< one line: what it changes in the step
};

/// Each setting's value, indexed like the model's specs.
using SettingValues = std::vector<double>;

/// A value to type into the engine, under the engine's own field name ("b2DistanceJointDef::hertz",
/// "solref[0]"), a static string. An enumerated field (Jolt's ESpringMode) has `choice` set and value 0.
struct Parameter {
  std::string_view name;
  double value = 0.0;
  std::string_view unit = {};
  std::string_view choice = {};
};
using Parameters = std::vector<Parameter>;

/// What the engine does with a set of parameters.
struct Prediction {
  std::optional<double> frequency_hz;   ///< Hz, natural frequency |s| / 2 pi; empty when undefined
  std::optional<double> damping_ratio;  ///< -Re(s) / |s|; empty when undefined
  double spectral_radius = 0.0;         ///< of the step map, per engine step
  bool stable = true;                   ///< spectral radius <= 1 + kMarginalBand
};

/// What the engine is asked to do.
struct Target {
  double effective_mass = 1.0;  ///< kg (kg m^2 for angular), the constraint's true m_eff
  double omega = 0.0;           ///< rad/s, the requested natural angular frequency (after any clamp)
  double damping_ratio = 0.0;   ///< the requested damping ratio
  double dt = 1.0 / 60.0;       ///< s, the step passed to the engine's step call: 1 / (fps substeps)
  SpringConstants spring;       ///< softtune's k, c in the request's mode (k', c' in exact mode)
  std::optional<double> box2d_reduced_mass;  ///< kg, what b2LinearStiffness would use (constraint given)
};

/// One engine's answer: the tune response's engines.<name>.
struct EngineReport {
  Parameters settings;                  ///< the settings assumed (defaults, or the request's)
  Parameters parameters;                ///< what to type for softtune's k, c (the plain export)
  Prediction predicted;                 ///< what the engine does with `parameters`
  std::optional<Parameters> exact;      ///< what to type so the engine does what was asked; empty: cannot
  std::optional<Prediction> exact_predicted;  ///< what the engine does with `exact`
  Warnings warnings;                    ///< each with engine = the model's name
};

/// A modelled engine: its name, what was read, its settings and its report.
struct EngineModel {
  std::string_view name;      ///< key in the tune response, e.g. "box2d_v3"
  std::string_view modelled;  ///< engine version and sources read, e.g. "Box2D v3.1 src/distance_joint.c"
  std::span<const SettingSpec> settings;
  /// The report for a target; `values` is indexed like `settings` and within their ranges.
  EngineReport (*report)(const Target& target, const SettingValues& values);
};

/// Every modelled engine, in the order answers list them.
std::span<const EngineModel* const> engine_models();

/// The model called `name`, or null.
const EngineModel* find_engine_model(std::string_view name);

/// The defaults of a model's settings.
SettingValues default_settings(const EngineModel& model);

/// The same for a registered model, built once (empty for a model not in engine_models()).
const SettingValues& default_settings_of(const EngineModel& model);

/// The settings as the report lists them (choices by name).
Parameters describe_settings(const EngineModel& model, const SettingValues& values);

/// The prediction of a linear step map over dt: the eigenvalue pair of largest modulus read through
/// achieved_from_poles; spectral radius over all eigenvalues. A non-finite map predicts unstable. A 2x2 map
/// takes the closed-form eigenvalues (tens of nanoseconds); larger ones Eigen's EigenSolver.
Prediction predict_from_step_map(const Eigen::MatrixXd& step_map, double dt);
Prediction predict_from_step_map(const Eigen::Matrix2d& step_map, double dt);  ///< the 2x2 map, no allocation

/// The value of the parameter called `name`, or empty.
std::optional<double> parameter_value(const Parameters& parameters, std::string_view name);

/// The result of solving for parameters whose prediction meets a target response.
struct ResponseSolve {
  double p0 = 0.0, p1 = 0.0;   ///< the best parameters found
  Prediction prediction;       ///< their prediction
  double frequency_error = 0.0;  ///< relative, predicted / asked - 1
  double damping_error = 0.0;    ///< absolute, predicted - asked
  bool met = false;              ///< within kExactFrequencyTolerance and kExactDampingTolerance
};

/// Tolerances for an engine's `exact` parameters (issue: 0.1 % frequency, 0.005 damping ratio); the solver
/// aims ten times tighter.
inline constexpr double kExactFrequencyTolerance = 1e-3;
inline constexpr double kExactDampingTolerance = 5e-3;
inline constexpr int kMaxSolveEvaluations = 400;

/// The nearest legal answer's bars, the real-engine conformance bars (1 % frequency, 0.02 damping ratio): where
/// no parameters the engine takes meet the exact tolerances, the nearest it takes is still given as `exact`
/// when its prediction is stable and within these of the request, flagged by an engine_inexact warning that
/// carries its predicted errors (value: relative frequency, limit: damping ratio).
inline constexpr double kNearestFrequencyTolerance = 1e-2;
inline constexpr double kNearestDampingTolerance = 2e-2;

/// Whether a stable prediction is within the nearest bars of natural frequency omega (rad/s), ratio zeta.
bool within_nearest(const Prediction& p, double omega, double zeta);

/// Whether a prediction has natural frequency omega (rad/s) and damping ratio zeta within `scale` times the
/// exact tolerances. Stability is the caller's to add (an engine that clamps may report a met response
/// whose map is marginal).
bool meets_response(const Prediction& p, double omega, double zeta, double scale = 1.0);

/// Finds parameters (p0, p1) whose prediction has natural frequency omega (rad/s) and damping ratio zeta:
/// damped Newton on the residual (ln f / f_asked, zeta - zeta_asked) over (ln p0, p1), with a
/// finite-difference Jacobian, from the guess. p0 is a positive stiffness-like parameter (searched in log
/// space), p1 a damping-like one of either sign. `predict` returns empty for parameters the engine refuses
/// (outside its legal range) and the solver then shortens its step. When the target cannot be met, the
/// nearest point found is returned with met = false. At most kMaxSolveEvaluations predictions.
ResponseSolve solve_response(const std::function<std::optional<Prediction>(double p0, double p1)>& predict,
                             double omega, double zeta, double guess0, double guess1);

}  // namespace softtune::engines
