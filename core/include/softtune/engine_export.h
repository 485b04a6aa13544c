#pragma once
// The same tuning in the units each engine's API takes. Each engine's convention is cited where it is
// computed (src/engine_export.cpp).

#include <limits>
#include <optional>

#include "softtune/softness.h"
#include "softtune/warnings.h"

namespace softtune {

struct EngineExportInput {
  double effective_mass = 1.0;  ///< kg, the true m_eff
  double omega = 0.0;           ///< rad/s, the asked (or clamped) natural angular frequency
  double damping_ratio = 0.0;   ///< the asked damping ratio
  double h = 1.0 / 60.0;        ///< s, the solver (sub)step
  SpringConstants spring;       ///< k, c actually used (k', c' in exact mode)
  std::optional<double> box2d_reduced_mass;  ///< kg, what b2LinearStiffness would use (constraint given)
};

/// Box2D 2.4 joints take stiffness (N/m) and damping (N s/m) (b2DistanceJointDef::stiffness, ::damping).
struct Box2D24Export {
  double stiffness = 0.0;  ///< N/m, with the true effective mass
  double damping = 0.0;    ///< N s/m
  std::optional<double> linear_stiffness_k;   ///< N/m, what b2LinearStiffness would give
  std::optional<double> linear_stiffness_c;   ///< N s/m
  std::optional<double> linear_stiffness_frequency_error;  ///< relative error of the resulting frequency
};

/// Box2D v3 joints take hertz and a damping ratio (b2DistanceJointDef::hertz, ::dampingRatio). The spring's
/// hertz goes to b2MakeSoft as typed: Box2D v3 clamps only a joint's rigid rows (constraintHertz, to a
/// quarter of the substep rate, joint.c b2PrepareJoint), never a spring (distance_joint.c
/// b2PrepareDistanceJoint). What v3 does with these numbers (substeps, the relax stage) is the
/// box2d_v3 engine model's report (engines/box2d_v3.h).
struct Box2DV3Export {
  std::optional<double> hertz;          ///< Hz; empty when k', c' have no (hertz, ratio) form
  std::optional<double> damping_ratio;
  /// Hz, the highest spring hertz Box2D v3 takes unchanged: none, +infinity (JSON null). Kept for
  /// readers of the field, which once held a 0.25 / h clamp that does not apply to springs.
  double max_hertz = std::numeric_limits<double>::infinity();
  /// max_hertz / hertz: +infinity (JSON null), no clamp to approach.
  double headroom = std::numeric_limits<double>::infinity();
};

/// Jolt SpringSettings: FrequencyAndDamping (mFrequency Hz, mDamping ratio) or StiffnessAndDamping
/// (mStiffness N/m, mDamping N s/m), both using the constraint's own effective mass.
struct JoltExport {
  std::optional<double> frequency_hz;
  std::optional<double> damping_ratio;
  double stiffness = 0.0;  ///< N/m
  double damping = 0.0;    ///< N s/m
};

/// MuJoCo solref: standard (timeconst s, dampratio) or direct (-stiffness, -damping) per unit mass.
struct MujocoExport {
  bool direct = false;
  double solref0 = 0.0;  ///< timeconst (s), or -stiffness (1/s^2) when direct
  double solref1 = 0.0;  ///< dampratio, or -damping (1/s) when direct
};

/// ODE / Bullet ERP and CFM at the step h: ERP = h k / (h k + c), CFM = 1 / (h k + c).
struct OdeExport {
  std::optional<double> erp;
  std::optional<double> cfm;
};

/// PhysX PxD6JointDrive: force drive (stiffness N/m, damping N s/m) or acceleration drive
/// (isAcceleration = true: stiffness omega^2 1/s^2, damping 2 zeta omega 1/s, mass-independent).
struct PhysxExport {
  double stiffness = 0.0, damping = 0.0;
  double acceleration_stiffness = 0.0, acceleration_damping = 0.0;
};

/// Rapier joint motor: MotorModel::ForceBased (stiffness N/m, damping N s/m) and
/// MotorModel::AccelerationBased (stiffness 1/s^2, damping 1/s).
struct RapierExport {
  double force_stiffness = 0.0, force_damping = 0.0;
  double acceleration_stiffness = 0.0, acceleration_damping = 0.0;
};

struct EngineExport {
  Box2D24Export box2d_v2_4;
  Box2DV3Export box2d_v3;
  JoltExport jolt;
  MujocoExport mujoco;
  OdeExport ode_bullet;
  PhysxExport physx;
  RapierExport rapier;
};

/// Every engine's form of the tuning; engine-specific limits go into `warnings`.
EngineExport export_engines(const EngineExportInput& in, Warnings& warnings);

}  // namespace softtune
