// Box2D 2.4.1 (Debian's libbox2d-dev 2.4.1), read in src/dynamics:
//   b2_distance_joint.cpp  b2DistanceJoint::InitVelocityConstraints, SolveVelocityConstraints,
//                          SolvePositionConstraints
//   b2_wheel_joint.cpp     the spring row (m_springMass, m_gamma, m_bias): the same three lines
//   b2_mouse_joint.cpp     InitVelocityConstraints (m_gamma, m_beta): the same softness per axis
//   b2_island.cpp          b2Island::Solve: integrate velocities, solve velocity constraints, integrate
//                          positions (semi-implicit Euler), then position iterations
// The joint is soft whenever stiffness > 0:
//   m_gamma = h (d + h k); m_gamma = m_gamma != 0 ? 1 / m_gamma : 0
//   m_bias = C h k m_gamma;  m_softMass = 1 / (invMass + m_gamma)
//   impulse = -m_softMass (Cdot + m_bias + m_gamma m_impulse)
// With one joint the velocity iterations converge in the first one (the second adds zero impulse whatever
// was warm-started), and SolvePositionConstraints returns at once for a spring (minLength < maxLength), so
// one world step is the talk's soft step: exactly implicit Euler on (m, k, d). Where d + h k = 0 the engine
// sets m_gamma = 0 and the joint turns rigid, so an exact-mode spring at zeta = 0 cannot be typed.
#include "softtune/engines/box2d_v2_4.h"

#include <array>
#include <cmath>

#include "softtune/designer.h"
#include "softtune/exact_softness.h"

namespace softtune::engines {
namespace {

// The joint kinds share the spring math; the mouse joint also multiplies the body's angular velocity by
// 0.98 each step (b2MouseJoint::InitVelocityConstraints), which only matters for a rotating body.
constexpr std::array<std::string_view, 3> kJointChoices = {"distance", "wheel", "mouse"};
constexpr std::array<SettingSpec, 2> kSettings = {{
    {"joint", 0, 0, 2, true, kJointChoices, "", "which joint carries the spring (all three soften alike)"},
    {"velocityIterations", 8, 1, 1000, true, {}, "",
     "b2World::Step velocityIterations; one joint converges in the first"},
}};

// Box2D 2.4.1 stores stiffness and damping as float: a value beyond float's range becomes infinity.
constexpr double kFloatMax = 3.4028234663852886e38;

std::optional<Prediction> predict_spring(double m, double k, double d, double h) {
  // The engine divides by h (d + h k) and treats k <= 0 as rigid: only a positive k and d + h k > 0 act
  // as the spring that was typed.
  if (!(k > 0.0) || !(d + h * k >= kBox2DV24FloatMargin * h * k) || k > kFloatMax || std::abs(d) > kFloatMax) return std::nullopt;
  return predict_from_step_map(box2d_v2_4_step_map(m, k, d, h), h);
}

Parameters parameters_of(double k, double d) {
  return {{"b2DistanceJointDef::stiffness", k, "N/m"}, {"b2DistanceJointDef::damping", d, "N s/m"}};
}

EngineReport report(const Target& t, const SettingValues& values) {
  EngineReport out;
  out.settings = describe_settings(kBox2DV24Model, values);
  const double m = t.effective_mass, h = t.dt;
  const double k = t.spring.stiffness, d = t.spring.damping;
  out.parameters = parameters_of(k, d);
  if (const std::optional<Prediction> p = predict_spring(m, k, d, h)) {
    out.predicted = *p;
    if (!p->stable) {
      out.warnings.push_back({WarningCode::engine_unstable, p->spectral_radius, 1.0, kBox2DV24Model.name});
    }
  } else {
    // What the engine does instead: m_gamma = 0 makes the joint rigid (k > 0) or absent (k <= 0).
    out.predicted = {std::nullopt, std::nullopt, 1.0, true};
    out.warnings.push_back({WarningCode::engine_refuses, d + h * k, 0.0, kBox2DV24Model.name,
                            "stiffness must be > 0 and damping + h stiffness > 0, else m_gamma = 0 and "
                            "the joint is rigid"});
  }
  // Exact: the (k, d) whose implicit-Euler poles are exp(s h) is softtune's exact spring (exact_softness.h,
  // a closed form); where the engine cannot take it (zeta = 0 needs d + h k = 0), the solver finds the
  // nearest spring it can.
  if (t.omega > 0.0) {
    const ExactSpring closed = exact_spring(m, t.omega, t.damping_ratio, h);
    const std::optional<Prediction> p = predict_spring(m, closed.spring.stiffness, closed.spring.damping, h);
    if (closed.finite && !closed.clamped_to_nyquist && p && p->frequency_hz && p->damping_ratio &&
        std::abs(*p->frequency_hz / frequency_from_angular(t.omega) - 1.0) <= kExactFrequencyTolerance &&
        std::abs(*p->damping_ratio - t.damping_ratio) <= kExactDampingTolerance) {
      out.exact = parameters_of(closed.spring.stiffness, closed.spring.damping);
      out.exact_predicted = *p;
    } else {
      const SpringConstants guess = spring_constants(m, t.omega, t.damping_ratio);
      const ResponseSolve solve = solve_response(
          [&](double k_try, double d_try) { return predict_spring(m, k_try, d_try, h); }, t.omega,
          t.damping_ratio, guess.stiffness, guess.damping);
      if (solve.met) {
        out.exact = parameters_of(solve.p0, solve.p1);
        out.exact_predicted = solve.prediction;
      } else {
        out.warnings.push_back({WarningCode::engine_inexact, solve.frequency_error, solve.damping_error,
                                kBox2DV24Model.name,
                                "its step is implicit Euler, which always damps: zero damping needs "
                                "damping + h stiffness = 0, where the joint turns rigid"});
      }
    }
  }
  return out;
}

}  // namespace

// Box2D 2.4.1 b2Island::Solve for one body on a static ground through one soft joint:
//   v1 = v0 + impulse / m, impulse = -m_soft (v0 + bias) (warm start cancels, see above)
//   x1 = x0 + h v1
// with m_soft = 1 / (1/m + gamma_i), gamma_i = 1 / (h (d + h k)), bias = x0 h k gamma_i.
Eigen::Matrix2d box2d_v2_4_step_map(double m, double k, double d, double h) {
  const double gamma_i = 1.0 / (h * (d + h * k));
  const double soft_mass = 1.0 / (1.0 / m + gamma_i);
  const double bias_per_x = h * k * gamma_i;
  Eigen::Matrix2d a;
  // v1 = v0 - (soft_mass / m) (v0 + bias_per_x x0)
  a(1, 0) = -(soft_mass / m) * bias_per_x;
  a(1, 1) = 1.0 - soft_mass / m;
  a(0, 0) = 1.0 + h * a(1, 0);
  a(0, 1) = h * a(1, 1);
  return a;
}

const EngineModel kBox2DV24Model = {
    "box2d_v2_4",
    "Box2D 2.4.1: b2_distance_joint.cpp, b2_wheel_joint.cpp, b2_mouse_joint.cpp, b2_island.cpp",
    kSettings,
    report,
};

}  // namespace softtune::engines
