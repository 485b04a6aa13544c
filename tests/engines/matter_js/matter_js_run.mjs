// One soft Constraint in the real matter.js (npm matter-js 0.20.0), built from softtune's answer alone: the
// `matter_js` report's settings (constraintIterations, frictionAir) and its `parameters` (or `exact`).
//
//   point:          a circle of mass m_eff (Body.setMass), its centre on a Constraint of length kRestLength to
//                   a fixed world point, so nothing turns it.
//   rotating_plank: a plank of mass 2 m_eff and inertia 2 m_eff 0.5^2 (Body.setMass, Body.setInertia), its
//                   anchor pointB 0.5 off its centre perpendicular to the constraint, on a Constraint to a
//                   world point kRestLength behind it: the anchor's effective mass is m_eff and matter's
//                   anchorLeverage (r x n)^2 invI / (invM + invI) is 0.25 (2/m) / (1/(2m) + 2/m) = 0.2.
//
// No gravity (engine.gravity.scale 0), no collisions (the bodies' collisionFilter.mask is 0), sleeping off
// (Engine.create's default). Each step is Engine.update(engine, 1000 dt) in milliseconds. The stretch is read
// from the body's position and angle (constraint.pointB is rotated only at each solve's start).
import Matter from 'matter-js';

const { Bodies, Body, Composite, Constraint, Engine } = Matter;

export const kRestLength = 1.0;
export const kPlankOffset = 0.5;
/** The plank's anchorLeverage (above). */
export const kPlankLeverage = 0.2;

// matter warns once (console.warn) for a delta above 16.667 ms: 30 fps is a case here.
Matter.Common.warnOnce = () => {};

function value(map, name) {
  const v = map[name];
  if (v === undefined) throw new Error(`matter_js: the report has no ${name}`);
  return v;
}

/**
 * Runs one case. `run` = {body: 'point'|'rotating_plank', effectiveMass, settings (the report's settings
 * object), parameters (name -> number), dt (s), steps, x0}. Returns the stretch after each step, x0 first.
 */
export function runMatter(run) {
  const m = run.effectiveMass;
  const stiffness = value(run.parameters, 'Constraint.stiffness');
  const damping = value(run.parameters, 'Constraint.damping');
  const engine = Engine.create({ gravity: { x: 0, y: 0, scale: 0 },
                                 constraintIterations: value(run.settings, 'constraintIterations') });
  const frictionAir = value(run.settings, 'frictionAir');
  const options = { frictionAir, collisionFilter: { mask: 0 } };
  let body, pointB, read;
  if (run.body === 'point') {
    body = Bodies.circle(kRestLength + run.x0, 0, 0.1, options);
    Body.setMass(body, m);
    pointB = { x: 0, y: 0 };
    read = () => Math.hypot(body.position.x, body.position.y) - kRestLength;
  } else {
    body = Bodies.rectangle(run.x0, kPlankOffset, 0.1, 2 * kPlankOffset, options);
    Body.setMass(body, 2 * m);
    Body.setInertia(body, 2 * m * kPlankOffset * kPlankOffset);
    pointB = { x: 0, y: -kPlankOffset };
    read = () => {
      const t = body.position, a = body.angle;
      const ax = t.x + Math.sin(a) * kPlankOffset, ay = t.y - Math.cos(a) * kPlankOffset;
      return Math.hypot(ax + kRestLength, ay) - kRestLength;
    };
  }
  const anchor = run.body === 'point' ? { x: 0, y: 0 } : { x: -kRestLength, y: 0 };
  const constraint = Constraint.create({ pointA: anchor, bodyB: body, pointB, length: kRestLength, stiffness, damping });
  Composite.add(engine.world, [body, constraint]);
  const delta = 1000 * run.dt;
  const trajectory = [read()];
  for (let i = 0; i < run.steps; ++i) {
    Engine.update(engine, delta);
    trajectory.push(read());
  }
  return trajectory;
}
