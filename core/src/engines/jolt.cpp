// Jolt Physics (v5, as built into npm jolt-physics 1.1.0), read in Jolt/Physics:
//   Constraints/ConstraintPart/SpringPart.h      CalculateSpringPropertiesWithFrequencyAndDamping,
//                                                ...WithStiffnessAndDamping, ...WithMassNormalizedStiffnessAndDamping,
//                                                GetBias
//   Constraints/ConstraintPart/AxisConstraintPart.h  CalculateConstraintPropertiesWithSettingsForLimit,
//                                                WarmStart, SolveVelocityConstraint, SolvePositionConstraint
//   Constraints/DistanceConstraint.cpp           CalculateConstraintProperties (mMinDistance == mMaxDistance:
//                                                one soft row, unclamped), SolvePositionConstraint (skipped
//                                                while the spring is active)
//   Constraints/SpringSettings.h                 ESpringMode, HasStiffness (mFrequency/mStiffness > 0)
//   PhysicsSystem.cpp                            Update (step_delta_time = inDeltaTime / inCollisionSteps),
//                                                JobApplyGravity, JobSolveVelocityConstraints,
//                                                JobIntegrateVelocity, JobSolvePositionConstraints
//   Body/MotionProperties.inl                    ApplyForceTorqueAndDragInternal (v *= max(0, 1 - c_L h))
//   PhysicsSettings.h                            mNumVelocitySteps = 10, mNumPositionSteps = 2
//   Body/BodyCreationSettings.h                  mLinearDamping = mAngularDamping = 0.05
//
// One Update(dt, n) runs n collision steps of h = dt / n. Each step, per body: ApplyForceTorqueAndDrag
// scales the velocity by a = max(0, 1 - mLinearDamping h); the constraint computes its soft row from the
// positions at the step's start:
//   FrequencyAndDamping: k = m_eff (2 pi f)^2, c = 2 m_eff zeta (2 pi f)   (m_eff = 1 / J M^-1 J^T)
//   StiffnessAndDamping: k, c as typed;  MassNormalizedStiffnessAndDamping: k m_eff, c m_eff
//   softness = 1 / (h (c + h k)), bias = h k softness C, effective mass = 1 / (1/m_eff + softness)
// then warm-starts the last impulse and runs mNumVelocitySteps iterations of
//   lambda = -K_soft (J v + softness total_lambda + bias);
// with one constraint the first iteration leaves J v + softness total + bias = 0 and the rest add nothing,
// and the total impulse does not depend on the warm start. Then x += h v (symplectic Euler), and the position
// steps skip the row (the spring is active). So each collision step is implicit Euler on (m_eff, k, c) after
// the damping scale (soft_substeps.h), mNumVelocitySteps >= 1 and mNumPositionSteps change nothing, and the
// spring mode changes only what is typed. Where c + h k = 0 the softness is infinite and the row does nothing
// (or NaN); k <= 0 turns the limit hard: both are refused.
#include "softtune/engines/jolt.h"

#include <array>
#include <cmath>
#include <numbers>

#include "soft_substeps.h"
#include "softtune/designer.h"
#include "softtune/exact_softness.h"

