#include "softtune/engine_export.h"

#include <cmath>
#include <numbers>

#include "softtune/designer.h"

namespace softtune {
namespace {

// Natural frequency and damping ratio of the spring actually used (k', c' in exact mode), for engines
// that take (hertz, ratio). Empty when k <= 0.
struct Modal {
  double omega, zeta;
};
std::optional<Modal> modal_of(double mass, const SpringConstants& s) {
  if (!(s.stiffness > 0.0)) return std::nullopt;
  const double omega = std::sqrt(s.stiffness / mass);
  return Modal{omega, s.damping / (2.0 * mass * omega)};
}

}  // namespace

EngineExport export_engines(const EngineExportInput& in, Warnings& warnings) {
  EngineExport out;
  const double m = in.effective_mass;
  const SpringConstants& s = in.spring;
  const std::optional<Modal> modal = modal_of(m, s);

  // Box2D 2.4.1 b2_distance_joint.cpp InitVelocityConstraints: m_gamma = 1 / (h (d + h k)),
  // m_bias = C h k m_gamma: the standard soft constraint in impulse form, fed stiffness k and damping d.
  out.box2d_v2_4.stiffness = s.stiffness;
  out.box2d_v2_4.damping = s.damping;
  if (in.box2d_reduced_mass && *in.box2d_reduced_mass > 0.0) {
    // b2LinearStiffness (b2_joint.cpp): k = m_red omega^2, c = 2 m_red zeta omega. Fed to a joint whose true
    // effective mass is m, its natural frequency is sqrt(m_red / m) times the asked one.
    const double m_red = *in.box2d_reduced_mass;
    const SpringConstants reduced = spring_constants(m_red, in.omega, in.damping_ratio);
    out.box2d_v2_4.linear_stiffness_k = reduced.stiffness;
    out.box2d_v2_4.linear_stiffness_c = reduced.damping;
    const double error = std::sqrt(m_red / m) - 1.0;
    out.box2d_v2_4.linear_stiffness_frequency_error = error;
    if (std::abs(error) > 0.01) warnings.push_back({WarningCode::box2d_reduced_mass_error, error, 0.0});
  }

  // Box2D v3 springs take (hertz, dampingRatio) into b2MakeSoft(hertz, zeta, h) at the substep h
  // (distance_joint.c b2PrepareDistanceJoint), as typed: joint.c b2PrepareJoint clamps only the joint's
  // rigid rows (min(constraintHertz, 0.25 / h)), so no clamp applies to a spring (max_hertz, headroom
  // stay +infinity). b2MakeSoft divides by 2 zeta + h omega; the box2d_v3 model checks that at the
  // engine's substep.
  if (modal && 2.0 * modal->zeta + in.h * modal->omega > 0.0) {
    const double hertz = frequency_from_angular(modal->omega);
    out.box2d_v3.hertz = hertz;
    out.box2d_v3.damping_ratio = modal->zeta;
  } else if (s.stiffness != 0.0 || s.damping != 0.0) {
    warnings.push_back({WarningCode::engine_note, 0.0, 0.0, "box2d_v3"});
  }

  // Jolt SpringPart::CalculateSpringPropertiesWithFrequencyAndDamping: k = m_eff omega^2, c = 2 m_eff zeta
  // omega, then the standard soft constraint; StiffnessAndDamping takes k, c directly.
  out.jolt.stiffness = s.stiffness;
  out.jolt.damping = s.damping;
  if (modal) {
    out.jolt.frequency_hz = frequency_from_angular(modal->omega);
    out.jolt.damping_ratio = modal->zeta;
  }

  // MuJoCo solref, standard form (timeconst, dampratio): stiffness = m / (timeconst^2 dampratio^2),
  // damping = 2 m / timeconst (mujoco user/user_model.cc, "same as solref computation"), so
  // timeconst = 1 / (zeta omega), dampratio = zeta. MuJoCo raises timeconst to at least 2h; below that, or
  // without positive damping, the direct form (-stiffness, -damping) per unit mass is exported instead.
  const double stiffness_per_mass = s.stiffness / m, damping_per_mass = s.damping / m;
  if (modal && modal->zeta > 0.0 && 1.0 / (modal->zeta * modal->omega) >= 2.0 * in.h) {
    out.mujoco = {false, 1.0 / (modal->zeta * modal->omega), modal->zeta};
  } else {
    out.mujoco = {true, -stiffness_per_mass, -damping_per_mass};
    if (modal && modal->zeta > 0.0) {
      warnings.push_back({WarningCode::mujoco_direct_solref, 1.0 / (modal->zeta * modal->omega), 2.0 * in.h});
    }
  }

  // ODE user guide "Joint error and the error reduction parameter": ERP = h k / (h k + c),
  // CFM = 1 / (h k + c); Bullet's btTypedConstraint uses the same ERP/CFM.
  const Softness soft = softness_from_spring(s.stiffness, s.damping, in.h);
  if (soft.kind == SoftnessKind::soft) out.ode_bullet = {soft.beta, soft.gamma};

  // PhysX PxD6JointDrive(stiffness, damping, forceLimit, isAcceleration); the acceleration form divides
  // out the mass.
  out.physx = {s.stiffness, s.damping, stiffness_per_mass, damping_per_mass};

  // Rapier GenericJoint::set_motor(target_pos, target_vel, stiffness, damping) with MotorModel.
  out.rapier = {s.stiffness, s.damping, stiffness_per_mass, damping_per_mass};
  return out;
}

}  // namespace softtune
