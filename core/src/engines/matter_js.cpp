// matter.js 0.20.0 (npm matter-js 0.20.0), read in src/:
//   constraint/Constraint.js  Constraint.create (stiffness = stiffness || 1 when length > 0, damping || 0,
//                             _warming = 0.4), preSolveAll (position += constraintImpulse),
//                             solveAll (timeScale = clamp(delta / _baseDelta, 0, 1)), solve (isRigid =
//                             stiffness >= 1 || length === 0: stiffness timeScale, else stiffness timeScale^2;
//                             damping timeScale; position += share force, positionPrev += damping share
//                             normal (normal . relative velocity); angle += torque), postSolveAll
//                             (constraintImpulse *= _warming)
//   core/Engine.js            Engine.create (constraintIterations = 2), Engine.update: Body.update, then
//                             two constraint passes (preSolveAll, constraintIterations x solveAll,
//                             postSolveAll), the first before and the second after the position resolver
//   body/Body.js              Body.update: Verlet, velocity = (position - positionPrev) (1 - frictionAir
//                             delta / _baseDelta) correction (correction = 1 at a constant delta), the same for
//                             the angle; Body.create (frictionAir = 0.01)
//   core/Common.js            _baseDelta = 1000 / 60 ms
//
// So matter.js has no spring constant and no mass in its constraint: each of the 2 constraintIterations
// passes moves the anchor a fraction s = stiffness tau^2 (tau = min(1, delta / 16.67 ms)) of its stretch
// toward the rest length, whatever the mass, and cuts the Verlet velocity along the constraint by damping
// tau. Each pass's moves, carried as constraintImpulse at 0.4 of their sum, are applied again at the next
// pass's start: the motion is third order (x, x_prev, the carried impulse), and the frequency at the same
// numbers changes with the iterations, with the rate (tau^2 below 60 fps, tau = 1 above) and with
// frictionAir, which scales the velocity every step. An anchor off the centre of a body turns it: the torque
// is (r x force) inverseInertia / (inverseMass + inverseInertia), so the anchor moves (1 + q) times the
// fraction, q the setting anchorLeverage; the damping acts on the centre's velocity alone.
#include "softtune/engines/matter_js.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <vector>

#include "softtune/designer.h"
#include "softtune/discrete_analysis.h"

