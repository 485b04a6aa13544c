#include "softtune/integrators.h"

#include <gtest/gtest.h>

#include <cmath>

#include "softtune/methods.h"

using namespace softtune;

TEST(Integrators, SoftConstraintIsImplicitEulerToRoundOff) {
  // Catto GDC 2011, "2:3:2": with gamma = 1/(c + h k), beta = h k/(c + h k) the soft constraint solved by
  // semi-implicit Euler is identical to implicit Euler.
  for (double zeta : {0.0, 0.1, 0.5, 1.0, 3.0}) {
    for (double h : {1.0 / 30, 1.0 / 60, 1.0 / 240}) {
      const double m = 1.3, omega = 2 * M_PI * 8.0;
      const SpringConstants sc = spring_constants(m, omega, zeta);
      const Oscillator o{m, sc.stiffness, sc.damping};
      const Softness s = softness_from_spring(sc.stiffness, sc.damping, h);
      State implicit{1.0, -0.5}, soft = implicit;
      for (int i = 0; i < 1000; ++i) {
        implicit = implicit_euler_step(implicit, o, h);
        soft = soft_step(soft, m, s, h);
        ASSERT_NEAR(soft.x, implicit.x, 1e-12) << zeta << " " << h << " step " << i;
        ASSERT_NEAR(soft.v, implicit.v, 1e-12 * omega) << zeta << " " << h << " step " << i;
      }
    }
  }
}

TEST(Integrators, ImplicitEulerSatisfiesItsDefinition) {
  const Oscillator o{2.0, 300.0, 4.0};
  const double h = 0.02;
  const State s0{0.7, 1.1};
  const State s1 = implicit_euler_step(s0, o, h);
  // v1 = v0 + h a(x1, v1), x1 = x0 + h v1.
  EXPECT_NEAR(s1.v, s0.v + h * (-(o.stiffness * s1.x + o.damping * s1.v) / o.mass), 1e-13);
  EXPECT_NEAR(s1.x, s0.x + h * s1.v, 1e-15);
}

TEST(Integrators, ExplicitAndSemiImplicitFollowTheirDefinitions) {
  const Oscillator o{2.0, 300.0, 4.0};
  const double h = 0.01;
  const State s0{0.7, 1.1};
  const double a0 = -(o.stiffness * s0.x + o.damping * s0.v) / o.mass;
  const State e = explicit_euler_step(s0, o, h);
  EXPECT_DOUBLE_EQ(e.x, s0.x + h * s0.v);
  EXPECT_DOUBLE_EQ(e.v, s0.v + h * a0);
  const State si = semi_implicit_euler_step(s0, o, h);
  EXPECT_DOUBLE_EQ(si.v, s0.v + h * a0);
  EXPECT_DOUBLE_EQ(si.x, s0.x + h * si.v);
}

TEST(Integrators, SubstepsAreSoftStepsAtTheSmallerStep) {
  const double m = 1.0, h = 1.0 / 60;
  const SpringConstants sc = spring_constants(m, 2 * M_PI * 12, 0.2);
  const Oscillator o{m, sc.stiffness, sc.damping};
  State a{1.0, 0.0}, b = a;
  a = soft_substep(a, o, h, 4);
  for (int i = 0; i < 4; ++i) b = implicit_euler_step(b, o, h / 4);
  EXPECT_NEAR(a.x, b.x, 1e-14);
  EXPECT_NEAR(a.v, b.v, 1e-12);
}

TEST(Integrators, SemiImplicitConservesAModifiedEnergyUndamped) {
  // Symplectic Euler keeps x^2 omega^2 + v^2 - h omega^2 x v constant (the shadow energy): no drift.
  const double m = 1.0, omega = 5.0, h = 0.05;
  const Oscillator o{m, m * omega * omega, 0.0};
  State s{1.0, 0.0};
  auto shadow = [&](State q) { return omega * omega * q.x * q.x + q.v * q.v - h * omega * omega * q.x * q.v; };
  const double e0 = shadow(s);
  for (int i = 0; i < 10000; ++i) s = semi_implicit_euler_step(s, o, h);
  EXPECT_NEAR(shadow(s), e0, 1e-9);
}
