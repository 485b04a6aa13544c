// Godot 3.2.3 2-D's model against Godot's own equations: a literal scalar re-run of Step2DSW::step for one
// body on one DampedSpringJoint2D (integrate_forces' damp, setup's spring impulse, the 8 passes of
// DampedSpringJoint2DSW::solve with its target_vrn, integrate_velocities), and against closed forms: the
// drag four times what is typed (issue 33 measured 4.0-4.07x in Godot), and exact's poles at exp(s h).
#include "softtune/engines/godot_2d.h"

#include "engine_test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "softtune/designer.h"
#include "softtune/exact_softness.h"

namespace softtune::engines {
namespace {

using testing::target;

struct GodotBody {
  double x, v;
};

// Step2DSW::step, one body of mass m (inverse mass = k_scalar on the axis) on a DampedSpringJoint2D of rest
// length 0 to a static anchor.
GodotBody godot_step(GodotBody b, double m, double stiffness, double damping, double h, double linear_damp, int iterations) {
  // Body2DSW::integrate_forces
  double damp = 1.0 - h * linear_damp;
  if (damp < 0) damp = 0;
  b.v *= damp;
  // DampedSpringJoint2DSW::setup
  const double k_scalar = 1.0 / m, n_mass = 1.0 / k_scalar;
  double target_vrn = 0.0;
  const double v_coef = 1.0 - std::exp(-damping * h * k_scalar);
  b.v += (0.0 - b.x) * stiffness * h / m;
  // DampedSpringJoint2DSW::solve, p_iterations times
  for (int i = 0; i < iterations; ++i) {
    const double vrn = b.v - target_vrn;
    const double v_damp = -vrn * v_coef;
    target_vrn = vrn + v_damp;
    b.v += v_damp * n_mass / m;
  }
  // Body2DSW::integrate_velocities
  b.x += b.v * h;
  return b;
}

TEST(Godot2DModel, StepMapIsStep2DSWOnOneDampedSpring) {
  const double m = 0.4, h = 1.0 / 60.0, k = 250.0;
  for (double damping : {0.0, 0.7, 9.0}) {
    for (double linear_damp : {0.0, 0.1, 5.0}) {
      const Eigen::Matrix2d a = godot_2d_step_map(m, k, damping, h, linear_damp);
      for (GodotBody b0 : {GodotBody{1.0, 0.0}, GodotBody{0.0, 1.0}, GodotBody{0.3, -2.0}}) {
        const GodotBody b1 = godot_step(b0, m, k, damping, h, linear_damp, kGodot2DIterations);
        EXPECT_NEAR(a(0, 0) * b0.x + a(0, 1) * b0.v, b1.x, 1e-12);
        EXPECT_NEAR(a(1, 0) * b0.x + a(1, 1) * b0.v, b1.v, 1e-12);
      }
    }
  }
}

TEST(Godot2DModel, EveryOtherSolvePassDrags) {
  // The velocity after N passes is (1 - v_coef)^ceil(N / 2) of what setup left.
  const double m = 1.0, h = 1.0 / 60.0, damping = 3.0;
  const double kept = std::exp(-damping * h / m);
  for (int n : {1, 2, 3, 8}) {
    const GodotBody b = godot_step({0.0, 1.0}, m, 0.0, damping, h, 0.0, n);
    EXPECT_NEAR(b.v, std::pow(kept, (n + 1) / 2), 1e-14) << n;
  }
  EXPECT_EQ(kGodot2DDragPasses, 4);
}

TEST(Godot2DModel, TypedDampingActsFourTimesOverAsIssue33Measured) {
  // A designer types the textbook k = m omega^2, c = 2 m zeta omega with linear_damp 0: the frequency stays
  // within semi-implicit Euler's error of the textbook one, the damping ratio is about 4 zeta (measured
  // 4.0-4.07x).
  const double m = 1.0, h = 1.0 / 60.0;
  for (double hz : {1.0, 2.0}) {
    for (double zeta : {0.02, 0.05}) {
      const double omega = 2.0 * std::numbers::pi * hz;
      const EngineReport r = kGodot2DModel.report(target(hz, zeta, m, h, spring_constants(m, omega, zeta)), {0.0, 0});
      ASSERT_TRUE(r.predicted.damping_ratio);
      EXPECT_NEAR(*r.predicted.damping_ratio / zeta, 4.0, 0.1) << hz << " " << zeta;
      EXPECT_NEAR(*r.predicted.frequency_hz / hz, 1.0, 0.025) << hz << " " << zeta;
    }
  }
}

TEST(Godot2DModel, ExactPutsThePolesAtExpSh) {
  const double m = 20.0, h = 1.0 / 180.0;
  for (double linear_damp : {0.0, 0.1, 3.0}) {
    for (double hz : {1.0, 18.0, 54.0}) {
      for (double zeta : {0.0, 0.3, 1.0, 2.0}) {
        const double omega = 2.0 * std::numbers::pi * hz;
        const ExactSpring closed = exact_spring(m, omega, zeta, h);
        const EngineReport r = kGodot2DModel.report(target(hz, zeta, m, h, closed.spring), {linear_damp, 0});
        ASSERT_TRUE(r.exact && r.exact_predicted) << hz << " " << zeta << " " << linear_damp;
        const Eigen::Matrix2d a = godot_2d_step_map(m, (*r.exact)[0].value, (*r.exact)[1].value, h, linear_damp);
        const double e = std::exp(-zeta * omega * h);
        const double s = zeta < 1.0   ? 2.0 * e * std::cos(omega * std::sqrt(1.0 - zeta * zeta) * h)
                         : zeta > 1.0 ? 2.0 * e * std::cosh(omega * std::sqrt(zeta * zeta - 1.0) * h)
                                      : 2.0 * e;
        EXPECT_NEAR(a.determinant(), e * e, 1e-12);
        EXPECT_NEAR(a.trace(), s, 1e-12);
        // Without body damping the drag to type is a quarter of the continuous c = 2 m zeta omega.
        if (linear_damp == 0.0) {
          EXPECT_NEAR((*r.exact)[1].value, 0.5 * m * zeta * omega, 1e-9 * m * omega);
        }
      }
    }
  }
}

TEST(Godot2DModel, ABodyDampThatStopsTheBodyIsRefused) {
  const double h = 1.0 / 60.0, omega = 2.0 * std::numbers::pi * 2.0;
  const EngineReport r = kGodot2DModel.report(target(2.0, 0.1, 1.0, h, spring_constants(1.0, omega, 0.1)), {60.0, 0});
  EXPECT_TRUE(r.parameters.empty());
  EXPECT_FALSE(r.exact);
}

struct PinBody {
  double x, v, p;  // stretch, velocity, the joint's accumulated impulse P
};

// Step2DSW::step for one body pinned by a PinJoint2D (PinJoint2DSW::setup and solve on the axis): the damp,
// the warm start A->apply_impulse(-P), 8 passes of impulse = M (bias - rel_vel - softness P) with
// bias = b x / h (gB - gA = -x), rel_vel = -v, M = 1 / (1/m + softness), then x += h v.
PinBody godot_pin_step(PinBody b, double m, double softness, double bias, double h, double linear_damp) {
  b.v *= std::max(0.0, 1.0 - h * linear_damp);
  b.v -= b.p / m;
  const double mass = 1.0 / (1.0 / m + softness), velocity_bias = bias * b.x / h;
  for (int i = 0; i < kGodot2DIterations; ++i) {
    const double impulse = mass * (velocity_bias + b.v - softness * b.p);
    b.v -= impulse / m;
    b.p += impulse;
  }
  b.x += h * b.v;
  return b;
}

TEST(Godot2DModel, PinJointStepIsPinJoint2DSWAndForgetsTheWarmStart) {
  const double m = 1.5, h = 1.0 / 120.0;
  for (double softness : {1e-3, 0.05, 2.0}) {
    for (double bias : {0.2, 0.6, 1.3}) {
      for (double damp : {0.0, 0.1, 4.0}) {
        const Eigen::Matrix2d a = godot_2d_pin_step_map(m, softness, bias, h, damp);
        for (PinBody b0 : {PinBody{1.0, 0.0, 0.0}, PinBody{0.0, 1.0, 0.3}, PinBody{0.3, -2.0, -5.0}}) {
          const PinBody b1 = godot_pin_step(b0, m, softness, bias, h, damp);
          EXPECT_NEAR(a(0, 0) * b0.x + a(0, 1) * b0.v, b1.x, 1e-11);
          EXPECT_NEAR(a(1, 0) * b0.x + a(1, 1) * b0.v, b1.v, 1e-11);
        }
      }
    }
  }
}

TEST(Godot2DModel, PinJointIsTheSoftConstraintAndExactMeetsTheRequest) {
  // Without body damping the pin is implicit Euler on k = b / (h^2 s), c = (1 - b) / (h s).
  const double m = 2.0, k = 900.0, c = 12.0, h = 1.0 / 60.0;
  const double softness = 1.0 / (h * (c + h * k)), bias = h * k / (c + h * k);
  testing::expect_implicit_euler(godot_2d_pin_step_map(m, softness, bias, h, 0.0), m, k, c, h);
  for (double damp : {0.0, 0.1, 3.0}) {
    for (double zeta : {0.1, 0.5, 1.0, 2.0}) {
      const double hz = 4.0, omega = 2.0 * std::numbers::pi * hz;
      const EngineReport r = kGodot2DModel.report(target(hz, zeta, m, h, exact_spring(m, omega, zeta, h).spring), {damp, 1});
      ASSERT_TRUE(r.exact && r.exact_predicted) << damp << " " << zeta;
      EXPECT_EQ((*r.exact)[0].name, "PinJoint2D.softness");
      const Eigen::Matrix2d a = godot_2d_pin_step_map(m, (*r.exact)[0].value, (*r.exact)[1].value, h, damp);
      const double e = std::exp(-zeta * omega * h);
      EXPECT_NEAR(a.determinant(), e * e, 1e-12) << damp << " " << zeta;
    }
  }
  // Undamped with no body damping needs c + h k = 0: no softness to type.
  const EngineReport none = kGodot2DModel.report(
      target(4.0, 0.0, m, h, exact_spring(m, 2.0 * std::numbers::pi * 4.0, 0.0, h).spring), {0.0, 1});
  EXPECT_FALSE(none.exact);
  EXPECT_TRUE(none.parameters.empty());
}

}  // namespace
}  // namespace softtune::engines