namespace softtune::engines {
namespace {

constexpr std::array<SettingSpec, 3> kSettings = {{
    {"constraintIterations", 2, 1, 1000, true, {}, "",
     "Engine.constraintIterations: constraint solves per pass, two passes per Engine.update"},
    {"frictionAir", 0.01, 0, 1, false, {}, "",
     "Body.frictionAir: the Verlet velocity is scaled by 1 - frictionAir delta / 16.67 ms every update"},
    {"anchorLeverage", 0, 0, 1e6, false, {}, "",
     "(r x n)^2 inverseInertia / (inverseMass + inverseInertia) (1 - angularStiffness) of the body's anchor "
     "r off its centre along the constraint n: 0 at the centre"},
}};

// What a typed stiffness and damping become in Constraint.solve at a timeScale tau.
struct Fractions {
  double s = 0.0;  // the stretch moved per solve
  double d = 0.0;  // the velocity fraction removed per solve
};

Fractions fractions(double stiffness, double damping, double tau) {
  const double typed = stiffness == 0.0 ? 1.0 : stiffness;  // Constraint.create: stiffness || 1 (length > 0)
  const bool rigid = typed >= 1.0;                          // isRigid
  return {rigid ? typed * tau : typed * tau * tau, damping > 0.0 ? damping * tau : 0.0};
}

struct Step {
  double delta_ms, tau, air;  // air: Body.update's velocity scale
  int n;
  double q;
  double dt;  // s
};

Step step_of(const Target& t, const SettingValues& values) {
  const double delta = 1000.0 * t.dt;
  return {delta, std::clamp(delta / kMatterJsBaseDeltaMs, 0.0, 1.0),
          1.0 - values[kMatterJsFrictionAir] * delta / kMatterJsBaseDeltaMs,
          static_cast<int>(values[kMatterJsConstraintIterations]), values[kMatterJsAnchorLeverage], t.dt};
}

using State = std::array<double, 6>;  // u, u_prev, w, w_prev, I_u, I_w
enum { kU = 0, kUPrev = 1, kW = 2, kWPrev = 3, kIU = 4, kIW = 5 };

// One Engine.update on the state, each line the engine's.
State update(State x, const Fractions& f, double air, int n, double q) {
  // Body.update: velocity = (position - positionPrev) frictionAir; positionPrev = position; position += velocity.
  const double vu = (x[kU] - x[kUPrev]) * air, vw = (x[kW] - x[kWPrev]) * air;
  x[kUPrev] = x[kU];
  x[kU] += vu;
  x[kWPrev] = x[kW];
  x[kW] += vw;
  for (int pass = 0; pass < 2; ++pass) {
    x[kU] += x[kIU];  // Constraint.preSolveAll: position += constraintImpulse (positionPrev stays)
    x[kW] += x[kIW];
    for (int i = 0; i < n; ++i) {
      // Constraint.solve: force = stretch s, the centre moves share force, the angle torque; damping moves
      // positionPrev by d (normal . velocity) of the centre's velocity before this solve.
      const double force = -f.s * (x[kU] + x[kW]);
      const double velocity = x[kU] - x[kUPrev];
      x[kU] += force;
      x[kIU] += force;
      x[kW] += q * force;
      x[kIW] += q * force;
      x[kUPrev] += f.d * velocity;
    }
    x[kIU] *= kMatterJsWarming;  // Constraint.postSolveAll
    x[kIW] *= kMatterJsWarming;
  }
  return x;
}

Eigen::Matrix<double, 6, 6> map_of(const Fractions& f, double air, int n, double q) {
  Eigen::Matrix<double, 6, 6> a;
  for (int j = 0; j < 6; ++j) {
    State e{};
    e[static_cast<std::size_t>(j)] = 1.0;
    const State y = update(e, f, air, n, q);
    for (int i = 0; i < 6; ++i) a(i, j) = y[static_cast<std::size_t>(i)];
  }
  return a;
}

// A real pole above this per step grows fast enough to be the motion shown, oscillation or not (the
// conformance fit reads the real engine's poles by the same rule: tests/engines/js/prony_order.mjs).
constexpr double kGrowingPole = 1.01;

// The motion of a map's poles: the complex pair of largest modulus (the oscillation), unless a real pole
// grows (modulus above kGrowingPole) or there is no pair: then the largest real pole with the next largest (itself
// when there is none). Poles at 1 within 1e-9 are left out (see below). The spectral radius is over the
// poles kept.
// The eigenvalues of a 3x3 map in closed form: the characteristic cubic z^3 - t z^2 + s z - d (t the trace, s
// the sum of the principal 2x2 minors, d the determinant), one real root by Cardano's formula (the
// trigonometric form when all three are real), polished by Newton on the cubic, then the quadratic left
// after dividing it out. A tenth of EigenSolver's cost on a dynamic 3x3 (bench/tune_bench.cpp).
std::array<std::complex<double>, 3> cubic_eigenvalues(const Eigen::Matrix3d& a) {
  const double t = a.trace(), d = a.determinant();
  const double s = a(0, 0) * a(1, 1) - a(0, 1) * a(1, 0) + a(0, 0) * a(2, 2) - a(0, 2) * a(2, 0) +
                   a(1, 1) * a(2, 2) - a(1, 2) * a(2, 1);
  // z = y + t / 3: y^3 + p y + q = 0.
  const double p = s - t * t / 3.0, q = -2.0 * t * t * t / 27.0 + t * s / 3.0 - d;
  const double disc = q * q / 4.0 + p * p * p / 27.0;
  double y;
  if (disc > 0.0) {
    const double r = std::sqrt(disc);
    y = std::cbrt(-q / 2.0 + r) + std::cbrt(-q / 2.0 - r);
  } else if (p < 0.0) {
    const double m = 2.0 * std::sqrt(-p / 3.0);
    y = m * std::cos(std::acos(std::clamp(3.0 * q / (p * m), -1.0, 1.0)) / 3.0);
  } else {
    y = 0.0;  // p = q = 0: a triple root
  }
  double z = y + t / 3.0;
  for (int i = 0; i < 3; ++i) {
    const double f = ((z - t) * z + s) * z - d, df = (3.0 * z - 2.0 * t) * z + s;
    if (df == 0.0) break;
    z -= f / df;
  }
  // z^3 - t z^2 + s z - d = (z - r)(z^2 + b z + c): b = r - t, c = s + r b.
  const double b = z - t, c = s + z * b;
  const std::complex<double> root = std::sqrt(std::complex<double>(b * b / 4.0 - c));
  return {z, -b / 2.0 + root, -b / 2.0 - root};
}

Prediction predict_from_poles(const Eigen::MatrixXd& a, double dt, bool drop_neutral) {
  if (!a.allFinite()) return predict_from_step_map(a, dt);  // unstable
  std::vector<std::complex<double>> poles;
  if (a.rows() == 3 && !drop_neutral) {
    const auto roots = cubic_eigenvalues(Eigen::Matrix3d(a));
    poles.assign(roots.begin(), roots.end());
  } else {
    const Eigen::VectorXcd eigen = Eigen::EigenSolver<Eigen::MatrixXd>(a, false).eigenvalues();
    for (Eigen::Index i = 0; i < eigen.size(); ++i) {
      if (!drop_neutral || std::abs(eigen(i) - 1.0) > 1e-9) poles.push_back(eigen(i));
    }
  }
  std::sort(poles.begin(), poles.end(), [](auto x, auto y) { return std::abs(x) > std::abs(y); });
  const auto is_real = [](std::complex<double> z) { return std::abs(z.imag()) <= 1e-9 * std::abs(z); };
  std::complex<double> z1 = poles[0], z2 = std::conj(poles[0]);
  const auto pair = std::find_if(poles.begin(), poles.end(), [&](auto z) { return !is_real(z); });
  if (is_real(z1) && (std::abs(z1) > kGrowingPole || pair == poles.end())) {
    const auto next = std::find_if(poles.begin() + 1, poles.end(), is_real);
    z1 = z1.real();
    z2 = next == poles.end() ? z1 : std::complex<double>(next->real());
  } else if (is_real(z1)) {
    z1 = *pair;
    z2 = std::conj(*pair);
  }
  Eigen::Matrix2d companion;
  companion << (z1 + z2).real(), -(z1 * z2).real(), 1.0, 0.0;
  Prediction p = predict_from_step_map(companion, dt);
  p.spectral_radius = std::abs(poles[0]);
  p.stable = p.stable && classify_spectral_radius(p.spectral_radius) != Verdict::unstable;
  return p;
}

// The prediction of the anchor's stretch u + w. Without damping or without leverage it is the third-order
// map on (stretch, previous stretch, impulse) with the fraction (1 + q) s (the turn adds to the move, and
// the rest of the body's motion leaves the stretch alone); otherwise the whole map, less the body's free
// motion that keeps the stretch at zero (eigenvalue 1: the centre and the turn cancelling at the anchor).
Prediction predict_fractions(const Step& st, Fractions f) {
  if (st.q == 0.0 || f.d == 0.0) {
    const double d = st.q == 0.0 ? f.d : 0.0;
    f.s *= 1.0 + st.q;
    f.d = d;
    const Eigen::Matrix<double, 6, 6> a = map_of(f, st.air, st.n, 0.0);
    Eigen::MatrixXd r(3, 3);
    const std::array<int, 3> keep = {kU, kUPrev, kIU};
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) r(i, j) = a(keep[static_cast<std::size_t>(i)], keep[static_cast<std::size_t>(j)]);
    }
    return predict_from_poles(r, st.dt, false);
  }
  return predict_from_poles(Eigen::MatrixXd(map_of(f, st.air, st.n, st.q)), st.dt, true);
}

