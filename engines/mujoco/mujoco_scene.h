#pragma once
// The scene backend of MuJoCo 2.2.2 (Debian's libmujoco-dev, linked in process): a scene (scene.h) written as
// MJCF in memory and loaded with mj_loadXML on a VFS, as mujoco_engine.cpp does for one spring. The MJCF is
// what a designer could type: mujoco_scene_mjcf() returns it, to open in MuJoCo's `simulate`. The mapping and
// what it measures: docs/engines/mujoco.md, "Scenes in MuJoCo".
//
// The plane: MuJoCo is z-up, so the scene's x-y plane is MuJoCo's x-z plane (scene y = MuJoCo z) and a scene
// angle (counter-clockwise seen from +z_scene = -y_MuJoCo) is a rotation about MuJoCo's -y: every hinge has
// axis "0 -1 0", so its qpos is the scene's angle.
//
// Bodies and joints. The scene's bodies form MuJoCo's kinematic tree:
//   - a wheel joint nests body_b in body_a with a slide joint along the axis (named after the scene joint, its
//     stiffness / damping the spring's k, c exactly: MuJoCo's passive joint spring, springref 0 at the start)
//     and a hinge "<joint id>/spin" at anchor_b for the free rotation; the motor is a <velocity> actuator
//     "<joint id>/motor" on that hinge (kv = the wheel's inertia / timestep, forcerange = +-max_motor_torque),
//     switched on at motor_start_s (until then the backend zeroes its actuator_gainprm / biasprm, then
//     writes kv back and sets ctrl = motor_speed; in the MJCF as written the servo holds ctrl 0 from the start);
//   - a weld nests body_b in body_a: with a spring, a hinge at the anchor with stiffness / damping (N m/rad,
//     N m s/rad: exact); without, no joint at all (welded: exactly rigid);
//   - a revolute nests body_b in body_a with a hinge at the anchor (exactly rigid); where body_b cannot be
//     nested (it already has a parent, it is static -- the bridge's pin to its right bank --, or nesting would
//     close a loop) it is an <equality><connect> instead, which MuJoCo keeps soft (solref 0.02 1, raised to
//     2 timestep: the loaded bridge's connect ends 1.4 cm apart);
//   - every other dynamic body is a child of the world with slide x, slide z and a hinge (none when
//     fixed_rotation); a static body is a child of the world without joints;
//   - a distance joint with a spring is a spatial tendon "<joint id>" between sites at the anchors with
//     stiffness, damping and springlength (the rest length): passive, exactly k, c along the anchor line;
//     without a spring, the same tendon held by an <equality><tendon> (MuJoCo-soft like the connect);
//   - a mouse joint is a spatial tendon from a world site at `target` to a site at anchor_b with a
//     <general> actuator, biastype affine, biasprm = (0, -k, -c), forcerange +-max_force: the pull is capped
//     like b2MouseJoint's maxForce. Unlike Box2D's mouse (a 2-D spring-damper on the point) the damping acts
//     along the tendon only, not across it.
// Masses and inertias are body_mass() (scene_geometry.h) as <inertial>: the inertia about the plane normal is
// Box2D's, the two other axes get the same value (they never move). Shapes: box -> box 1 m deep; circle ->
// sphere (MuJoCo 2.2.2 collides spheres with boxes and spheres in closed form, a cylinder only through
// libccd's general convex test); polygon -> a convex mesh prism 1 m deep.
// Contacts: MuJoCo takes the larger of two geoms' frictions; where Box2D's sqrt(fa fb) differs, the pair is an
// explicit <contact><pair> with that friction (an explicit pair replaces the dynamic one of the same geoms).
// collide_connected false is a <contact><exclude> of the two bodies (filterparent is disabled, so a nested
// pair with collide_connected true does collide). MuJoCo has no restitution: a non-zero one is refused
// (bodies.N.restitution), as is allow_sleeping (2.2.2 has no sleeping), and so is a spring whose explicit step
// grows on its coordinate's J M^-1 J' at the start (joints.N: MuJoCo would blow up; the stiff preset's 20 Hz). The contacts themselves are MuJoCo's
// soft ones (solref 0.02 1 raised to 2 timestep), without Box2D's contact skin: the vehicle preset's tyres,
// placed where Box2D's skin holds them, start 5 mm above the road and land.
// Step: timestep = 1 / (fps substeps), world.substeps mj_step calls per frame. If MuJoCo still finds a bad qacc
// it resets the state (mj_checkAcc): the backend then reports NaN bodies instead of the reset pose.
//
// Fields a designer types (SceneBackend::fields), on the MJCF element named after the scene joint's id:
//   distance: "tendon/spatial/@stiffness" N/m, "tendon/spatial/@damping" N s/m, "tendon/spatial/@springlength" m
//   wheel:    "joint(slide)/@stiffness" N/m, "joint(slide)/@damping" N s/m
//   weld:     "joint(hinge)/@stiffness" N m/rad, "joint(hinge)/@damping" N m s/rad
//   mouse:    "actuator/general/@biasprm[1]" = -k N/m, "actuator/general/@biasprm[2]" = -c N s/m
// All are linear in k, c: no conversion with the step.

#include <optional>
#include <string>

#include "softtune/scene/scene_world.h"

namespace softtune::engines {

extern const softtune::scene::SceneBackend kMujocoSceneBackend;

/// Index of each scene setting in kMujocoSceneBackend.settings (mjOption's fields, MuJoCo's defaults).
enum MujocoSceneSetting : int {
  kMujocoSceneIntegrator = 0,  ///< Euler, RK4, implicit (mjtIntegrator; implicitfast is MuJoCo 3 only)
  kMujocoSceneIterations,      ///< main solver iterations (100)
  kMujocoSceneSolver,          ///< PGS, CG, Newton (mjtSolver; Newton)
  kMujocoSceneCone,            ///< pyramidal, elliptic (mjtCone; pyramidal)
  kMujocoSceneTolerance,       ///< solver early-termination tolerance (1e-8)
  kMujocoSceneSettingCount,
};

/// The MJCF the backend loads for `build`, or empty with `error` set when the scene is refused.
std::string mujoco_scene_mjcf(const softtune::scene::SceneBuild& build, std::optional<FieldError>& error);

}  // namespace softtune::engines
