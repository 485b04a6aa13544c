// The methods' shared step (methods.cpp) against hand-worked steps and the continuous oscillator: one step of
// each Euler from (x, v) = (1, 0), the soft step equal to implicit Euler (the talk's identity), and soft_exact's
// step map carrying the continuous poles e^{(-zeta omega +- i omega_d) h}.
#include "softtune/methods.h"

#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <set>
#include <string>

namespace softtune {
namespace {

constexpr double kMass = 2.0, kOmega = 10.0, kH = 1.0 / 60.0;

TEST(Methods, NamesAreDistinctSnakeCase) {
  std::set<std::string> names;
  for (Method m : kAllMethods) {
    const std::string name(method_name(m));
    EXPECT_FALSE(name.empty());
    for (char c : name) EXPECT_TRUE(std::islower(static_cast<unsigned char>(c)) || c == '_') << name;
    names.insert(name);
  }
  EXPECT_EQ(names.size(), kAllMethods.size());
  EXPECT_EQ(method_name(Method::semi_implicit_euler), "semi_implicit_euler");
}

TEST(Methods, StepModelHoldsTheClosedFormSpring) {
  const StepModel model = make_step_model(kMass, kOmega, 0.3, kH);
  EXPECT_DOUBLE_EQ(model.h, kH);
  EXPECT_DOUBLE_EQ(model.spring.mass, kMass);
  EXPECT_NEAR(model.spring.stiffness, kMass * kOmega * kOmega, 1e-12);  // k = m omega^2
  EXPECT_NEAR(model.spring.damping, 2.0 * kMass * 0.3 * kOmega, 1e-12);  // c = 2 m zeta omega
  // Only soft_exact integrates the corrected spring.
  EXPECT_DOUBLE_EQ(method_spring(Method::soft, model).stiffness, model.spring.stiffness);
  EXPECT_DOUBLE_EQ(method_spring(Method::soft_exact, model).stiffness, model.exact.spring.stiffness);
  EXPECT_DOUBLE_EQ(method_spring(Method::soft_exact, model).damping, model.exact.spring.damping);
}

TEST(Methods, EulerStepsFromRestAtUnitStretch) {
  const StepModel model = make_step_model(kMass, kOmega, 0.0, kH);
  const double w2h = kOmega * kOmega * kH;  // the acceleration -omega^2 x over one step
  const State e = step(Method::explicit_euler, {1.0, 0.0}, model);
  EXPECT_NEAR(e.x, 1.0, 1e-15);  // x moves with the old v = 0
  EXPECT_NEAR(e.v, -w2h, 1e-12);
  const State s = step(Method::semi_implicit_euler, {1.0, 0.0}, model);
  EXPECT_NEAR(s.v, -w2h, 1e-12);
  EXPECT_NEAR(s.x, 1.0 - w2h * kH, 1e-12);  // x moves with the new v
  // Implicit Euler: x1 = x0 + h v1, v1 = v0 - h omega^2 x1, so x1 = 1 / (1 + (omega h)^2).
  const State i = step(Method::implicit_euler, {1.0, 0.0}, model);
  const double wh2 = kOmega * kOmega * kH * kH;
  EXPECT_NEAR(i.x, 1.0 / (1.0 + wh2), 1e-12);
  EXPECT_NEAR(i.v, -w2h / (1.0 + wh2), 1e-12);
}

TEST(Methods, SoftStepIsImplicitEuler) {
  for (double zeta : {0.0, 0.5, 2.0}) {
    const StepModel model = make_step_model(kMass, kOmega, zeta, kH);
    State a{0.3, -1.2}, b = a;
    for (int n = 0; n < 50; ++n) {
      a = step(Method::soft, a, model);
      b = step(Method::implicit_euler, b, model);
    }
    EXPECT_NEAR(a.x, b.x, 1e-12) << zeta;
    EXPECT_NEAR(a.v, b.v, 1e-11) << zeta;
  }
}

// The step map's trace and determinant, from its images of (1, 0) and (0, 1).
void trace_and_det(Method m, const StepModel& model, double& trace, double& det) {
  const State c1 = step(m, {1.0, 0.0}, model), c2 = step(m, {0.0, 1.0}, model);
  trace = c1.x + c2.v;
  det = c1.x * c2.v - c2.x * c1.v;
}

TEST(Methods, SoftExactStepCarriesTheContinuousPoles) {
  for (double zeta : {0.0, 0.2, 0.7}) {
    const StepModel model = make_step_model(kMass, kOmega, zeta, kH);
    double trace = 0.0, det = 0.0;
    trace_and_det(Method::soft_exact, model, trace, det);
    // Poles z = e^{(-zeta omega +- i omega_d) h}: det = e^{-2 zeta omega h}, trace = 2 e^{-zeta omega h} cos(omega_d h).
    const double decay = std::exp(-zeta * kOmega * kH), omega_d = kOmega * std::sqrt(1.0 - zeta * zeta);
    EXPECT_NEAR(det, decay * decay, 1e-9) << zeta;
    EXPECT_NEAR(trace, 2.0 * decay * std::cos(omega_d * kH), 1e-9) << zeta;
    // Plain implicit Euler on (k, c) instead: det = 1 / (1 + c h / m + k h^2 / m), solved by hand.
    double trace_ie = 0.0, det_ie = 0.0;
    trace_and_det(Method::implicit_euler, model, trace_ie, det_ie);
    EXPECT_NEAR(det_ie, 1.0 / (1.0 + 2.0 * zeta * kOmega * kH + kOmega * kOmega * kH * kH), 1e-12) << zeta;
  }
}

}  // namespace
}  // namespace softtune
