#pragma once
// Scenes in Bullet 3.24 (Debian's libbullet-dev, float btScalar) in process: the SceneBackend of
// scene_world.h. A btDiscreteDynamicsWorld with the sequential impulse solver, stepped by
// stepSimulation(h, 0) per substep (one internal step of h, as the 1-D backend engines/bullet/bullet_engine.cpp
// steps). The scene plane is Bullet's x-y plane (y up, no axis change); every body keeps to it by
// setLinearFactor(1, 1, 0) and setAngularFactor(0, 0, 1).
//
// What maps to what (docs/engines/bullet.md, "Scenes in Bullet"):
//   box       btBoxShape, 1 m deep; circle: btCylinderShapeZ, 1 m long (its axis the plane normal);
//             polygon: btConvexHullShape prism, its points about the centre of mass. Collision margin 0.01 m
//             (Box2D's polygon skin, b2_polygonRadius); the box's and cylinder's margin lies inside their
//             extents, the hull's outside its points (so a polygon is 1 cm larger, as Box2D's skin makes it).
//   mass      body_mass() (scene_geometry.h): mass, inertia about the plane normal (the other two axes the
//             same value: the angular factor zeroes them), centre of mass.
//   joints    all btGeneric6DofSpring2Constraint, the plane's rows only (z, x- and y-rotation left free: the
//             factors hold them), each row locked (lower = upper limit) or sprung (enableSpring, setStiffness /
//             setDamping with limitIfNeeded false: k and c act as typed):
//             wheel     across the axis locked, along it the spring, rotation free with the rotational motor
//                       (setTargetVelocity, setMaxMotorForce = max_motor_torque) from motor_start_s;
//             distance  the frames re-aimed along the anchor line before every step (setFrames), the line's
//                       row sprung with equilibrium = the rest length (soft) or locked at it (rigid rod);
//             weld      x, y locked, the rotation sprung (soft) or locked;
//             revolute  x, y locked, rotation free;
//             mouse     x, y sprung to a fixed body at the target; refused when max_force is below Box2D's
//                       unbounded 1e9: Bullet's springs have no force cap.
//   friction  Bullet multiplies the bodies' friction (btManifoldResult::calculateCombinedFriction), so each
//             body gets sqrt(friction): the pair's product is sqrt(fa fb), Box2D's b2MixFriction.
//   restitution  Bullet multiplies them too (calculateCombinedRestitution); Box2D takes the max. Left as
//             Bullet does it (the product): the presets' restitution is 0 everywhere, where both agree.
// Refused: a spring whose explicit step grows at the scene's rate (semi-implicit Euler: omega h above 2, the
// `stiff` preset), and a capped mouse. A joint's spring is typed as
// "btGeneric6DofSpring2Constraint::setStiffness" / "::setDamping" (N/m and N s/m, the weld's N m/rad and
// N m s/rad) on the joint's sprung axis, limitIfNeeded false.

#include "softtune/scene/scene_world.h"

namespace softtune::scene {

extern const SceneBackend kBulletSceneBackend;

}  // namespace softtune::scene
