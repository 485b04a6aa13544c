#include "softtune/effective_mass.h"
#include "softtune/effective_mass_terms.h"

#include <gtest/gtest.h>

#include <random>

using namespace softtune;

namespace {
Body2D body2d(double mass, double inertia, Eigen::Vector2d position) {
  Body2D b;
  b.mass = mass;
  b.inertia = inertia;
  b.position = position;
  return b;
}
Body2D ground2d() {
  Body2D b;
  b.is_static = true;
  return b;
}
}  // namespace

TEST(EffectiveMass, PointMassOnGroundIsItsMass) {
  Constraint2D c;
  c.body_a = ground2d();
  c.body_b = body2d(3.0, 0.5, {1, 2});
  c.anchor_a = {0, 0};
  c.anchor_b = {1, 2};  // at the centre of mass: rotation plays no part
  c.axis = {0, 1};
  EXPECT_DOUBLE_EQ(1.0 / inverse_effective_mass(c), 3.0);
}

TEST(EffectiveMass, TwoBodiesGiveTheReducedMass) {
  Constraint2D c;
  c.body_a = body2d(2.0, 1.0, {0, 0});
  c.body_b = body2d(6.0, 1.0, {1, 0});
  c.anchor_a = {0, 0};
  c.anchor_b = {1, 0};
  c.axis = {1, 0};
  EXPECT_NEAR(1.0 / inverse_effective_mass(c), 2.0 * 6.0 / 8.0, 1e-15);
  EXPECT_DOUBLE_EQ(box2d_reduced_mass(2.0, false, 6.0, false), 1.5);
}

TEST(EffectiveMass, OffsetAnchorAddsPerpendicularLeverOverInertia) {
  // A plank hung at offset d from its centre, pulled perpendicular to the plank: K = 1/m + d^2 / I.
  const double m = 4.0, length = 2.0, inertia = m * length * length / 12.0;
  for (double d : {0.0, 0.25, 0.5, 1.0}) {
    Constraint2D c;
    c.body_a = ground2d();
    c.body_b = body2d(m, inertia, {0, 0});
    c.anchor_a = {d, 1};
    c.anchor_b = {d, 0};
    c.axis = {0, 1};
    EXPECT_NEAR(inverse_effective_mass(c), 1.0 / m + d * d / inertia, 1e-14) << d;
    // Along the plank the lever is zero: the offset does not matter.
    c.axis = {1, 0};
    EXPECT_NEAR(inverse_effective_mass(c), 1.0 / m, 1e-14) << d;
  }
  // b2LinearStiffness sees only the mass.
  EXPECT_DOUBLE_EQ(box2d_reduced_mass(0.0, true, m, false), m);
}

TEST(EffectiveMass, TermsAreEachBodysMassAndLever) {
  // Body A 2 kg, I = 0.5 at the origin, anchor 0.3 m off across the axis; body B 3 kg, I = 0.4, anchor
  // 0.5 m off: K = 1/2 + 0.3^2 / 0.5 + 1/3 + 0.5^2 / 0.4.
  Constraint2D c;
  c.body_a = body2d(2.0, 0.5, {0, 0});
  c.body_b = body2d(3.0, 0.4, {1, 0});
  c.anchor_a = {0, 0.3};
  c.anchor_b = {1, 0.5};
  c.axis = {1, 0};
  const InverseMassTerms t = inverse_effective_mass_terms(c);
  EXPECT_DOUBLE_EQ(t.a_translational, 0.5);
  EXPECT_NEAR(t.a_rotational, 0.09 / 0.5, 1e-15);
  EXPECT_DOUBLE_EQ(t.b_translational, 1.0 / 3.0);
  EXPECT_NEAR(t.b_rotational, 0.25 / 0.4, 1e-15);
  EXPECT_NEAR(inverse_effective_mass(c), 0.5 + 0.18 + 1.0 / 3.0 + 0.625, 1e-15);
  c.body_a = ground2d();  // a static body adds nothing
  const InverseMassTerms g = inverse_effective_mass_terms(c);
  EXPECT_EQ(g.a_translational, 0.0);
  EXPECT_EQ(g.a_rotational, 0.0);
  c.type = ConstraintType::angular;  // angular: only 1/I
  const InverseMassTerms r = inverse_effective_mass_terms(c);
  EXPECT_EQ(r.b_translational, 0.0);
  EXPECT_DOUBLE_EQ(r.b_rotational, 1.0 / 0.4);
}

