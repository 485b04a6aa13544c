// One soft constraint in the real Rapier (npm @dimforge/rapier2d-compat / rapier3d-compat 0.21.0), built
// from softtune's answer alone: the `rapier` report's settings and its `parameters` (or `exact`).
//
//   point:          a body of mass m_eff on a prismatic joint along x, rotation locked, its motor driven
//                   to position 0 with UnitImpulseJoint.configureMotorPosition(0, stiffness, damping) under
//                   the report's motor model (configureMotorModel). rapier2d and rapier3d.
//   rotating_plank: a plank of mass 2 m_eff and inertia 2 m_eff 0.5^2, hung by a spring joint
//                   (JointData.spring(rest length, stiffness, damping, anchor1, anchor2)) from a point on the
//                   ground 1 m behind it along x (the plank near the origin), its anchor 0.5 m off its centre perpendicular to x, so the
//                   anchor's effective mass along x is m_eff and the plank turns as it swings (rapier2d).
//                   A spring joint is a coupled linear motor that Rapier builds ForceBased
//                   (spring_joint.rs SpringJoint::new); for AccelerationBased the motor model of its LinX axis
//                   is switched through the joint set's own jointConfigureMotorModel.
//
// Rapier's world step runs numSolverIterations (+ the body's additionalSolverIterations) substeps; the body
// never sleeps (setCanSleep(false)), there is no gravity and no collider (the mass comes from
// setAdditionalMassProperties; CCD, with nothing to act on, is switched off for speed).
import RAPIER2D from '@dimforge/rapier2d-compat';
import RAPIER3D from '@dimforge/rapier3d-compat';

let ready = null;
/** Initialises both WebAssembly modules once. */
export function initRapier() {
  if (!ready) ready = Promise.all([RAPIER2D.init(), RAPIER3D.init()]);
  return ready;
}

export const kRestLength = 1.0;  // m, the plank's spring joint
export const kPlankOffset = 0.5;  // m, engines/include/softtune/engines/engine_run.h rotating_plank()

function value(map, name) {
  const v = map[name];
  if (v === undefined) throw new Error(`rapier: the report has no ${name}`);
  return v;
}

function motorModelOf(R, name) {
  if (name === 'AccelerationBased') return R.MotorModel.AccelerationBased;
  if (name === 'ForceBased') return R.MotorModel.ForceBased;
  throw new Error(`rapier: unknown motor model ${name}`);
}

function configureWorld(R, world, settings, dt) {
  const p = world.integrationParameters;
  p.dt = dt;
  p.numSolverIterations = value(settings, 'IntegrationParameters::num_solver_iterations');
  p.numInternalPgsIterations = value(settings, 'IntegrationParameters::num_internal_pgs_iterations');
  // CCD has nothing to act on (no collider anywhere) but costs half of each step's time under node.
  p.maxCcdSubsteps = 0;
  world.integrationParameters = p;
  world.timestep = dt;
}

/**
 * Runs one case. `run` = {dim: 2|3, body: 'point'|'rotating_plank', effectiveMass, settings (name -> number
 * or choice string, as the report lists them), parameters (name -> number or choice string), dt, steps, x0}.
 * Returns the stretch along the axis after each step, x0 first (steps + 1 samples).
 */
export function runRapier(run) {
  const R = run.dim === 3 ? RAPIER3D : RAPIER2D;
  const m = run.effectiveMass;
  const stiffness = value(run.parameters, 'JointMotor::stiffness');
  const damping = value(run.parameters, 'JointMotor::damping');
  const model = motorModelOf(R, value(run.parameters, 'JointMotor::model'));
  const extra = value(run.settings, 'RigidBodyDesc::additionalSolverIterations');
  const linearDamping = value(run.settings, 'RigidBodyDesc::linearDamping');
  const vec = (x, y) => (run.dim === 3 ? { x, y, z: 0 } : { x, y });

  const world = new R.World(vec(0, 0));
  configureWorld(R, world, run.settings, run.dt);
  const ground = world.createRigidBody(R.RigidBodyDesc.fixed());
  const trajectory = [];
  let read;
  if (run.body === 'point') {
    const desc = R.RigidBodyDesc.dynamic()
      .setTranslation(...Object.values(vec(run.x0, 0)))
      .setCanSleep(false)
      .setLinearDamping(linearDamping)
      .setAngularDamping(linearDamping)
      .setAdditionalSolverIterations(extra)
      .lockRotations();
    if (run.dim === 3) desc.setAdditionalMassProperties(m, { x: 0, y: 0, z: 0 }, { x: 1, y: 1, z: 1 }, { w: 1, x: 0, y: 0, z: 0 });
    else desc.setAdditionalMassProperties(m, { x: 0, y: 0 }, 1);
    const body = world.createRigidBody(desc);
    const data = R.JointData.prismatic(vec(0, 0), vec(0, 0), vec(1, 0));
    const joint = world.createImpulseJoint(data, ground, body, true);
    joint.configureMotorModel(model);
    joint.configureMotorPosition(0, stiffness, damping);
    read = () => body.translation().x;
  } else {
    if (run.dim === 3) throw new Error('rapier: the rotating plank runs in rapier2d');
    const mass = 2 * m, inertia = mass * kPlankOffset * kPlankOffset;
    // The plank's centre sits kPlankOffset above its anchor, the anchor x0 past the rest length from the
    // ground point (-kRestLength, 0): the body stays near the origin, where f32 positions keep resolution.
    const desc = R.RigidBodyDesc.dynamic()
      .setTranslation(run.x0, kPlankOffset)
      .setCanSleep(false)
      .setLinearDamping(linearDamping)
      .setAngularDamping(linearDamping)
      .setAdditionalSolverIterations(extra)
      .setAdditionalMassProperties(mass, { x: 0, y: 0 }, inertia);
    const body = world.createRigidBody(desc);
    const data = R.JointData.spring(kRestLength, stiffness, damping, { x: -kRestLength, y: 0 }, { x: 0, y: -kPlankOffset });
    const joint = world.createImpulseJoint(data, ground, body, true);
    world.impulseJoints.raw.jointConfigureMotorModel(joint.handle, R.JointAxis.LinX, model);
    // The anchor's distance from the ground point, minus the rest length: the spring's own coordinate.
    read = () => {
      const t = body.translation(), a = body.rotation();
      const ax = t.x + Math.sin(a) * kPlankOffset, ay = t.y - Math.cos(a) * kPlankOffset;
      return Math.hypot(ax + kRestLength, ay) - kRestLength;
    };
  }
  trajectory.push(read());
  for (let i = 0; i < run.steps; ++i) {
    world.step();
    trajectory.push(read());
  }
  world.free();
  return trajectory;
}
