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
// sets m_gamma = 0 and the joint turns rigid, so an exact-mode spring at zeta = 0 cannot be typed: `exact`
// is then softtune's exact spring at zeta = kExactDampingTolerance / 2, within the tolerance (closed form).
// The mouse joint also multiplies the body's angular velocity by 0.98 in InitVelocityConstraints: on a body
// that turns (rotationShare > 0) that is a third state, modelled by box2d_v2_4_mouse_step_map.
#include "softtune/engines/box2d_v2_4.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>
#include <complex>

#include "softtune/designer.h"
#include "softtune/discrete_analysis.h"
#include "softtune/exact_softness.h"

namespace softtune::engines {
namespace {

// The joint kinds share the spring math; the mouse joint also multiplies the body's angular velocity by
// 0.98 each step (b2MouseJoint::InitVelocityConstraints: "Cheat with some damping", wB *= 0.98f), which
// damps the share of the anchor's motion that is the body's rotation: rotationShare says how much that is.
constexpr std::array<std::string_view, 3> kJointChoices = {"distance", "wheel", "mouse"};
constexpr std::array<SettingSpec, 3> kSettings = {{
    {"joint", 0, 0, 2, true, kJointChoices, "",
     "which joint carries the spring (b2DistanceJointDef, b2WheelJointDef along its axis, b2MouseJointDef)"},
    {"velocityIterations", 8, 1, 1000, true, {}, "",
     "b2World::Step velocityIterations; one joint converges in the first"},
    {"rotationShare", 0, 0, 1, false, {}, "",
     "not a Box2D field: the share of 1/m_eff that is the body's rotation, invI (r x u)^2 m_eff (0 for a "
     "point or fixedRotation body, 0.5 for the rotating plank); the mouse joint's 0.98 angular damping "
     "acts on it"},
}};

enum class Joint { distance = 0, wheel = 1, mouse = 2 };

// Box2D 2.4.1 stores stiffness and damping as float: a value beyond float's range becomes infinity.
constexpr double kFloatMax = 3.4028234663852886e38;

struct Setup {
  double m = 1.0, h = 1.0 / 60.0;
  Joint joint = Joint::distance;
  double rotation_share = 0.0;
  bool angular_damping() const { return joint == Joint::mouse && rotation_share > 0.0; }
};

Setup setup_of(const Target& t, const SettingValues& values) {
  Setup s;
  s.m = t.effective_mass;
  s.h = t.dt;
  if (!values.empty()) s.joint = static_cast<Joint>(static_cast<int>(values[0]));
  if (values.size() > 2) s.rotation_share = values[2];
  return s;
}

// The poles the stretch shows from a release at rest: of the mouse joint's three (x, translation,
// rotation) modes, the pair with the largest weight in x (the residues of x after a release from rest).
// The third is the body turning about its anchor, free but for the 0.98 damping: a real pole whose weight
// in the stretch box2d_v2_4_mouse_third_mode_weight gives.
struct MouseModes {
  std::array<std::complex<double>, 3> z{};
  std::array<double, 3> weight{};
  int third = 0;
};
MouseModes mouse_modes(const Eigen::Matrix3d& a) {
  MouseModes out;
  Eigen::EigenSolver<Eigen::Matrix3d> solver(a, /*computeEigenvectors=*/true);
  const Eigen::Vector3cd z = solver.eigenvalues();
  const Eigen::Matrix3cd v = solver.eigenvectors();
  const Eigen::Matrix3cd vi = v.inverse();
  for (int i = 0; i < 3; ++i) {
    out.z[i] = z(i);
    out.weight[i] = std::abs(v(0, i) * vi(i, 0));
  }
  // A conjugate pair shares one weight; the third mode is the real one outside the pair of largest weight.
  for (int i = 1; i < 3; ++i) {
    if (out.weight[i] < out.weight[out.third]) out.third = i;
  }
  return out;
}

Prediction predict_mouse_rotating(const Eigen::Matrix3d& a, double h) {
  if (!a.allFinite()) return predict_from_step_map(Eigen::MatrixXd(a), h);
  const MouseModes modes = mouse_modes(a);
  std::array<std::complex<double>, 2> pair{};
  for (int i = 0, j = 0; i < 3; ++i) {
    if (i != modes.third) pair[j++] = modes.z[i];
  }
  if (std::abs(pair[1]) > std::abs(pair[0])) std::swap(pair[0], pair[1]);
  if (pair[0].imag() < 0.0) std::swap(pair[0], pair[1]);
  Prediction out;
  out.spectral_radius = std::max({std::abs(modes.z[0]), std::abs(modes.z[1]), std::abs(modes.z[2])});
  out.stable = classify_spectral_radius(out.spectral_radius) != Verdict::unstable;
  double frequency = 0.0, zeta = 0.0;
  if (achieved_from_poles(pair[0], pair[1], h, frequency, zeta) && std::isfinite(frequency) && std::isfinite(zeta)) {
    out.frequency_hz = frequency;
    out.damping_ratio = zeta;
  }
  return out;
}

// The step with what was typed, without the legality check: (k, d) as the engine's step map holds them.
Prediction predict_typed(const Setup& s, double k, double d) {
  if (s.angular_damping()) return predict_mouse_rotating(box2d_v2_4_mouse_step_map(s.m, k, d, s.h, s.rotation_share), s.h);
  return predict_from_step_map(box2d_v2_4_step_map(s.m, k, d, s.h), s.h);
}

std::optional<Prediction> predict_spring(const Setup& s, double k, double d) {
  const double h = s.h;
  // The engine divides by h (d + h k) and treats k <= 0 as rigid: only a positive k and d + h k > 0 act
  // as the spring that was typed.
  if (!(k > 0.0) || !(d + h * k >= kBox2DV24FloatMargin * h * k) || k > kFloatMax || std::abs(d) > kFloatMax) return std::nullopt;
  return predict_typed(s, k, d);
}

// What the engine does with a refused (k, d), k > 0 and finite in float: InitVelocityConstraints computes
// m_gamma = h (d + h k) in float from the float fields and the float step. At 0 the joint is rigid
// (m_gamma = 0: the velocity along the axis is zeroed, the stretch holds); otherwise its step is the same
// implicit-Euler map with the damping the float sum leaves, d' = (d + h k)_float - h k: where d + h k
// rounds to a few 1e-7 of h k (exact mode at zeta 0) that is an undamped spring (symplectic Euler), where it
// is clearly negative (a negative typed damping) the map grows or turns unstable.
struct Refused {
  Prediction predicted;
  bool rigid = false;
};
Refused predict_refused(const Setup& s, double k, double d) {
  const float hf = static_cast<float>(s.h), kf = static_cast<float>(k), df = static_cast<float>(d);
  const float hk = hf * kf;
  const float sum = df + hk;  // b2_distance_joint.cpp: m_gamma = h * (d + h * k)
  if (hf * sum == 0.0f) return {{std::nullopt, std::nullopt, 1.0, true}, true};
  const double hd = static_cast<double>(hf);
  Setup used = s;
  used.h = hd;
  // b2_wheel_joint.cpp inverts m_gamma only `if (m_gamma > 0.0f)`: below 0 it stays g = h (d + h k), so the
  // row is the soft step whose softness is g itself: the implicit-Euler map with d + h k = 1 / (h^2 (d + h k)),
  // hugely negative, which zeroes the velocity along the axis each step. Its poles are a real one near 1 (the
  // stretch holds, or creeps for a typed damping well below -h k) and one near 0: rigid, with that map's
  // spectral radius and stability.
  if (s.joint == Joint::wheel && sum < 0.0f) {
    const double d_wheel = 1.0 / (hd * hd * static_cast<double>(sum)) - hd * static_cast<double>(kf);
    const Prediction p = predict_typed(used, static_cast<double>(kf), d_wheel);
    return {{std::nullopt, std::nullopt, p.spectral_radius, p.stable}, true};
  }
  const double d_used = static_cast<double>(sum) - static_cast<double>(hd * kf);
  return {predict_typed(used, static_cast<double>(kf), d_used), false};
}

Parameters parameters_of(const Setup& s, double k, double d) {
  switch (s.joint) {
    case Joint::wheel:
      return {{"b2WheelJointDef::stiffness", k, "N/m"}, {"b2WheelJointDef::damping", d, "N s/m"}};
    case Joint::mouse:
      return {{"b2MouseJointDef::stiffness", k, "N/m"}, {"b2MouseJointDef::damping", d, "N s/m"},
              {"b2MouseJointDef::maxForce", kBox2DV24MouseMaxForce, "N"}};
    case Joint::distance:
      break;
  }
  return {{"b2DistanceJointDef::stiffness", k, "N/m"}, {"b2DistanceJointDef::damping", d, "N s/m"}};
}

bool meets(const Prediction& p, const Target& t) { return meets_response(p, t.omega, t.damping_ratio); }

// The mouse joint's 0.98 angular damping on a rotating body: a third, real mode in the stretch.
void add_third_mode_note(const Setup& s, double k, double d, Warnings& warnings) {
  if (!s.angular_damping()) return;
  const double w3 = box2d_v2_4_mouse_third_mode_weight(s.m, k, d, s.h, s.rotation_share);
  if (w3 > kBox2DV24MouseThirdModeLimit) {
    warnings.push_back({WarningCode::engine_note, w3, kBox2DV24MouseThirdModeLimit, kBox2DV24Model.name,
                        "the mouse joint's 0.98 angular damping on a rotating body adds a third, real "
                        "mode to the stretch (value: its weight): `predicted` is the oscillating pair, "
                        "the motion is not second order"});
  }
}

// softtune's exact spring at zeta' = kExactDampingTolerance / 2 when less was asked: its poles differ from
// the request's by less than the tolerance, and its d + h k stays clear of the engine's zero.
std::optional<ExactSpring> nearly_undamped(const Target& t, const Setup& s) {
  const double zeta = 0.5 * kExactDampingTolerance;
  if (!(t.damping_ratio >= 0.0 && t.damping_ratio < zeta)) return std::nullopt;
  const ExactSpring e = exact_spring(s.m, t.omega, zeta, s.h);
  if (!e.finite || e.clamped_to_nyquist) return std::nullopt;
  const std::optional<Prediction> p = predict_spring(s, e.spring.stiffness, e.spring.damping);
  if (!p || !meets(*p, t)) return std::nullopt;
  return e;
}

EngineReport report(const Target& t, const SettingValues& values) {
  EngineReport out;
  out.settings = describe_settings(kBox2DV24Model, values);
  const Setup s = setup_of(t, values);
  const double m = s.m, h = s.h;
  const double k = t.spring.stiffness, d = t.spring.damping;
  out.parameters = parameters_of(s, k, d);
  if (const std::optional<Prediction> p = predict_spring(s, k, d)) {
    out.predicted = *p;
    if (!p->stable) {
      out.warnings.push_back({WarningCode::engine_unstable, p->spectral_radius, 1.0, kBox2DV24Model.name});
    }
    add_third_mode_note(s, k, d, out.warnings);
  } else if (k > 0.0 && k <= kFloatMax && std::abs(d) <= kFloatMax) {
    // Refused (d + h k too close to 0 or below it), yet the engine runs it: `predicted` is what it does.
    const Refused r = predict_refused(s, k, d);
    out.predicted = r.predicted;
    out.warnings.push_back({WarningCode::engine_refuses, d + h * k, 0.0, kBox2DV24Model.name,
                            r.rigid ? "stiffness must be > 0 and damping + h stiffness > 0: here h (damping + h "
                                      "stiffness) rounds to 0 in float (or below it, for the wheel joint), "
                                      "m_gamma is not inverted and the joint is rigid"
                                    : "stiffness must be > 0 and damping + h stiffness > 0: below, `predicted` is "
                                      "the step with the damping that float rounding leaves (an undamped spring "
                                      "near 0, growing below it)"});
    if (!r.rigid && !r.predicted.stable) {
      out.warnings.push_back({WarningCode::engine_unstable, r.predicted.spectral_radius, 1.0, kBox2DV24Model.name});
    }
    if (!r.rigid) add_third_mode_note(s, k, d, out.warnings);
  } else {
    // What the engine does instead: k <= 0 makes the joint rigid, a value past float's range infinity.
    out.predicted = {std::nullopt, std::nullopt, 1.0, true};
    out.warnings.push_back({WarningCode::engine_refuses, d + h * k, 0.0, kBox2DV24Model.name,
                            "stiffness must be > 0 and damping + h stiffness > 0, else m_gamma = 0 and "
                            "the joint is rigid"});
  }
  // Exact: the (k, d) whose implicit-Euler poles are exp(s h) is softtune's exact spring (exact_softness.h,
  // a closed form); where the engine cannot take it (zeta = 0 needs d + h k = 0), or the mouse joint's
  // angular damping moves its poles, the solver finds the nearest spring it can.
  if (t.omega > 0.0) {
    const ExactSpring closed = exact_spring(m, t.omega, t.damping_ratio, h);
    const std::optional<Prediction> p = predict_spring(s, closed.spring.stiffness, closed.spring.damping);
    if (s.angular_damping()) {
      // No spring makes the mouse joint's three-mode stretch a second-order response; the solver matches
      // the oscillating pair, and the answer stands only while the third mode stays faint.
      SpringConstants guess = spring_constants(m, t.omega, t.damping_ratio);
      if (closed.finite && closed.spring.damping + h * closed.spring.stiffness > 0.0) guess = closed.spring;
      const ResponseSolve solve = solve_response(
          [&](double k_try, double d_try) { return predict_spring(s, k_try, d_try); }, t.omega,
          t.damping_ratio, guess.stiffness, guess.damping);
      const double w3 = solve.met ? box2d_v2_4_mouse_third_mode_weight(m, solve.p0, solve.p1, h, s.rotation_share) : 1.0;
      if (solve.met && w3 <= kBox2DV24MouseThirdModeLimit) {
        out.exact = parameters_of(s, solve.p0, solve.p1);
        out.exact_predicted = solve.prediction;
      } else {
        out.warnings.push_back({WarningCode::engine_inexact, solve.frequency_error, solve.damping_error,
                                kBox2DV24Model.name,
                                "the mouse joint multiplies the body's angular velocity by 0.98 each step: on "
                                "a rotating body that adds a third, real mode to the stretch which no "
                                "stiffness and damping remove (a distance or wheel joint has none)"});
      }
    } else if (closed.finite && !closed.clamped_to_nyquist && p && meets(*p, t)) {
      out.exact = parameters_of(s, closed.spring.stiffness, closed.spring.damping);
      out.exact_predicted = *p;
    } else if (const std::optional<ExactSpring> near = nearly_undamped(t, s)) {
      // Asked (nearly) undamped: the exact spring at half the damping tolerance, which the engine takes
      // (d + h k = m (1 - P) / (P h) > 0), in closed form instead of the solver.
      out.exact = parameters_of(s, near->spring.stiffness, near->spring.damping);
      out.exact_predicted = predict_spring(s, near->spring.stiffness, near->spring.damping);
    } else {
      SpringConstants guess = spring_constants(m, t.omega, t.damping_ratio);
      if (closed.finite && closed.spring.damping + h * closed.spring.stiffness > 0.0) guess = closed.spring;
      const ResponseSolve solve = solve_response(
          [&](double k_try, double d_try) { return predict_spring(s, k_try, d_try); }, t.omega,
          t.damping_ratio, guess.stiffness, guess.damping);
      // Not met: the solver's nearest, when the engine takes it and it is within the nearest bars.
      const bool nearest = !solve.met && within_nearest(solve.prediction, t.omega, t.damping_ratio) &&
                           predict_spring(s, solve.p0, solve.p1).has_value();
      if (solve.met || nearest) {
        out.exact = parameters_of(s, solve.p0, solve.p1);
        out.exact_predicted = solve.prediction;
      }
      if (!solve.met) {
        out.warnings.push_back({WarningCode::engine_inexact, solve.frequency_error, solve.damping_error,
                                kBox2DV24Model.name,
                                nearest ? "its step is implicit Euler, which always damps: `exact` is the "
                                          "nearest spring the joint takes"
                                        : "its step is implicit Euler, which always damps: zero damping needs "
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

// b2MouseJoint on a body whose anchor moves by translation (share 1 - a of 1/m_eff) and rotation (share a),
// per b2World::Step, state (x, u_t, u_r) with x = C along the axis and u_t + u_r = Cdot:
//   InitVelocityConstraints  wB *= 0.98f                                       -> u_r *= 0.98
//                            m_gamma = 1 / (h (d + h k)), m_C = C h k m_gamma, m_mass = 1 / (K + gamma)
//   SolveVelocityConstraints impulse = -m_mass (Cdot + m_C + m_gamma m_impulse); the warm start cancels
//                            as for the distance joint; vB += invMass P, wB += invI cross(rB, P)
//                                                     -> u_t += (1 - a) P / m, u_r += a P / m
//   b2Island::Solve          positions += h velocities                         -> x += h (u_t + u_r)
Eigen::Matrix3d box2d_v2_4_mouse_step_map(double m, double k, double d, double h, double rotation_share) {
  const double gamma_i = 1.0 / (h * (d + h * k));
  const double soft_mass = 1.0 / (1.0 / m + gamma_i);
  const double bias_per_x = h * k * gamma_i;
  Eigen::Matrix3d damp = Eigen::Matrix3d::Identity();
  damp(2, 2) = 0.98;
  Eigen::Matrix3d solve = Eigen::Matrix3d::Identity();
  // P = -soft_mass (u_t + u_r + bias_per_x x)
  const Eigen::RowVector3d p_row(-soft_mass * bias_per_x, -soft_mass, -soft_mass);
  solve.row(1) += (1.0 - rotation_share) / m * p_row;
  solve.row(2) += rotation_share / m * p_row;
  Eigen::Matrix3d integrate = Eigen::Matrix3d::Identity();
  integrate(0, 1) = h;
  integrate(0, 2) = h;
  return integrate * solve * damp;
}

double box2d_v2_4_mouse_third_mode_weight(double m, double k, double d, double h, double rotation_share) {
  const Eigen::Matrix3d a = box2d_v2_4_mouse_step_map(m, k, d, h, rotation_share);
  if (!a.allFinite()) return 1.0;
  const MouseModes modes = mouse_modes(a);
  return modes.weight[modes.third];
}

const EngineModel kBox2DV24Model = {
    "box2d_v2_4",
    "Box2D 2.4.1: b2_distance_joint.cpp, b2_wheel_joint.cpp, b2_mouse_joint.cpp, b2_island.cpp",
    kSettings,
    report,
};

}  // namespace softtune::engines
