#pragma once
// A joint's designer tuning -> the k, c Box2D 2.4 takes, through the core (softtune::tune) with the mass the
// scene's mass model picks. The effective mass is the core's inverse_effective_mass(Constraint2D) of the
// joint's configuration; the Constraint2D is built to be the same 1-D constraint Box2D 2.4.1 solves:
//   distance: linear along u = (pB - pA)/|pB - pA|, K = 1/mA + iA (rA x u)^2 + 1/mB + iB (rB x u)^2
//             (box2d v2.4.1 src/dynamics/b2_distance_joint.cpp, InitVelocityConstraints)
//   wheel:    linear along the axis ax with lever d + rA = pB - cA for body A and rB for body B:
//             K = mA + mB + iA sAx^2 + iB sBx^2, sAx = (d + rA) x ax, sBx = rB x ax
//             (box2d v2.4.1 src/dynamics/b2_wheel_joint.cpp, "Spring constraint")
//   weld:     angular, K = iA + iB (b2_weld_joint.cpp, the soft angular row when stiffness > 0)
//   mouse:    linear from a fixed target to body B's anchor along the pull direction n: the 2x2 mass matrix of
//             b2_mouse_joint.cpp gives n^T K n = 1/mB + iB (rB x n)^2
// Box2D 2.4 then builds gamma = 1 / (h (c + h k)), bias = C h k gamma with its own, identical K, so a single
// soft joint on a free body is the 1-D oscillator (m_eff, k, c) solved by implicit Euler.

#include <optional>
#include <string>
#include <vector>

#include "softtune/diagnostics.h"
#include "softtune/effective_mass.h"
#include "softtune/engines/engine_model.h"
#include "softtune/scene/scene.h"
#include "softtune/tune.h"

namespace softtune::scene {

/// A joint a modal tuning solved (modal_tuning.h): what it serves, and the engines' answer for its solved k, c.
struct SolvedJoint {
  std::string group;                     ///< the group whose shared k, c it carries
  /// The engines' answer (TuneResult::engine_reports) for the joint alone as Box2D 2.4 runs it with the solved
  /// k, c: the exact request of the poles implicit Euler has with (model mass, k, c) at the step, so each
  /// engine's `parameters` is its form of k, c and its `exact` the values that make its joint do, alone, what
  /// Box2D 2.4's does (a per-joint model: the scene itself runs in Box2D 2.4 only). Empty when that request
  /// is outside the tune contract.
  std::optional<TuneResult> joint_export;
};

struct JointTuning {
  std::string joint;                     ///< joint id
  bool tuned = false;                    ///< false: a rigid joint or a typed one (below), no request applies
  bool typed = false;                    ///< run with the values as typed (JointSettings::typed), not tuned
  bool angular = false;                  ///< weld: k in N m/rad, c in N m s/rad, masses in kg m^2
  MassModel mass_model = MassModel::effective;
  double effective_mass = 0.0;           ///< kg (kg m^2), 1 / K of the joint at the start
  double box2d_reduced_mass = 0.0;       ///< kg (kg m^2), b2LinearStiffness's / b2AngularStiffness's mass
  double model_mass = 0.0;               ///< the one the mass model picked and k, c were computed with
  double requested_frequency_hz = 0.0;   ///< Hz, the designer's request
  double requested_damping_ratio = 0.0;
  double stiffness = 0.0;                ///< k given to Box2D (N/m or N m/rad)
  double damping = 0.0;                  ///< c given to Box2D (N s/m or N m s/rad)
  /// The frequency this k gives on the true effective mass: f sqrt(model_mass / effective_mass), Hz.
  double predicted_frequency_hz = 0.0;
  bool fell_back_to_standard = false;    ///< exact mode had no finite gamma (zeta = 0): standard k, c used
  TuneRequest request;                   ///< the request tune() ran (fps, substeps, mass and engine settings filled in)
  TuneResult result;                     ///< the core's full answer (warnings, stages, softness)
  std::optional<SolvedJoint> solved;     ///< set when a modal tuning solved this joint's k, c
  /// Whether Box2D 2.4 runs this joint as a spring (tuned or typed) rather than a rigid row.
  bool soft() const { return tuned || typed; }
};

/// The Box2D 2.4 model's settings (core/src/engines/box2d_v2_4.cpp) for this joint: its def (distance, wheel,
/// mouse), the world's velocity iterations and, for a mouse joint, the share of 1/m_eff that is body B's
/// rotation, iB (rB x n)^2 m_eff, on which b2MouseJoint's 0.98 angular damping acts.
engines::SettingValues box2d_joint_settings(const JointSettings& joint, const Constraint2D& constraint, const WorldSettings& world);

/// The exact request whose poles are implicit Euler's with (m, k, c) at the step h (fps, substeps from
/// `world`): (m + c h + k h^2) z^2 - (2 m + c h) z + m = 0. exact_spring() maps it back to exactly k, c, so it
/// is how a solved k, c is handed to a joint (modal_tuning.cpp) and how its engines' answer is asked.
TuneRequest implicit_euler_request(double m, double k, double c, const WorldSettings& world);

/// The core constraint Box2D solves for this joint, from the bodies' mass data at the start.
Constraint2D joint_constraint(const JointSettings& joint, const Body2D& body_a, const Body2D& body_b);

/// Tunes one joint: fills fps and substeps from the world and the mass from `model`, validates, runs
/// softtune::tune(). A rigid joint (no tuning) returns `tuned = false`. A failed validation returns the error
/// with its field prefixed by `path` ("joints.3").
std::optional<FieldError> tune_joint(const JointSettings& joint, const Constraint2D& constraint,
                                     const WorldSettings& world, MassModel model, const std::string& path,
                                     JointTuning& out);

/// The body as the core sees it at the start: its mass data (scene_geometry.h, Box2D 2.4.1's) at its pose.
Body2D start_body(const BodySettings& body);

/// Every joint of the scene tuned (tune_joint) on the bodies as they start, indexed like scene.joints: the
/// same k, c whichever engine the scene runs in. The first joint that fails validation is returned.
std::optional<FieldError> tune_scene_joints(const Scene& scene, MassModel model, std::vector<JointTuning>& out);

}  // namespace softtune::scene