namespace softtune::engines {
namespace {

constexpr std::array<std::string_view, 3> kSpringModes = {"FrequencyAndDamping", "StiffnessAndDamping",
                                                          "MassNormalizedStiffnessAndDamping"};
constexpr std::array<SettingSpec, 5> kSettings = {{
    {"collisionSteps", 1, 1, 64, true, {}, "",
     "PhysicsSystem::Update inCollisionSteps: steps of dt / collisionSteps per update"},
    {"numVelocitySteps", 10, 1, 255, true, {}, "",
     "PhysicsSettings::mNumVelocitySteps; one soft row converges in the first"},
    {"numPositionSteps", 2, 0, 255, true, {}, "",
     "PhysicsSettings::mNumPositionSteps; skipped while the spring is active"},
    {"springMode", 0, 0, 2, true, kSpringModes, "",
     "SpringSettings::mMode: how the spring is typed (the engine turns each into k, c alike)"},
    {"linearDamping", 0.05, 0, 1e6, false, {}, "1/s",
     "BodyCreationSettings::mLinearDamping (and mAngularDamping): v *= max(0, 1 - damping h) each step"},
}};

constexpr double kFloatMax = 3.4028234663852886e38;
constexpr double kTwoPi = 2.0 * std::numbers::pi;

struct Step {
  double m, h, a, dt;
  int n;
};

Step step_of(const Target& t, const SettingValues& values) {
  const int n = static_cast<int>(values[kJoltCollisionSteps]);
  const double h = t.dt / n;
  return {t.effective_mass, h, std::max(0.0, 1.0 - values[kJoltLinearDamping] * h), t.dt, n};
}

// What the engine does with (k, c): empty when it refuses them (k <= 0 is a hard limit, c + h k near 0
// divides by zero in float, a value past float's range is infinity).
bool legal(const Step& s, double k, double c) {
  return k > 0.0 && c + s.h * k >= kJoltFloatMargin * s.h * k && k <= kFloatMax && std::abs(c) <= kFloatMax;
}

std::optional<Prediction> predict_spring(const Step& s, double k, double c) {
  if (!legal(s, k, c)) return std::nullopt;
  return predict_from_step_map(soft_substeps::power(soft_substeps::substep_map(s.m, k, c, s.h, s.a), s.n), s.dt);
}

// What the engine does with a refused spring, as typed (`typed`, in the spring mode `mode`): SpringPart
// computes k and c in float from the float fields and the body's float inverse mass (SpringPart.h
// CalculateSpringPropertiesWithFrequencyAndDamping: omega = 2 pi f, k = m_eff omega^2, c = 2 m_eff zeta
// omega; ...WithMassNormalizedStiffnessAndDamping: k / K, c / K), then softness = 1 / (h (c + h k)). Where
// c + h k rounds to 0 the softness is infinite, the row's effective mass 1 / (K + softness) is 0 and
// AxisConstraintPart::IsActive (mEffectiveMass != 0) turns the row off: the body moves free, and released at
// rest it stays (measured in the real engine). Otherwise the algebra of the soft row holds for any sign of the softness, so the step is the same
// implicit-Euler map with the damping the float sum leaves, c' = (c + h k)_float - h k: an undamped spring
// where the sum rounds to a few 1e-7 of h k (exact mode at zeta 0, one collision step), a growing one below
// (exact mode's negative damping at collisionSteps > 1). Empty where the spring is not soft (k <= 0).
std::optional<Prediction> predict_refused(const Step& s, int mode, const Parameters& typed) {
  const float inv_k = 1.0f / static_cast<float>(s.m);  // MotionProperties: mInvMass = 1 / mass
  const float hf = static_cast<float>(s.h);
  float k = 0.0f, c = 0.0f;
  const float damping = static_cast<float>(parameter_value(typed, "SpringSettings::mDamping").value_or(0.0));
  if (mode == 0) {
    const float m_eff = 1.0f / inv_k;
    const float omega = 2.0f * std::numbers::pi_v<float> *
                        static_cast<float>(parameter_value(typed, "SpringSettings::mFrequency").value_or(0.0));
    k = m_eff * (omega * omega);
    c = 2.0f * m_eff * damping * omega;
  } else {
    const float stiffness = static_cast<float>(parameter_value(typed, "SpringSettings::mStiffness").value_or(0.0));
    k = mode == 2 ? stiffness / inv_k : stiffness;
    c = mode == 2 ? damping / inv_k : damping;
  }
  if (!(k > 0.0f) || !std::isfinite(k) || !std::isfinite(c)) return std::nullopt;
  const float hk = hf * k;
  const float sum = c + hk;  // SpringPart.h: 1.0f / (inDeltaTime * (inDamping + inDeltaTime * inStiffness))
  if (hf * sum == 0.0f) return Prediction{std::nullopt, std::nullopt, 1.0, true};  // free: poles 1 and a
  const double hd = static_cast<double>(hf), kd = static_cast<double>(k);
  const double c_used = static_cast<double>(sum) - hd * kd;
  return predict_from_step_map(soft_substeps::power(soft_substeps::substep_map(s.m, kd, c_used, hd, s.a), s.n), s.dt);
}

// The SpringSettings that make the engine compute (k, c), in the chosen mode; empty when the mode cannot
// (FrequencyAndDamping needs k > 0). The engine's m_eff is the target's effective mass.
std::optional<Parameters> parameters_of(int mode, double m, double k, double c) {
  const std::string_view mode_name = kSpringModes[static_cast<std::size_t>(mode)];
  Parameter mode_parameter{"SpringSettings::mMode", 0.0, "", mode_name};
  switch (mode) {
    case 0: {
      if (!(k > 0.0)) return std::nullopt;
      const double omega = std::sqrt(k / m);
      return Parameters{mode_parameter,
                        {"SpringSettings::mFrequency", omega / kTwoPi, "Hz"},
                        {"SpringSettings::mDamping", c / (2.0 * m * omega), ""}};
    }
    case 1:
      return Parameters{mode_parameter, {"SpringSettings::mStiffness", k, "N/m"},
                        {"SpringSettings::mDamping", c, "N s/m"}};
    default:
      return Parameters{mode_parameter, {"SpringSettings::mStiffness", k / m, "1/s^2"},
                        {"SpringSettings::mDamping", c / m, "1/s"}};
  }
}

bool meets(const Prediction& p, const Target& t) { return meets_response(p, t.omega, t.damping_ratio); }

EngineReport report(const Target& t, const SettingValues& values) {
  EngineReport out;
  out.settings = describe_settings(kJoltModel, values);
  const Step s = step_of(t, values);
  const int mode = static_cast<int>(values[kJoltSpringMode]);
  const double k = t.spring.stiffness, c = t.spring.damping;
  std::optional<Parameters> plain = parameters_of(mode, s.m, k, c);
  const std::optional<Prediction> p = plain ? predict_spring(s, k, c) : std::nullopt;
  // FrequencyAndDamping cannot type k <= 0 (mFrequency <= 0 is a hard limit): the refused spring is shown
  // as stiffness and damping.
  out.parameters = plain ? std::move(*plain) : *parameters_of(1, s.m, k, c);
  if (p) {
    out.predicted = *p;
    if (!p->stable) out.warnings.push_back({WarningCode::engine_unstable, p->spectral_radius, 1.0, kJoltModel.name});
  } else if (const std::optional<Prediction> r = predict_refused(s, plain ? mode : 1, out.parameters)) {
    // Refused, yet the engine runs it: `predicted` is what it does.
    out.predicted = *r;
    out.warnings.push_back({WarningCode::engine_refuses, c + s.h * k, 0.0, kJoltModel.name,
                            r->frequency_hz ? "damping + h stiffness must be > 0 at the collision step h: below, "
                                              "`predicted` is the step with the damping float rounding leaves "
                                              "(an undamped spring near 0, growing below it)"
                                            : "damping + h stiffness rounds to 0 in float at the collision step h: "
                                              "SpringPart divides by it, the row's effective mass is 0 and the "
                                              "constraint is inactive: the body moves free"});
    if (!r->stable) out.warnings.push_back({WarningCode::engine_unstable, r->spectral_radius, 1.0, kJoltModel.name});
  } else {
    out.predicted = {std::nullopt, std::nullopt, 1.0, true};
    out.warnings.push_back({WarningCode::engine_refuses, c + s.h * k, 0.0, kJoltModel.name,
                            "SpringSettings needs stiffness (mFrequency) > 0, else the limit is hard, and "
                            "damping + h stiffness > 0, else SpringPart divides by zero"});
  }
  if (!(t.omega > 0.0)) return out;

  // Exact: softtune's exact spring at the collision step h, corrected for the linear damping (closed form,
  // soft_substeps::exact_scaled); where that needs c + h k <= 0 (zeta near 0), the least-damped spring the
  // engine takes at the asked frequency.
  const ExactSpring closed = exact_spring(s.m, t.omega, t.damping_ratio, s.h);
  std::optional<soft_substeps::Spring> candidate;
  std::optional<Prediction> e;
  if (closed.finite && !closed.clamped_to_nyquist && s.a > 0.0) {
    candidate = soft_substeps::exact_scaled(s.m, closed.spring.stiffness, closed.spring.damping, s.h, s.a);
    if (legal(s, candidate->k, candidate->c)) {
      e = soft_substeps::matched_prediction(t.omega, t.damping_ratio, s.dt);
    } else {
      candidate = soft_substeps::least_damped(s.m, t.omega, s.h, s.a, 2.0 * kJoltFloatMargin);
      if (candidate) e = predict_spring(s, candidate->k, candidate->c);
    }
  }
  if (e && meets(*e, t)) {
    out.exact = parameters_of(mode, s.m, candidate->k, candidate->c);
    out.exact_predicted = *e;
  } else if (e && e->frequency_hz && e->damping_ratio) {
    // The least-damped spring is the nearest the engine takes: given when within the nearest bars.
    const bool nearest = within_nearest(*e, t.omega, t.damping_ratio);
    if (nearest) {
      out.exact = parameters_of(mode, s.m, candidate->k, candidate->c);
      out.exact_predicted = *e;
    }
    out.warnings.push_back({WarningCode::engine_inexact, *e->frequency_hz / frequency_from_angular(t.omega) - 1.0,
                            *e->damping_ratio - t.damping_ratio, kJoltModel.name,
                            nearest ? "each collision step is implicit Euler after mLinearDamping's velocity "
                                      "scale, which always damps: `exact` is the least-damped spring it takes, "
                                      "the nearest legal value"
                                    : "each collision step is implicit Euler after mLinearDamping's velocity scale, "
                                      "which always damps: less damping needs damping + h stiffness <= 0, which "
                                      "SpringPart divides by"});
  } else {
    out.warnings.push_back({WarningCode::engine_inexact, 0.0, 0.0, kJoltModel.name,
                            "no spring reaches the asked poles: they pass the collision step's Nyquist "
                            "limit, or mLinearDamping h >= 1 stops the body every step"});
  }
  return out;
}

}  // namespace

// PhysicsSystem::Update(dt, n) for one body on one soft row: n times
//   v = max(0, 1 - c_L h) v                      (MotionProperties::ApplyForceTorqueAndDragInternal)
//   v = v - K_soft/m (v + bias)                  (AxisConstraintPart::SolveVelocityConstraint, converged)
//   x = x + h v                                  (JobIntegrateVelocity)
Eigen::Matrix2d jolt_step_map(double m, double k, double c, double dt, int collision_steps,
                              double linear_damping) {
  const double h = dt / collision_steps;
  return soft_substeps::power(
      soft_substeps::substep_map(m, k, c, h, std::max(0.0, 1.0 - linear_damping * h)), collision_steps);
}

const EngineModel kJoltModel = {
    "jolt",
    "Jolt Physics 5 (npm jolt-physics 1.1.0): SpringPart.h, AxisConstraintPart.h, DistanceConstraint.cpp, "
    "PhysicsSystem.cpp, MotionProperties.inl",
    kSettings,
    report,
};

}  // namespace softtune::engines
