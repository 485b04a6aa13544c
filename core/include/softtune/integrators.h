#pragma once
// One step of each integrator for the oscillator m x'' + c x' + k x = 0 (Catto GDC 2011, "1:2").
// Pure functions: (state, parameters, h) -> next state. No allocation.

#include "softtune/softness.h"

namespace softtune {

/// Position (m) and velocity (m/s) of the 1-D oscillator, or of a constraint's C and Cdot.
struct State {
  double x = 0.0;
  double v = 0.0;
};

/// Explicit Euler: x1 = x0 + h v0, v1 = v0 + h a(x0, v0), a = -(k x + c v)/m ("1:2:1").
State explicit_euler_step(State s, const Oscillator& o, double h);

/// Semi-implicit (symplectic) Euler: v1 = v0 + h a(x0, v0), x1 = x0 + h v1 ("1:2:2").
State semi_implicit_euler_step(State s, const Oscillator& o, double h);

/// Implicit Euler: v1 = v0 + h a(x1, v1), x1 = x0 + h v1, solved in closed form ("1:2:3"):
/// v1 = (m v0 - h k x0) / (m + h c + h^2 k).
State implicit_euler_step(State s, const Oscillator& o, double h);

/// The soft constraint solved with semi-implicit Euler ("2:2:3"): the constraint force lambda satisfies
/// v1 + (beta/h) x0 + gamma lambda = 0 with v1 = v0 + h lambda / m, so
/// lambda = -(v0 + beta x0 / h) / (h/m + gamma); then x1 = x0 + h v1.
/// `softness` must be `soft` or `rigid`; any other kind applies no constraint force.
State soft_step(State s, double mass, const Softness& softness, double h);

/// The soft constraint with n substeps of h/n per step, softness recomputed for h/n from (k, c).
State soft_substep(State s, const Oscillator& o, double h, int substeps);

}  // namespace softtune