// What the engine does with a stiffness and damping the exact solve may type: stiffness in (0, 1) (1 and
// above is the rigid rule), damping in [0, 1].
std::optional<Prediction> predict_legal(const Step& st, double stiffness, double damping) {
  if (!(stiffness > 0.0 && stiffness < 1.0 && damping >= 0.0 && damping <= 1.0)) return std::nullopt;
  return predict_fractions(st, fractions(stiffness, damping, st.tau));
}

Parameters parameters_of(double stiffness, double damping) {
  return {{"Constraint.stiffness", stiffness, ""}, {"Constraint.damping", damping, ""}};
}

// The nearest legal value is given as exact, with its predicted error, when it is this close to the request
// (what the real-engine conformance holds exact to: 1 % of the frequency, 0.02 of the damping ratio).
constexpr double kNearFrequency = 0.01, kNearDamping = 0.02;

double scaled_miss(const Prediction& p, const Target& t) {
  if (!p.frequency_hz || !p.damping_ratio || !p.stable) return INFINITY;
  return std::hypot((*p.frequency_hz / frequency_from_angular(t.omega) - 1.0) / kExactFrequencyTolerance,
                    (*p.damping_ratio - t.damping_ratio) / kExactDampingTolerance);
}

// The least-damped legal spring at the asked frequency: damping 0, the stiffness by bisection on ln f
// (the frequency rises with the stiffness).
std::optional<std::pair<double, Prediction>> undamped_at_frequency(const Step& st, const Target& t) {
  const double asked = frequency_from_angular(t.omega);
  double lo = std::log(1e-12), hi = std::log(1.0 - 1e-9);
  std::optional<std::pair<double, Prediction>> best;
  for (int i = 0; i < 80; ++i) {
    const double mid = 0.5 * (lo + hi);
    const std::optional<Prediction> p = predict_legal(st, std::exp(mid), 0.0);
    if (!p || !p->frequency_hz) {
      hi = mid;
      continue;
    }
    if (!best || std::abs(*p->frequency_hz / asked - 1.0) < std::abs(*best->second.frequency_hz / asked - 1.0)) {
      best = std::make_pair(std::exp(mid), *p);
    }
    (*p->frequency_hz < asked ? lo : hi) = mid;
  }
  return best;
}

