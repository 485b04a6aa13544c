// One soft joint in the real planck.js (npm planck 1.4.2), built from softtune's answer alone: the
// `planck_js` report's settings (joint, velocityIterations) and its `parameters` (or `exact`).
//
//   point:          a fixedRotation body of mass m_eff (setMassData) 1 + x0 from a ground point along x on a
//                   DistanceJoint of length 1, or on a WheelJoint along x through the ground point (its
//                   spring pulling to the anchor, the motor off), or held by a MouseJoint at its centre
//                   whose target is then set to the body's rest point.
//   rotating_plank: a plank of mass 2 m_eff and inertia 2 m_eff 0.5^2, its anchor 0.5 off its centre
//                   perpendicular to x, on a DistanceJoint of length 1 to a ground point behind it: the
//                   anchor's effective mass is m_eff (planck's m_mass), and the plank turns as it swings.
//
// No gravity, no fixtures (so no contacts), sleeping off. Each step is world.step(dt, velocityIterations, 3).
import planck from 'planck';

export const kRestLength = 1.0;
export const kPlankOffset = 0.5;

function value(map, name) {
  const v = map[name];
  if (v === undefined) throw new Error(`planck_js: the report has no ${name}`);
  return v;
}

/**
 * Runs one case. `run` = {body: 'point'|'rotating_plank', effectiveMass, settings (the report's settings),
 * parameters (name -> number), dt (s), steps, x0}. Returns the stretch after each step, x0 first.
 */
export function runPlanck(run) {
  const { Vec2 } = planck;
  const m = run.effectiveMass;
  const joint = value(run.settings, 'joint');
  const iterations = value(run.settings, 'velocityIterations');
  const world = new planck.World({ gravity: Vec2(0, 0), allowSleep: false });
  const ground = world.createBody();
  let read;
  if (run.body === 'point') {
    const body = world.createDynamicBody({ position: Vec2(run.x0, 0), fixedRotation: true, allowSleep: false });
    body.setMassData({ mass: m, center: Vec2(0, 0), I: 0 });
    if (joint === 'distance') {
      world.createJoint(new planck.DistanceJoint({
        frequencyHz: value(run.parameters, 'DistanceJointDef.frequencyHz'),
        dampingRatio: value(run.parameters, 'DistanceJointDef.dampingRatio'), length: kRestLength,
      }, ground, body, Vec2(-kRestLength, 0), Vec2(run.x0, 0)));
    } else if (joint === 'wheel') {
      world.createJoint(new planck.WheelJoint({
        frequencyHz: value(run.parameters, 'WheelJointDef.frequencyHz'),
        dampingRatio: value(run.parameters, 'WheelJointDef.dampingRatio'), enableMotor: false,
        localAnchorA: Vec2(0, 0), localAnchorB: Vec2(0, 0), localAxisA: Vec2(1, 0),
      }, ground, body));
    } else {
      // The joint holds the body point at its target when created (its centre), then pulls it to the rest point.
      const mouse = world.createJoint(new planck.MouseJoint({
        frequencyHz: value(run.parameters, 'MouseJointDef.frequencyHz'),
        dampingRatio: value(run.parameters, 'MouseJointDef.dampingRatio'),
        maxForce: value(run.parameters, 'MouseJointDef.maxForce'),
      }, ground, body, Vec2(run.x0, 0)));
      mouse.setTarget(Vec2(0, 0));
    }
    read = () => body.getPosition().x;
  } else {
    if (joint !== 'distance') throw new Error('planck_js: the rotating plank runs on the distance joint');
    const body = world.createDynamicBody({ position: Vec2(run.x0, kPlankOffset), allowSleep: false });
    body.setMassData({ mass: 2 * m, center: Vec2(0, 0), I: 2 * m * kPlankOffset * kPlankOffset });
    world.createJoint(new planck.DistanceJoint({
      frequencyHz: value(run.parameters, 'DistanceJointDef.frequencyHz'),
      dampingRatio: value(run.parameters, 'DistanceJointDef.dampingRatio'), length: kRestLength,
    }, ground, body, Vec2(-kRestLength, 0), Vec2(run.x0, 0)));
    read = () => {
      const t = body.getPosition(), a = body.getAngle();
      const ax = t.x + Math.sin(a) * kPlankOffset, ay = t.y - Math.cos(a) * kPlankOffset;
      return Math.hypot(ax + kRestLength, ay) - kRestLength;
    };
  }
  const trajectory = [read()];
  for (let i = 0; i < run.steps; ++i) {
    world.step(run.dt, iterations, 3);
    trajectory.push(read());
  }
  return trajectory;
}
