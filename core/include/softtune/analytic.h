#pragma once
// Exact solution of m x'' + c x' + k x = 0 from (x0, v0), for the three damping regimes
// (Catto GDC 2011, "1:1:3"; any ODE text). With omega = sqrt(k/m), zeta = c / (2 m omega):
//   under-damped (zeta < 1):  x = e^(-zeta omega t) (x0 cos(wd t) + (v0 + zeta omega x0)/wd sin(wd t)),
//                             wd = omega sqrt(1 - zeta^2)
//   critical (zeta = 1):      x = e^(-omega t) (x0 + (v0 + omega x0) t)
//   over-damped (zeta > 1):   x = A e^(r1 t) + B e^(r2 t), r1,2 = -omega (zeta -+ sqrt(zeta^2 - 1)),
//                             A = (v0 - r2 x0)/(r1 - r2), B = x0 - A
// omega = 0 (no spring): x = x0 + v0 t.

#include <vector>

#include <Eigen/Core>

#include "softtune/integrators.h"

namespace softtune {

/// State at time t (s) of the oscillator with natural angular frequency omega (rad/s) and damping
/// ratio zeta, started at `initial`.
State analytic_state(State initial, double omega, double zeta, double t);

/// The exact motion over one step h as a linear map: [x(t + h), v(t + h)] = E [x(t), v(t)]. The motion is
/// linear in its start, so E's columns are the motion from (1, 0) and from (0, 1) after h. Iterating E
/// gives the closed form on the step grid, the way a method's step matrix replays that method.
Eigen::Matrix2d analytic_step_matrix(double omega, double zeta, double h);

/// What a plot of the response needs of the exact motion: how long to show (three periods of the
/// frequency f, Hz, or 1 s without a spring: a 0.5 Hz spring completes its swings), the flow over one
/// step h, and the position from (1, 0) on a fine grid of `kExactMotionPoints` intervals.
struct ExactMotion {
  double duration_s = 1.0;
  Eigen::Matrix2d step_matrix = Eigen::Matrix2d::Identity();
  double smooth_dt_s = 0.0;         ///< s between the fine samples
  std::vector<double> smooth_x;     ///< x(i smooth_dt_s), i = 0..kExactMotionPoints, from x0 = 1, v0 = 0
};

inline constexpr int kExactMotionPoints = 200;

ExactMotion exact_motion(double omega, double zeta, double frequency_hz, double h);

}  // namespace softtune
