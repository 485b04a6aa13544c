#pragma once
// Box2D 2.4.1 (Debian's libbox2d-dev) linked in process: the oscillator of one soft joint built from an
// EngineRun alone (the box2d_v2_4 model's `parameters` or `exact` and its `settings`), in the joint the
// `joint` setting names:
//   distance  b2DistanceJoint from the ground's origin, rest length kBox2DV24RestLength, minLength 0 and
//             maxLength 1000 times the rest length (so the spring is soft and its limits never act);
//             the stretch is the joint's length minus the rest length
//   wheel     b2WheelJoint along the x axis from the ground's origin (the spring's rest is zero
//             translation); motor and limit off; the stretch is the translation along the axis
//   mouse     b2MouseJoint pulling the anchor to the origin; maxForce from the parameters (the model exports
//             kBox2DV24MouseMaxForce, 1e15 N: the force cap never acts, h maxForce squared stays finite); the stretch is the anchor's
//             x minus the target's
// The body (RunBody) carries the anchor: a point of mass m_eff (fixedRotation, anchor at its centre), or the
// rotating plank (engine_run.h: mass 2 m_eff, inertia mass 0.25, anchor 0.5 m from its centre along +y,
// perpendicular to the x axis the joint pulls along). Zero gravity, sleeping off, one b2World::Step(dt,
// velocityIterations, 3) per sample. Every b2Vec2 is set explicitly (its default constructor leaves x, y
// unset).
#include "softtune/engines/box2d_v2_4.h"
#include "softtune/engines/engine_run.h"

namespace softtune::engines {

/// The distance joint's rest length (m): short, so float positions near it keep ~3e-8 m.
inline constexpr float kBox2DV24RestLength = 0.25f;

extern const RealEngine kBox2DV24Engine;

}  // namespace softtune::engines
