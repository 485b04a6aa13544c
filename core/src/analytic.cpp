#include "softtune/analytic.h"

#include <cmath>

namespace softtune {

State analytic_state(State initial, double omega, double zeta, double t) {
  const double x0 = initial.x, v0 = initial.v;
  if (omega == 0.0) return {x0 + v0 * t, v0};
  if (zeta < 1.0) {
    const double wd = omega * std::sqrt(1.0 - zeta * zeta);
    const double decay = std::exp(-zeta * omega * t);
    const double b = (v0 + zeta * omega * x0) / wd;
    const double cs = std::cos(wd * t), sn = std::sin(wd * t);
    const double x = decay * (x0 * cs + b * sn);
    // d/dt of the above.
    const double v = decay * (-zeta * omega * (x0 * cs + b * sn) + wd * (-x0 * sn + b * cs));
    return {x, v};
  }
  if (zeta == 1.0) {
    const double decay = std::exp(-omega * t);
    const double b = v0 + omega * x0;
    return {decay * (x0 + b * t), decay * (b - omega * (x0 + b * t))};
  }
  const double root = std::sqrt(zeta * zeta - 1.0);
  const double r1 = -omega / (zeta + root);  // slow root, written without cancellation
  const double r2 = -omega * (zeta + root);  // fast root
  const double a = (v0 - r2 * x0) / (r1 - r2);
  const double b = x0 - a;
  const double e1 = std::exp(r1 * t), e2 = std::exp(r2 * t);
  return {a * e1 + b * e2, a * r1 * e1 + b * r2 * e2};
}

Eigen::Matrix2d analytic_step_matrix(double omega, double zeta, double h) {
  const State from_x = analytic_state({1.0, 0.0}, omega, zeta, h);
  const State from_v = analytic_state({0.0, 1.0}, omega, zeta, h);
  Eigen::Matrix2d e;
  e << from_x.x, from_v.x, from_x.v, from_v.v;
  return e;
}

ExactMotion exact_motion(double omega, double zeta, double frequency_hz, double h) {
  ExactMotion m;
  m.duration_s = frequency_hz > 0.0 ? 3.0 / frequency_hz : 1.0;
  m.step_matrix = analytic_step_matrix(omega, zeta, h);
  m.smooth_dt_s = m.duration_s / kExactMotionPoints;
  m.smooth_x.reserve(kExactMotionPoints + 1);
  for (int i = 0; i <= kExactMotionPoints; ++i) m.smooth_x.push_back(analytic_state({1.0, 0.0}, omega, zeta, i * m.smooth_dt_s).x);
  return m;
}

}  // namespace softtune