EngineReport report(const Target& t, const SettingValues& values) {
  EngineReport out;
  out.settings = describe_settings(kMatterJsModel, values);
  const Step st = step_of(t, values);
  // The plain export: what a designer types from the continuous spring, the Verlet step's own fractions
  // (stiffness = k h^2 / m moves the stretch by h^2 k / m per step, damping = c h / m cuts the velocity).
  const double m = t.effective_mass, h = t.dt;
  const double stiffness = t.spring.stiffness * h * h / m, damping = t.spring.damping * h / m;
  out.parameters = parameters_of(stiffness, damping);
  out.predicted = predict_fractions(st, fractions(stiffness, damping, st.tau));
  if (!(stiffness > 0.0 && stiffness < 1.0)) {
    out.warnings.push_back({WarningCode::engine_refuses, stiffness, 1.0, kMatterJsModel.name,
                            "Constraint.stiffness 0 becomes 1, and 1 or more is the rigid rule (stiffness "
                            "timeScale per solve): predicted is that rigid constraint"});
  }
  if (damping < 0.0) {
    out.warnings.push_back({WarningCode::engine_refuses, damping, 0.0, kMatterJsModel.name,
                            "Constraint.solve applies damping only when it is > 0: predicted is damping 0"});
  }
  if (!out.predicted.stable) {
    out.warnings.push_back({WarningCode::engine_unstable, out.predicted.spectral_radius, 1.0, kMatterJsModel.name});
  }
  if (!(t.omega > 0.0)) return out;

  // Exact: the solver from the small-fraction reading of the step (3.33 n (1 + q) s tau^2 = (omega h)^2: each
  // pass's move plus the carried impulse, 2 + 4/3 times per update; the velocity cut 2 n d tau plus
  // frictionAir), then the least-damped spring when that cannot reach the damping ratio.
  const double wh = t.omega * h;
  const double s_guess = std::min(0.5, wh * wh / ((2.0 + 4.0 / 3.0) * st.n * (1.0 + st.q) * st.tau * st.tau));
  const double d_guess = std::clamp((2.0 * t.damping_ratio * wh - (1.0 - st.air)) / (2.0 * st.n * st.tau), 1e-4, 0.5);
  const ResponseSolve solve = solve_response(
      [&](double s_try, double d_try) { return predict_legal(st, s_try, d_try); }, t.omega, t.damping_ratio,
      s_guess, d_guess);
  double best_s = solve.p0, best_d = solve.p1;
  Prediction best = solve.prediction;
  bool found = solve.prediction.frequency_hz.has_value();
  if (!solve.met) {
    if (const auto undamped = undamped_at_frequency(st, t);
        undamped && (!found || scaled_miss(undamped->second, t) < scaled_miss(best, t))) {
      best_s = undamped->first;
      best_d = 0.0;
      best = undamped->second;
      found = true;
    }
  }
  if (!found || !best.frequency_hz || !best.damping_ratio) {
    out.warnings.push_back({WarningCode::engine_inexact, 0.0, 0.0, kMatterJsModel.name,
                            "no stiffness below 1 reaches the asked frequency at this step and these "
                            "constraintIterations"});
    return out;
  }
  const double frequency_error = *best.frequency_hz / frequency_from_angular(t.omega) - 1.0;
  const double damping_error = *best.damping_ratio - t.damping_ratio;
  const bool met = meets_response(best, t.omega, t.damping_ratio) && best.stable;
  if (met || (best.stable && std::abs(frequency_error) <= kNearFrequency && std::abs(damping_error) <= kNearDamping)) {
    out.exact = parameters_of(best_s, best_d);
    out.exact_predicted = best;
  }
  if (!met) {
    out.warnings.push_back({WarningCode::engine_inexact, frequency_error, damping_error, kMatterJsModel.name,
                            "the constraint's fractions damp by themselves, and frictionAir adds to it: less "
                            "damping needs Constraint.damping < 0, which matter.js ignores"});
  }
  return out;
}

}  // namespace

Eigen::Matrix<double, 6, 6> matter_js_step_map(double stiffness, double damping, double delta_ms, int iterations,
                                               double friction_air, double leverage) {
  const double tau = std::clamp(delta_ms / kMatterJsBaseDeltaMs, 0.0, 1.0);
  return map_of(fractions(stiffness, damping, tau), 1.0 - friction_air * delta_ms / kMatterJsBaseDeltaMs,
                iterations, leverage);
}

const EngineModel kMatterJsModel = {
    "matter_js",
    "matter.js 0.20.0 (npm matter-js 0.20.0): src/constraint/Constraint.js (create, preSolveAll, solveAll, "
    "solve, postSolveAll), src/core/Engine.js (update), src/body/Body.js (update)",
    kSettings,
    report,
};

}  // namespace softtune::engines
