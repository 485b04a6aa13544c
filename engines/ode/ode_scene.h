#pragma once
// Scenes in ODE 0.16 (Debian's libode-dev 0.16.2, double precision) in process: the SceneBackend of
// scene_world.h. One dWorld, a dSimpleSpace, each substep dSpaceCollide's contacts as dContact joints then
// dWorldStep (or dWorldQuickStep, the "stepper" setting, as the 1-D model core/engines/ode.h names it) of
// h = 1 / (fps substeps). The scene plane is ODE's x-y plane (no axis change); every dynamic body has a
// dJointCreatePlane2D, and after each step its rotation and angular velocity are projected back onto the
// z axis, as ODE's own ode/demo/demo_plane2d.cpp does (the joint holds velocities, not the drift).
//
// What maps to what (docs/engines/ode.md, "Scenes in ODE"):
//   box       dCreateBox, 1 m deep. circle: dCreateSphere of the radius -- ODE 0.16's dCylinder collides with
//             a box and a plane, but with another cylinder only through libccd, so a sphere (whose section in
//             the plane is the circle) is what collides with every shape. polygon: refused -- a dCreateConvex prism
//             meets a box at one contact point at a time (a dropped triangle rocks and creeps at 1 cm/s).
//   mass      body_mass() (scene_geometry.h) through dMassSetParameters, the centre of mass at the body's
//             origin and the geom offset from it (dGeomSetOffsetPosition); fixed_rotation: the Plane2D
//             joint's angle motor at velocity 0 with dInfinity force.
//   joints    revolute: dJointCreateHinge about z. weld: dJointCreateFixed (rigid) or a hinge whose lo = hi
//             = 0 stops carry the spring (dParamStopERP, dParamStopCFM). wheel: dJointCreateHinge2 (ODE's car
//             wheel), axis 1 the wheel's axis carrying the suspension (dParamSuspensionERP / CFM; rigid: the
//             world's ERP, CFM), axis 2 the spin about z with the motor dParamVel2 / dParamFMax2 from
//             motor_start_s. Joints to a static body attach to a kinematic stand-in at its pose. distance:
//             dJointCreateDBall at the rest length, dParamERP / dParamCFM (soft) or the world's (rigid).
//             mouse: dJointCreateBall to the world at the target, dParamERP / dParamCFM; refused when
//             max_force is below Box2D's unbounded 1e9 (ODE's ball rows have no force cap).
//   contacts  one per (x, y) of a prism's face contact (its twins at +-depth/2 would be redundant rows),
//             dContactApprox1 (mu a coefficient of the normal force), mu = sqrt(fa fb) (b2MixFriction),
//             bounce = max(ra, rb) (b2MixRestitution), dContactBounce only where it is above 0; jointed
//             bodies do not collide unless collide_connected.
// A spring's fields are ERP and CFM of the joint's row (dParamSuspensionERP / CFM, dParamStopERP / CFM for
// the weld's hinge, dParamERP / CFM for the dball and ball), from k, c and the step h = 1 / (fps substeps):
// ERP = h k / (h k + c), CFM = 1 / (h k + c) (implicit Euler on k, c: core/src/engines/ode.cpp), so they
// depend on the scene's rate and are typed per joint.

#include "softtune/scene/scene_world.h"

namespace softtune::scene {

extern const SceneBackend kOdeSceneBackend;

}  // namespace softtune::scene
