#include "softtune/engine_export.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "softtune/integrators.h"

using namespace softtune;

namespace {
EngineExportInput input(double m, double omega, double zeta, double h) {
  EngineExportInput in;
  in.effective_mass = m;
  in.omega = omega;
  in.damping_ratio = zeta;
  in.h = h;
  in.spring = spring_constants(m, omega, zeta);
  return in;
}
bool has(const Warnings& w, WarningCode code) {
  return std::any_of(w.begin(), w.end(), [code](const Warning& x) { return x.code == code; });
}
}  // namespace

TEST(EngineExport, Box2D24FeedsKAndCAndShowsTheReducedMassError) {
  EngineExportInput in = input(2.0, 30.0, 0.4, 1.0 / 60);
  in.box2d_reduced_mass = 8.0;
  Warnings w;
  const EngineExport e = export_engines(in, w);
  EXPECT_DOUBLE_EQ(e.box2d_v2_4.stiffness, in.spring.stiffness);
  EXPECT_DOUBLE_EQ(e.box2d_v2_4.damping, in.spring.damping);
  EXPECT_DOUBLE_EQ(*e.box2d_v2_4.linear_stiffness_k, 8.0 * 900.0);
  // A spring k = 8 omega^2 on a 2 kg effective mass oscillates at sqrt(8/2) = 2 times the asked omega.
  EXPECT_NEAR(*e.box2d_v2_4.linear_stiffness_frequency_error, 1.0, 1e-15);
  EXPECT_TRUE(has(w, WarningCode::box2d_reduced_mass_error));
}

TEST(EngineExport, Box2D24StiffnessDampingGiveTheSoftConstraint) {
  // Box2D 2.4's distance joint computes gamma = 1/(h (d + h k)), bias = C h k gamma (b2_distance_joint.cpp):
  // that is impulse_gamma and bias_factor of the talk's softness for the exported (k, d).
  const EngineExportInput in = input(1.5, 25.0, 0.7, 1.0 / 120);
  Warnings w;
  const EngineExport e = export_engines(in, w);
  const double h = in.h, k = e.box2d_v2_4.stiffness, d = e.box2d_v2_4.damping;
  const Softness s = softness_from_spring(in.spring.stiffness, in.spring.damping, h);
  EXPECT_NEAR(1.0 / (h * (d + h * k)), impulse_gamma(s.gamma, h), 1e-12);
  EXPECT_NEAR(h * k / (h * (d + h * k)), bias_factor(s.beta, h), 1e-9);
}

TEST(EngineExport, Box2DV3SpringHertzHasNoClamp) {
  // Box2D v3 clamps constraintHertz (a joint's rigid rows) to 0.25 / h in b2PrepareJoint, never the
  // spring's hertz (b2PrepareDistanceJoint hands joint->hertz to b2MakeSoft as typed): no max, no warning.
  Warnings w;
  const EngineExport e = export_engines(input(1.0, 2 * M_PI * 5.0, 0.5, 1.0 / 60), w);
  EXPECT_NEAR(*e.box2d_v3.hertz, 5.0, 1e-12);
  EXPECT_NEAR(*e.box2d_v3.damping_ratio, 0.5, 1e-12);
  EXPECT_TRUE(std::isinf(e.box2d_v3.max_hertz));
  EXPECT_TRUE(std::isinf(e.box2d_v3.headroom));
  EXPECT_FALSE(has(w, WarningCode::box2d_v3_clamped));
  for (double hz : {20.0, 1000.0}) {
    Warnings w2;
    const EngineExport fast = export_engines(input(1.0, 2 * M_PI * hz, 0.5, 1.0 / 60), w2);
    EXPECT_NEAR(*fast.box2d_v3.hertz, hz, 1e-9 * hz);
    EXPECT_TRUE(std::isinf(fast.box2d_v3.max_hertz));
    EXPECT_FALSE(has(w2, WarningCode::box2d_v3_clamped));
  }
}

TEST(EngineExport, JoltFrequencyFormIsTheModalForm) {
  Warnings w;
  const EngineExport e = export_engines(input(3.0, 12.0, 0.25, 1.0 / 60), w);
  EXPECT_NEAR(*e.jolt.frequency_hz, 12.0 / (2 * M_PI), 1e-12);
  EXPECT_NEAR(*e.jolt.damping_ratio, 0.25, 1e-12);
  EXPECT_DOUBLE_EQ(e.jolt.stiffness, 3.0 * 144.0);
}

TEST(EngineExport, MujocoSolrefStandardAndDirect) {
  // Standard: stiffness = m / (tc^2 dr^2), damping = 2 m / tc must give back k and c.
  const EngineExportInput in = input(2.0, 10.0, 0.5, 1.0 / 60);
  Warnings w;
  const EngineExport e = export_engines(in, w);
  ASSERT_FALSE(e.mujoco.direct);
  const double tc = e.mujoco.solref0, dr = e.mujoco.solref1;
  EXPECT_NEAR(2.0 / (tc * tc * dr * dr), in.spring.stiffness, 1e-9);
  EXPECT_NEAR(2.0 * 2.0 / tc, in.spring.damping, 1e-12);
  // timeconst = 1 / (zeta omega) = 0.0125 s < 2h at 60 fps: direct form, with a warning.
  Warnings w2;
  const EngineExport fast = export_engines(input(2.0, 160.0, 0.5, 1.0 / 60), w2);
  ASSERT_TRUE(fast.mujoco.direct);
  EXPECT_NEAR(fast.mujoco.solref0, -160.0 * 160.0, 1e-9);
  EXPECT_NEAR(fast.mujoco.solref1, -160.0, 1e-12);
  EXPECT_TRUE(has(w2, WarningCode::mujoco_direct_solref));
  // Undamped: no timeconst exists; direct form without the clamp warning.
  Warnings w3;
  EXPECT_TRUE(export_engines(input(2.0, 10.0, 0.0, 1.0 / 60), w3).mujoco.direct);
}

TEST(EngineExport, OdeErpCfmAreBetaGamma) {
  const EngineExportInput in = input(1.0, 20.0, 1.0, 0.01);
  Warnings w;
  const EngineExport e = export_engines(in, w);
  const double hk = in.h * in.spring.stiffness;
  EXPECT_NEAR(*e.ode_bullet.erp, hk / (hk + in.spring.damping), 1e-15);
  EXPECT_NEAR(*e.ode_bullet.cfm, 1.0 / (hk + in.spring.damping), 1e-15);
}

TEST(EngineExport, AccelerationDrivesDivideOutTheMass) {
  const EngineExportInput in = input(4.0, 10.0, 0.5, 1.0 / 60);
  Warnings w;
  const EngineExport e = export_engines(in, w);
  EXPECT_DOUBLE_EQ(e.physx.acceleration_stiffness, 100.0);
  EXPECT_DOUBLE_EQ(e.physx.acceleration_damping, 10.0);
  EXPECT_DOUBLE_EQ(e.rapier.acceleration_stiffness, 100.0);
  EXPECT_DOUBLE_EQ(e.rapier.force_stiffness, 400.0);
}
