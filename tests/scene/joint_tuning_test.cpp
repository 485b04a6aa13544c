// Joint tuning (joint_tuning.cpp) in a Box2D run: each joint is tuned with its effective mass, so the talk's
// Buddhas all land on the request; with Box2D's reduced mass the off-centre planks miss as implicit Euler on the
// true mass predicts.
#include "softtune/scene/joint_tuning.h"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <tuple>

#include "scene_builders.h"
#include "softtune/discrete_analysis.h"
#include "softtune/scene/runner.h"
#include "softtune/validation.h"

namespace softtune::scene {
namespace {

using namespace test;

// m_eff of a plank (mass m, L x H) held at r from its centre, perpendicular to it: 1 / (1/m + r^2 / I).
double plank_effective_mass(double m, double l, double h, double r) { return 1.0 / (1.0 / m + r * r / (m * (l * l + h * h) / 12.0)); }

TEST(SceneRunner, BuddhasLandOnTheRequestWithTheEffectiveMass) {
  const std::vector<double> offsets = {0.0, 0.4, 0.7, 0.95};
  const SceneResult r = run_scene(buddhas(offsets));
  ASSERT_FALSE(r.error);
  for (std::size_t i = 0; i < offsets.size(); ++i) {
    EXPECT_NEAR(r.joints[i].effective_mass, plank_effective_mass(4.0, 2.0, 0.2, offsets[i]), 1e-4) << i;
    ASSERT_TRUE(r.probes[i].frequency_error) << i;
    EXPECT_LT(std::abs(*r.probes[i].frequency_error), 0.03) << i;
    EXPECT_LT(std::abs(*r.probes[i].damping_ratio_error), 0.03) << i;
  }
}

TEST(SceneRunner, Box2DReducedMassMissesOffCentrePlanksAsImplicitEulerOnTheTrueMassPredicts) {
  const std::vector<double> offsets = {0.0, 0.7, 0.95};
  const SceneResult r = run_scene(buddhas(offsets), RunOptions{MassModel::box2d_reduced});
  ASSERT_FALSE(r.error);
  EXPECT_LT(std::abs(*r.probes[0].frequency_error), 0.03);
  for (std::size_t i = 1; i < offsets.size(); ++i) {
    // k, c were computed for m = 4 kg but the plank resists with m_eff: the joint is implicit Euler on
    // (m_eff, k, c), whose discrete poles give the frequency Box2D must show (roughly f sqrt(m / m_eff)).
    const JointTuning& t = r.joints[i];
    EXPECT_DOUBLE_EQ(t.model_mass, 4.0);
    StepModel model;
    model.h = r.h;
    model.spring = {t.effective_mass, t.stiffness, t.damping};
    std::complex<double> z1, z2;
    eigenvalues_2x2(step_matrix(Method::implicit_euler, model), z1, z2);
    double f = 0.0, zeta = 0.0;
    ASSERT_TRUE(achieved_from_poles(z1, z2, r.h, f, zeta));
    EXPECT_NEAR(*r.probes[i].measured.frequency_hz / f, 1.0, 0.01) << i;
    EXPECT_NEAR(*r.probes[i].measured.damping_ratio, zeta, 0.01) << i;
    EXPECT_GT(*r.probes[i].frequency_error, 0.3) << i;
  }
}

// A solved k, c handed to a joint as the exact request of implicit Euler's poles on (m, k, c) comes back as that
// k, c: exact_spring inverts the poles of (m + c h + k h^2) z^2 - (2 m + c h) z + m = 0, written out here.
TEST(JointTuning, ImplicitEulerRequestGivesBackItsSpring) {
  WorldSettings world;
  world.fps = 60.0;
  for (const auto& [m, k, c] : {std::tuple{2.0, 500.0, 3.0}, std::tuple{11.35, 24842.07, 914.75}, std::tuple{5.0, 4.0e4, -100.0}}) {
    const TuneRequest q = implicit_euler_request(m, k, c, world);
    ASSERT_FALSE(validate_tune_request(q)) << k;
    const double h = 1.0 / 60.0, d = m + c * h + k * h * h;
    const RecurrencePoles poles = poles_of_recurrence((2.0 * m + c * h) / d, -m / d, h);
    EXPECT_NEAR(*q.frequency_hz, *poles.frequency_hz, 1e-12 * *poles.frequency_hz);
    const TuneResult r = tune(q);
    EXPECT_NEAR(r.spring.stiffness / k, 1.0, 1e-9) << k;
    EXPECT_NEAR(r.spring.damping, c, 1e-9 * std::abs(k * h)) << c;
  }
}

// The Box2D 2.4 model's settings for a scene joint: its def, the world's velocity iterations, and for a mouse
// joint the share of 1/m_eff that is the body's rotation: a 1 kg, 1 m box (I = 1/6 kg m^2) grabbed 0.5 m off
// its centre and pulled across that lever has 1/m_eff = 1 + 0.5^2 / (1/6) = 2.5, of which 1.5 / 2.5 = 0.6 turns it.
TEST(JointTuning, Box2DSettingsNameTheJointAndItsRotationShare) {
  WorldSettings world;
  world.velocity_iterations = 12;
  Body2D box;
  box.mass = 1.0;
  box.inertia = 1.0 / 6.0;
  JointSettings mouse;
  mouse.kind = JointKind::mouse;
  mouse.anchor_b = {0.5, 0.0};
  mouse.target = {0.5, 1.0};
  const Constraint2D pull = joint_constraint(mouse, Body2D{}, box);
  const engines::SettingValues s = box2d_joint_settings(mouse, pull, world);
  ASSERT_EQ(s.size(), 3u);
  EXPECT_EQ(s[0], 2.0);
  EXPECT_EQ(s[1], 12.0);
  EXPECT_NEAR(s[2], 0.6, 1e-12);
  JointSettings wheel;
  wheel.kind = JointKind::wheel;
  EXPECT_EQ(box2d_joint_settings(wheel, joint_constraint(wheel, box, box), world), (engines::SettingValues{1.0, 12.0, 0.0}));
}

}  // namespace
}  // namespace softtune::scene
