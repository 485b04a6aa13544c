// Box2D v3 (github erincatto/box2d HEAD, commit 617d32a "Tunable ccd", v3.2 development), read in:
//   include/box2d/box2d.h  b2World_Step(worldId, timeStep, subStepCount): "Usually 4"; b2World_EnableWarmStarting
//   include/box2d/types.h  b2DistanceJointDef: enableSpring, hertz, dampingRatio, lower/upperSpringForce
//   src/joint.c            b2DefaultDistanceJointDef (spring off, hertz 0, spring force +-FLT_MAX),
//                          b2CreateDistanceJoint (no check on hertz or dampingRatio),
//                          b2PrepareJoint: "Clamp joint hertz based on the time step":
//                            hertz = min(constraintHertz, 0.25 inv_h) -> constraintSoftness, the joint's
//                            RIGID rows (limits, and the distance itself when the spring is off) only
//   src/distance_joint.c   b2PrepareDistanceJoint: distanceSoftness = b2MakeSoft(joint->hertz,
//                            joint->dampingRatio, context->h), the spring's own hertz, not clamped; zeroes
//                            joint->impulse when warm starting is off (once per b2World_Step)
//                          b2WarmStartDistanceJoint: v += invMass axialImpulse axis
//                          b2SolveDistanceJoint(useBias): the spring branch ignores useBias, so the spring
//                            runs whole in both the solve (useBias true) and the relax (false) stage
//   src/solver.h           b2MakeSoft: biasRate = omega / a1, massScale = a2 a3, impulseScale = a3,
//                            a1 = 2 zeta + h omega, a2 = h omega a1, a3 = 1 / (1 + a2)
//   src/solver.c           b2SolverStep: prepare joints once, then per substep: integrate velocities,
//                            warm start, solve (ITERATIONS 1), integrate positions, relax
//                            (RELAX_ITERATIONS 1); restitution and store impulses touch contacts only.
//                          b2IntegrateVelocitiesTask (v = v / (1 + h linearDamping), body default 0),
//                          b2IntegratePositionsTask (deltaPosition += h v; speed clamps, see below)
//   src/physics_world.c    b2World_Step: context.h = timeStep / subStepCount; enableWarmStarting true
// One spring joint on one body of effective mass m (axialMass = m) is then, per substep h:
//   warm start   v_a = v + lambda / m
//   solve        d1 = -massScale m (v_a + biasRate x) - impulseScale lambda; lambda1 = lambda + d1;
//                v1 = v_a + d1 / m                           ( = impulseScale v - massScale biasRate x )
//   integrate    x1 = x + h v1
//   relax        d2 = -massScale m (v1 + biasRate x1) - impulseScale lambda1; lambda2 = lambda1 + d2;
//                v2 = v1 + d2 / m                            ( = impulseScale v - massScale biasRate x1 )
// Because massScale + impulseScale = 1 the warm-started impulse cancels in the solve stage, so neither
// warm starting nor the impulse carried between substeps changes the motion, and the spring acts twice
// per substep: the relax stage adds damping of about h omega / 2 over the talk's soft step. Asked 10 Hz
// undamped at 60 fps with one substep this gives 10.0 Hz and zeta 0.71 (issue 15 measured exactly that),
// where softtune's implicit Euler predicted 8.49 Hz / 0.42; softtune's exact k', c' for 10 Hz, zeta 0.1
// give 17.0 Hz. The spring's hertz is never clamped (only constraintHertz is): the substep is stable for
// every hertz > 0 and dampingRatio >= 0 (det = is^2 (1 + 2 zeta h omega) < 1, 1 - tr + det > 0).
// Not modelled (nonlinear): the speed clamps of b2IntegratePositionsTask (maximumLinearSpeed, default
// 400 m/s; angular speed 0.25 pi / dt), lower/upperSpringForce (defaults +-FLT_MAX), joint limits and motor.
#include "softtune/engines/box2d_v3.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

#include "softtune/designer.h"
#include "softtune/exact_softness.h"