TEST(EffectiveMass, AngularIsTheReducedInertia) {
  Constraint2D c;
  c.type = ConstraintType::angular;
  c.body_a = body2d(1.0, 2.0, {0, 0});
  c.body_b = body2d(1.0, 6.0, {3, 0});
  EXPECT_NEAR(1.0 / inverse_effective_mass(c), 2.0 * 6.0 / 8.0, 1e-15);
  c.body_a = ground2d();
  EXPECT_NEAR(1.0 / inverse_effective_mass(c), 6.0, 1e-15);
}

TEST(EffectiveMass, LockedRotationIgnoresTheLever) {
  Constraint2D c;
  c.body_a = ground2d();
  c.body_b.mass = 2.0;  // no inertia: rotation locked
  c.anchor_b = {0.0, 5.0};
  c.axis = {1, 0};
  EXPECT_DOUBLE_EQ(1.0 / inverse_effective_mass(c), 2.0);
}

TEST(EffectiveMass, ThreeDimensionalRotatedTensor) {
  // A box with principal moments (1, 2, 4) rotated 90 degrees about z: its body x axis points along
  // world y, so world y sees Ixx = 1 and world x sees Iyy = 2.
  Constraint3D c;
  c.type = ConstraintType::angular;
  c.body_a.is_static = true;
  c.body_b.mass = 1.0;
  c.body_b.inertia = Eigen::Vector3d(1, 2, 4).asDiagonal();
  c.body_b.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(EIGEN_PI / 2, Eigen::Vector3d::UnitZ()));
  c.axis = {0, 1, 0};
  EXPECT_NEAR(1.0 / inverse_effective_mass(c), 1.0, 1e-12);
  c.axis = {1, 0, 0};
  EXPECT_NEAR(1.0 / inverse_effective_mass(c), 2.0, 1e-12);
  // Linear, lever r = (0, 0, 1) with axis x: r x n = (0, 1, 0), world inverse inertia about y is 1/1.
  c.type = ConstraintType::linear;
  c.body_b.position = {0, 0, 0};
  c.anchor_b = {0, 0, 1};
  EXPECT_NEAR(inverse_effective_mass(c), 1.0 / 1.0 + 1.0 / 1.0, 1e-12);
}

TEST(EffectiveMass, UnitImpulseExperimentEqualsJacobian2D) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-3.0, 3.0), pos(0.1, 10.0);
  for (int i = 0; i < 500; ++i) {
    Constraint2D c;
    c.type = i % 5 == 0 ? ConstraintType::angular : ConstraintType::linear;
    c.body_a = i % 7 == 0 ? ground2d() : body2d(pos(rng), pos(rng), {u(rng), u(rng)});
    c.body_b = body2d(pos(rng), pos(rng), {u(rng), u(rng)});
    c.anchor_a = {u(rng), u(rng)};
    c.anchor_b = {u(rng), u(rng)};
    c.axis = Eigen::Vector2d(u(rng), u(rng)).normalized();
    const double k = inverse_effective_mass(c);
    EXPECT_NEAR(unit_impulse_response(c), k, 1e-12 * k) << i;
  }
}

TEST(EffectiveMass, UnitImpulseExperimentEqualsJacobian3D) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-3.0, 3.0), pos(0.1, 10.0);
  auto random_body = [&] {
    Body3D b;
    b.mass = pos(rng);
    const Eigen::Matrix3d a = Eigen::Matrix3d::Random();
    b.inertia = a * a.transpose() + Eigen::Matrix3d::Identity() * 0.5;  // symmetric positive definite
    b.position = {u(rng), u(rng), u(rng)};
    b.orientation = Eigen::Quaterniond(Eigen::Vector4d(u(rng), u(rng), u(rng), u(rng))).normalized();
    return b;
  };
  for (int i = 0; i < 500; ++i) {
    Constraint3D c;
    c.type = i % 5 == 0 ? ConstraintType::angular : ConstraintType::linear;
    c.body_a = random_body();
    if (i % 7 == 0) c.body_a.is_static = true;
    c.body_b = random_body();
    c.anchor_a = {u(rng), u(rng), u(rng)};
    c.anchor_b = {u(rng), u(rng), u(rng)};
    c.axis = Eigen::Vector3d(u(rng), u(rng), u(rng)).normalized();
    const double k = inverse_effective_mass(c);
    EXPECT_NEAR(unit_impulse_response(c), k, 1e-12 * k) << i;
  }
}
