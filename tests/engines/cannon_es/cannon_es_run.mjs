// One soft joint in the real cannon-es (npm cannon-es 0.20.0), built from softtune's answer alone: the
// `cannon_es` report's settings (joint, linearDamping, spookTimeStep, iterations) and its `parameters` (or
// `exact`).
//
//   joint spring:   a Spring (restLength kRestLength) from a static body's point to the body, its applyForce
//                   on the world's postStep (as cannon-es's Spring doc shows) and once before the first step.
//   joint distance: a DistanceConstraint (distance kRestLength) from the static body's centre to the body's,
//                   its equation's setSpookParams(stiffness, relaxation, spookTimeStep or the world's dt).
//   point:          a sphere of mass m_eff whose centre carries the joint.
//   rotating_plank: (spring) a box of mass 2 m_eff, half extents (sqrt(0.5), 0.5, 0.05), so its inertia about z
//                   is 2 m_eff 0.5^2 (Box.calculateLocalInertia: M (hx^2 + hy^2) / 3), the spring on its
//                   anchor 0.5 off its centre perpendicular to the spring: the anchor's effective mass is m_eff.
//
// No gravity, no contacts (the bodies' collisionFilterMask is 0), no sleeping (World's defaults); the body's
// angularDamping is its linearDamping. Each step is world.step(dt). The stretch is read from the world anchors.
import * as CANNON from 'cannon-es';

export const kRestLength = 1.0;
export const kPlankOffset = 0.5;

function value(map, name) {
  const v = map[name];
  if (v === undefined) throw new Error(`cannon_es: the report has no ${name}`);
  return v;
}

/**
 * Runs one case. `run` = {body: 'point'|'rotating_plank', effectiveMass, settings (the report's settings
 * object), parameters (name -> number), dt (s), steps, x0}. Returns the stretch after each step, x0 first.
 */
export function runCannon(run) {
  const m = run.effectiveMass;
  const joint = value(run.settings, 'joint');
  const damping = value(run.settings, 'linearDamping');
  const world = new CANNON.World({ gravity: new CANNON.Vec3(0, 0, 0) });
  world.solver.iterations = value(run.settings, 'iterations');
  const ground = new CANNON.Body({ mass: 0, collisionFilterMask: 0 });
  const options = { linearDamping: damping, angularDamping: damping, collisionFilterMask: 0 };
  let body, read;
  const anchorA = new CANNON.Vec3(), anchorB = new CANNON.Vec3();
  if (run.body === 'point') {
    body = new CANNON.Body({ ...options, mass: m, shape: new CANNON.Sphere(0.1),
                             position: new CANNON.Vec3(kRestLength + run.x0, 0, 0) });
    read = () => body.position.length() - kRestLength;
  } else {
    if (joint !== 'spring') throw new Error('cannon_es: the plank carries the spring only');
    body = new CANNON.Body({ ...options, mass: 2 * m, shape: new CANNON.Box(new CANNON.Vec3(Math.SQRT1_2, kPlankOffset, 0.05)),
                             position: new CANNON.Vec3(run.x0, kPlankOffset, 0) });
    anchorA.set(-kRestLength, 0, 0);
    anchorB.set(0, -kPlankOffset, 0);
    const world_anchor = new CANNON.Vec3();
    read = () => {
      body.pointToWorldFrame(anchorB, world_anchor);
      return Math.hypot(world_anchor.x + kRestLength, world_anchor.y, world_anchor.z) - kRestLength;
    };
  }
  world.addBody(ground);
  world.addBody(body);
  if (joint === 'spring') {
    const spring = new CANNON.Spring(ground, body, {
      restLength: kRestLength, localAnchorA: anchorA, localAnchorB: anchorB,
      stiffness: value(run.parameters, 'Spring.stiffness'), damping: value(run.parameters, 'Spring.damping'),
    });
    spring.applyForce();
    world.addEventListener('postStep', () => spring.applyForce());
  } else {
    const constraint = new CANNON.DistanceConstraint(ground, body, kRestLength);
    const bake = value(run.settings, 'spookTimeStep') > 0 ? value(run.settings, 'spookTimeStep') : run.dt;
    constraint.distanceEquation.setSpookParams(value(run.parameters, 'setSpookParams.stiffness'),
                                               value(run.parameters, 'setSpookParams.relaxation'), bake);
    world.addConstraint(constraint);
  }
  const trajectory = [read()];
  for (let i = 0; i < run.steps; ++i) {
    world.step(run.dt);
    trajectory.push(read());
  }
  return trajectory;
}