namespace softtune::engines {
namespace {

constexpr std::array<std::string_view, 2> kBoolChoices = {"false", "true"};
constexpr std::array<SettingSpec, 2> kSettings = {{
    {"subStepCount", 4, 1, 1000, true, {}, "",
     "b2World_Step subStepCount (\"Usually 4\"): the spring is softened at h = timeStep / subStepCount"},
    {"enableWarmStarting", 1, 0, 1, true, kBoolChoices, "",
     "b2World_EnableWarmStarting; one spring moves the same either way (its solve cancels the warm start)"},
}};

// Box2D v3 stores hertz and dampingRatio as float and computes omega = 2 pi hertz in float.
constexpr double kFloatMax = 3.4028234663852886e38;

struct Typed {
  double hertz = 0.0, damping_ratio = 0.0;
};

int substeps_of(const SettingValues& values) { return values.empty() ? 4 : static_cast<int>(values[0]); }
bool warm_starting_of(const SettingValues& values) { return values.size() < 2 || values[1] != 0.0; }

// The legal range: hertz > 0 (at 0 b2SolveDistanceJoint skips the spring: `if (joint->hertz > 0.0f)`),
// omega finite in float, and a1 = 2 zeta + h omega clear of zero (b2MakeSoft divides by it).
enum class Legality { ok, no_spring, divides_by_zero };
Legality legality(const Typed& p, double h) {
  if (!(p.hertz > 0.0) || !(2.0 * std::numbers::pi * p.hertz <= kFloatMax) || !std::isfinite(p.damping_ratio) ||
      std::abs(p.damping_ratio) > kFloatMax) {
    return Legality::no_spring;
  }
  const double hw = h * 2.0 * std::numbers::pi * p.hertz;
  return 2.0 * p.damping_ratio + hw >= kBox2DV3FloatMargin * hw ? Legality::ok : Legality::divides_by_zero;
}

Prediction predict_typed(const Typed& p, double dt, int substeps, bool warm_starting) {
  // Mass drops out (the v3 spring is mass-normalised: axialMass scales both impulse and 1 / m). The
  // substep's impulse column is zero (see box2d_v3_substep_map), so the frame's (x, v) block is the n-th
  // power of the substep's (x, v) block and holds every pole but the 0; warm starting, which only zeroes
  // that column, changes nothing here (box2d_v3_step_map models it for the tests).
  (void)warm_starting;
  const Eigen::Matrix2d sub = box2d_v3_substep_map(1.0, p.hertz, p.damping_ratio, dt / substeps).topLeftCorner<2, 2>();
  Eigen::Matrix2d power = Eigen::Matrix2d::Identity(), base = sub;
  for (int k = substeps; k > 0; k >>= 1) {
    if (k & 1) power = power * base;
    if (k > 1) base = base * base;
  }
  return predict_from_step_map(power, dt);
}

Parameters parameters_of(const Typed& p) {
  return {{"b2DistanceJointDef::enableSpring", 0.0, "", "true"},
          {"b2DistanceJointDef::hertz", p.hertz, "Hz"},
          {"b2DistanceJointDef::dampingRatio", p.damping_ratio, ""}};
}

bool meets(const Prediction& p, const Target& t) { return p.stable && meets_response(p, t.omega, t.damping_ratio); }

EngineReport report(const Target& t, const SettingValues& values) {
  EngineReport out;
  out.settings = describe_settings(kBox2DV3Model, values);
  const int n = substeps_of(values);
  const bool warm = warm_starting_of(values);
  const double m = t.effective_mass, dt = t.dt, h = dt / n;

  // The plain export: softtune's k, c in (hertz, ratio) form with the true effective mass.
  Typed plain;
  if (t.spring.stiffness > 0.0 && m > 0.0) {
    const double omega = std::sqrt(t.spring.stiffness / m);
    plain = {frequency_from_angular(omega), t.spring.damping / (2.0 * m * omega)};
  }
  out.parameters = parameters_of(plain);
  switch (legality(plain, h)) {
    case Legality::ok:
      out.predicted = predict_typed(plain, dt, n, warm);
      if (!out.predicted.stable) {
        out.warnings.push_back({WarningCode::engine_unstable, out.predicted.spectral_radius, 1.0, kBox2DV3Model.name});
      }
      break;
    case Legality::no_spring:
      out.predicted = {std::nullopt, std::nullopt, 1.0, true};
      out.warnings.push_back({WarningCode::engine_refuses, plain.hertz, 0.0, kBox2DV3Model.name,
                              "hertz must be > 0 (and finite in float): at 0 b2SolveDistanceJoint skips the "
                              "spring and the body moves free"});
      break;
    case Legality::divides_by_zero: {
      // Refused, yet the engine runs it. b2MakeSoft computes a1 = 2 zeta + h omega in float: at 0 the bias
      // rate is infinite and the impulse 0 x infinity, NaN. Elsewhere its algebra holds for a1 < 0 or a1 a
      // few ulp from 0 (massScale biasRate = h omega^2 a3 stays finite), so `predicted` is the substep map
      // with what was typed, which may well stay bounded.
      const float omega_f = 2.0f * std::numbers::pi_v<float> * static_cast<float>(plain.hertz);
      const float a1 = 2.0f * static_cast<float>(plain.damping_ratio) + static_cast<float>(h) * omega_f;
      const bool nan = a1 == 0.0f;
      out.predicted = nan ? Prediction{std::nullopt, std::nullopt, std::numeric_limits<double>::infinity(), false}
                          : predict_typed(plain, dt, n, warm);
      out.warnings.push_back({WarningCode::engine_refuses, 2.0 * plain.damping_ratio + h * 2.0 * std::numbers::pi * plain.hertz,
                              0.0, kBox2DV3Model.name,
                              nan ? "b2MakeSoft divides by 2 dampingRatio + h omega (h the substep), which rounds "
                                    "to 0 in float here: the spring's impulse is NaN"
                                  : "b2MakeSoft divides by 2 dampingRatio + h omega (h the substep): it must be "
                                    "> 0; exact mode's negative damping makes it <= 0, and `predicted` is what "
                                    "the substeps then do"});
      if (!out.predicted.stable && !nan) {
        out.warnings.push_back({WarningCode::engine_unstable, out.predicted.spectral_radius, 1.0, kBox2DV3Model.name});
      }
      break;
    }
  }

  // Exact: the closed form matching the substep's poles to exp(s h) (then the frame's are exp(s dt)).
  if (t.omega > 0.0) {
    if (const std::optional<Box2DV3Spring> e = box2d_v3_exact_spring(t.omega, t.damping_ratio, h)) {
      const Typed typed{e->hertz, e->damping_ratio};
      if (legality(typed, h) == Legality::ok) {
        const Prediction p = predict_typed(typed, dt, n, warm);
        if (meets(p, t)) {
          out.exact = parameters_of(typed);
          out.exact_predicted = p;
        }
      }
    }
    if (!out.exact && frequency_from_angular(t.omega) * dt >= 0.5) {
      out.warnings.push_back({WarningCode::engine_inexact, 0.0, 0.0, kBox2DV3Model.name,
                              "the asked frequency is at or above half the step rate: sampled once per "
                              "b2World_Step it aliases whatever the substeps do"});
    } else if (!out.exact) {
      // The substep's damping floor: at the asked frequency no spring damps less than this. The nearest
      // legal spring is the closed form at the least ratio above the floor that keeps b2MakeSoft's divisor
      // clear of 0 (kBox2DV3FloatMargin): given as `exact` when within the nearest bars.
      const double floor = box2d_v3_min_damping_ratio(t.omega, h);
      std::optional<Prediction> nearest;
      double step = 1e-3 * std::max(floor, 1e-6);
      for (int attempt = 0; attempt < 12 && !nearest && floor + step <= t.damping_ratio + kNearestDampingTolerance;
           ++attempt, step *= 4.0) {
        const std::optional<Box2DV3Spring> e = box2d_v3_exact_spring(t.omega, floor + step, h);
        if (!e || legality(Typed{e->hertz, e->damping_ratio}, h) != Legality::ok) continue;
        const Prediction p = predict_typed(Typed{e->hertz, e->damping_ratio}, dt, n, warm);
        if (within_nearest(p, t.omega, t.damping_ratio)) {
          nearest = p;
          out.exact = parameters_of(Typed{e->hertz, e->damping_ratio});
          out.exact_predicted = p;
        }
      }
      if (nearest) {
        out.warnings.push_back({WarningCode::engine_inexact, *nearest->frequency_hz / frequency_from_angular(t.omega) - 1.0,
                                *nearest->damping_ratio - t.damping_ratio, kBox2DV3Model.name,
                                "the spring runs in both the solve and the relax stage of every substep, "
                                "which damps at least about pi hertz h (h the substep): `exact` is the "
                                "least-damped spring b2MakeSoft takes, the nearest legal value; more substeps "
                                "lower the floor"});
      } else {
        out.warnings.push_back({WarningCode::engine_inexact, 0.0, floor - t.damping_ratio, kBox2DV3Model.name,
                                "the spring runs in both the solve and the relax stage of every substep, "
                                "which damps at least about pi hertz h (h the substep): less damping needs "
                                "2 dampingRatio + h omega <= 0, which b2MakeSoft divides by; more substeps "
                                "lower the floor"});
      }
    }
  }
  return out;
}

}  // namespace

Box2DV3Softness box2d_v3_make_soft(double hertz, double zeta, double h) {
  // solver.h b2MakeSoft
  if (hertz == 0.0) return {0.0, 0.0, 0.0};
  const double omega = 2.0 * std::numbers::pi * hertz;
  const double a1 = 2.0 * zeta + h * omega;
  const double a2 = h * omega * a1;
  const double a3 = 1.0 / (1.0 + a2);
  return {omega / a1, a2 * a3, a3};
}

Eigen::Matrix3d box2d_v3_substep_map(double m, double hertz, double zeta, double h) {
  const Box2DV3Softness s = box2d_v3_make_soft(hertz, zeta, h);
  // State (x, v, lambda). Each stage is a linear map; the substep is their product, right to left.
  // b2IntegrateVelocitiesTask: no force, no gravity, linearDamping 0 -> identity.
  // b2WarmStartDistanceJoint: stateB->linearVelocity = b2MulAdd(v, mB, P), P = axialImpulse axis.
  Eigen::Matrix3d warm = Eigen::Matrix3d::Identity();
  warm(1, 2) = 1.0 / m;
  // b2SolveDistanceJoint spring branch (any useBias):
  //   c = length - joint->length (= x); cdot = dot(axis, vr) (= v); bias = biasRate c;
  //   impulse = -massScale axialMass (cdot + bias) - impulseScale oldImpulse; joint->impulse += impulse;
  //   vB = b2MulAdd(vB, mB, P)
  Eigen::Matrix3d solve = Eigen::Matrix3d::Identity();
  const double di_dx = -s.mass_scale * m * s.bias_rate, di_dv = -s.mass_scale * m, di_dl = -s.impulse_scale;
  solve(2, 0) = di_dx;
  solve(2, 1) = di_dv;
  solve(2, 2) = 1.0 + di_dl;
  solve(1, 0) = di_dx / m;
  solve(1, 1) = 1.0 + di_dv / m;
  solve(1, 2) = di_dl / m;
  // b2IntegratePositionsTask: deltaPosition = b2MulAdd(deltaPosition, h, v) (the stretch grows by h v).
  Eigen::Matrix3d integrate = Eigen::Matrix3d::Identity();
  integrate(0, 1) = h;
  // Relax stage: b2SolveDistanceJoint(useBias = false), the same spring branch on the moved body.
  return solve * integrate * solve * warm;
}

Eigen::Matrix3d box2d_v3_step_map(double m, double hertz, double zeta, double dt, int substeps,
                                  bool warm_starting) {
  const int n = substeps < 1 ? 1 : substeps;  // b2World_Step: subStepCount = b2MaxInt(1, subStepCount)
  const Eigen::Matrix3d sub = box2d_v3_substep_map(m, hertz, zeta, dt / n);
  // sub^n by squaring.
  Eigen::Matrix3d power = Eigen::Matrix3d::Identity(), base = sub;
  for (int k = n; k > 0; k >>= 1) {
    if (k & 1) power = power * base;
    base = base * base;
  }
  // b2PrepareDistanceJoint: `if (context->enableWarmStarting == false) joint->impulse = 0.0f;`
  if (!warm_starting) power.col(2).setZero();
  return power;
}

std::optional<Box2DV3Spring> box2d_v3_exact_spring(double omega, double zeta, double h) {
  if (!(omega > 0.0) || !(h > 0.0) || !(zeta >= 0.0)) return std::nullopt;
  // Substep map (see the top): det = is (1 - u), tr = (1 - u)(1 + is), with is = impulseScale and
  // u = h^2 omega_b^2 is. Target poles z1, z2 = exp(s h): P = z1 z2, S = z1 + z2. Then
  //   is = P / (S - P),  1 - u = S - P,  W^2 = (h omega_b)^2 = (1 - S + P)(S - P) / P,
  //   2 zeta_b W = (S - 2P) / P - W^2.
  // softtune's exact implicit-Euler spring at h (unit mass) has A = k' h^2 = (1 - S + P) / P and
  // B = c' h = (S - 2P) / P, computed without cancellation (exact_softness.h), and (S - P) / P = 1 + B.
  const ExactSpring ie = exact_spring(1.0, omega, zeta, h);
  if (!ie.finite || ie.clamped_to_nyquist) return std::nullopt;
  const double a = ie.spring.stiffness * h * h, b = ie.spring.damping * h;
  const double p = std::exp(-2.0 * zeta * omega * h);
  const double w2 = a * p * (1.0 + b);
  // a1 W = 2 zeta_b W + W^2 = B: b2MakeSoft's divisor is positive only when c' > 0.
  if (!(w2 > 0.0) || !std::isfinite(w2) || !(b >= kBox2DV3FloatMargin * w2)) return std::nullopt;
  const double w = std::sqrt(w2);
  return Box2DV3Spring{w / (2.0 * std::numbers::pi * h), (b - w2) / (2.0 * w)};
}

double box2d_v3_min_damping_ratio(double omega, double h) {
  // On the boundary a1 = 0: impulseScale = 1, the substep map has det = 1 - W^2 and tr = 2 (1 - W^2), so
  // its poles are cos(phi) exp(+-i phi) with W = sin(phi). Solve |ln z| = omega h for phi in (0, pi/2),
  // f(phi) = ln(cos phi)^2 + phi^2 increasing, by Newton from below.
  const double r = omega * h;
  if (!(r > 0.0) || !std::isfinite(r)) return 0.0;
  double lo = 0.0, hi = 0.5 * std::numbers::pi;
  double phi = std::min(r, 0.5 * (lo + hi));
  for (int i = 0; i < 40; ++i) {
    const double lc = std::log(std::cos(phi));
    const double f = lc * lc + phi * phi - r * r;
    if (f > 0.0) hi = phi; else lo = phi;
    const double df = -2.0 * lc * std::tan(phi) + 2.0 * phi;
    double next = phi - f / df;
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (std::abs(next - phi) <= 1e-13 * phi) { phi = next; break; }
    phi = next;
  }
  return -std::log(std::cos(phi)) / r;
}

const EngineModel kBox2DV3Model = {
    "box2d_v3",
    "Box2D v3 (erincatto/box2d HEAD 617d32a): src/distance_joint.c, src/joint.c, src/solver.c, src/solver.h, "
    "src/physics_world.c",
    kSettings,
    report,
};

}  // namespace softtune::engines
