#pragma once
// Exact solution of m x'' + c x' + k x = 0 from (x0, v0), for the three damping regimes
// (Catto GDC 2011, "1:1:3"; any ODE text). With omega = sqrt(k/m), zeta = c / (2 m omega):
//   under-damped (zeta < 1):  x = e^(-zeta omega t) (x0 cos(wd t) + (v0 + zeta omega x0)/wd sin(wd t)),
//                             wd = omega sqrt(1 - zeta^2)
//   critical (zeta = 1):      x = e^(-omega t) (x0 + (v0 + omega x0) t)
//   over-damped (zeta > 1):   x = A e^(r1 t) + B e^(r2 t), r1,2 = -omega (zeta -+ sqrt(zeta^2 - 1)),
//                             A = (v0 - r2 x0)/(r1 - r2), B = x0 - A
// omega = 0 (no spring): x = x0 + v0 t.

#include "softtune/integrators.h"

namespace softtune {

/// State at time t (s) of the oscillator with natural angular frequency omega (rad/s) and damping
/// ratio zeta, started at `initial`.
State analytic_state(State initial, double omega, double zeta, double t);

}  // namespace softtune
