// One soft constraint in the real Jolt (npm jolt-physics 1.1.0, WebAssembly, single precision), built from
// softtune's answer alone: the `jolt` report's settings and its `parameters` (or `exact`).
//
//   point:          a body of mass m_eff free to move along x only (EAllowedDOFs_TranslationX), held by a
//                   DistanceConstraint from a fixed point kRestLength behind it (the body near the origin) with mMinDistance =
//                   mMaxDistance = kRestLength and the report's SpringSettings as mLimitsSpringSettings.
//   rotating_plank: a plank of mass 2 m_eff and inertia 2 m_eff 0.5^2 about z, moving in the plane
//                   (EAllowedDOFs_Plane2D), hung by the same DistanceConstraint at a point 0.5 m off its
//                   centre perpendicular to the constraint, so the anchor's effective mass is m_eff and the
//                   plank turns as it swings.
//
// Each case steps JoltInterface::Step(dt, collisionSteps) with the report's PhysicsSettings
// (mNumVelocitySteps, mNumPositionSteps), no gravity, sleeping off, and mLinearDamping = mAngularDamping =
// the report's BodyCreationSettings::mLinearDamping.
import initJolt from 'jolt-physics';

let joltModule = null;
/** Loads the WebAssembly module once. */
export async function initJoltModule() {
  if (!joltModule) joltModule = await initJolt();
  return joltModule;
}

export const kRestLength = 1.0;  // m
export const kPlankOffset = 0.5;  // m, engines/include/softtune/engines/engine_run.h rotating_plank()

function value(map, name) {
  const v = map[name];
  if (v === undefined) throw new Error(`jolt: the report has no ${name}`);
  return v;
}

function springModeOf(J, name) {
  const mode = {
    FrequencyAndDamping: J.ESpringMode_FrequencyAndDamping,
    StiffnessAndDamping: J.ESpringMode_StiffnessAndDamping,
    MassNormalizedStiffnessAndDamping: J.ESpringMode_MassNormalizedStiffnessAndDamping,
  }[name];
  if (mode === undefined) throw new Error(`jolt: unknown spring mode ${name}`);
  return mode;
}

function makeInterface(J) {
  const settings = new J.JoltSettings();
  const objectFilter = new J.ObjectLayerPairFilterTable(2);
  objectFilter.EnableCollision(0, 1);
  objectFilter.EnableCollision(1, 1);
  const bpInterface = new J.BroadPhaseLayerInterfaceTable(2, 2);
  bpInterface.MapObjectToBroadPhaseLayer(0, new J.BroadPhaseLayer(0));
  bpInterface.MapObjectToBroadPhaseLayer(1, new J.BroadPhaseLayer(1));
  settings.mObjectLayerPairFilter = objectFilter;
  settings.mBroadPhaseLayerInterface = bpInterface;
  settings.mObjectVsBroadPhaseLayerFilter = new J.ObjectVsBroadPhaseLayerFilterTable(
    settings.mBroadPhaseLayerInterface, 2, settings.mObjectLayerPairFilter, 2);
  const jolt = new J.JoltInterface(settings);
  J.destroy(settings);
  return jolt;
}

/**
 * Runs one case. `run` = {body: 'point'|'rotating_plank', effectiveMass, settings (name -> number or choice
 * string, as the report lists them), parameters (name -> number or choice string), dt, steps, x0}.
 * Returns the stretch along the constraint after each step, x0 first (steps + 1 samples).
 */
export function runJolt(J, run) {
  const m = run.effectiveMass;
  const jolt = makeInterface(J);
  const system = jolt.GetPhysicsSystem();
  const bodies = system.GetBodyInterface();
  system.SetGravity(new J.Vec3(0, 0, 0));
  const ps = system.GetPhysicsSettings();
  ps.mNumVelocitySteps = value(run.settings, 'PhysicsSettings::mNumVelocitySteps');
  ps.mNumPositionSteps = value(run.settings, 'PhysicsSettings::mNumPositionSteps');
  ps.mAllowSleeping = false;
  system.SetPhysicsSettings(ps);
  const collisionSteps = value(run.settings, 'PhysicsSystem::Update inCollisionSteps');
  const linearDamping = value(run.settings, 'BodyCreationSettings::mLinearDamping');

  const plank = run.body === 'rotating_plank';
  const mass = plank ? 2 * m : m;
  const inertia = plank ? mass * kPlankOffset * kPlankOffset : m;
  // The moving body sits near the origin (float positions keep their resolution as the motion decays); the
  // fixed point is kRestLength behind the body's anchor.
  const centre = plank ? [run.x0, kPlankOffset, 0] : [run.x0, 0, 0];
  const anchor1 = [-kRestLength, 0, 0];
  const anchor2 = [run.x0, 0, 0];

  const shape = new J.SphereShape(0.05, null);
  const cs = new J.BodyCreationSettings(shape, new J.RVec3(...centre), J.Quat.prototype.sIdentity(),
                                        J.EMotionType_Dynamic, 1);
  cs.mOverrideMassProperties = J.EOverrideMassProperties_MassAndInertiaProvided;
  cs.mMassPropertiesOverride.mMass = mass;
  cs.mMassPropertiesOverride.mInertia = J.Mat44.prototype.sScale(inertia);
  cs.mAllowedDOFs = plank ? J.EAllowedDOFs_Plane2D : J.EAllowedDOFs_TranslationX;
  cs.mAllowSleeping = false;
  cs.mLinearDamping = linearDamping;
  cs.mAngularDamping = linearDamping;
  cs.mGravityFactor = 0;
  const body = bodies.CreateBody(cs);
  J.destroy(cs);
  bodies.AddBody(body.GetID(), J.EActivation_Activate);

  const dc = new J.DistanceConstraintSettings();
  dc.mSpace = J.EConstraintSpace_WorldSpace;
  dc.mPoint1 = new J.RVec3(...anchor1);
  dc.mPoint2 = new J.RVec3(...anchor2);
  dc.mMinDistance = kRestLength;
  dc.mMaxDistance = kRestLength;
  const spring = dc.mLimitsSpringSettings;
  const mode = value(run.parameters, 'SpringSettings::mMode');
  spring.mMode = springModeOf(J, mode);
  if (mode === 'FrequencyAndDamping') spring.mFrequency = value(run.parameters, 'SpringSettings::mFrequency');
  else spring.mStiffness = value(run.parameters, 'SpringSettings::mStiffness');
  spring.mDamping = value(run.parameters, 'SpringSettings::mDamping');
  dc.mLimitsSpringSettings = spring;
  const constraint = dc.Create(J.JoltInterface.prototype.sGetFixedToWorldBody(), body);
  J.destroy(dc);
  system.AddConstraint(constraint);

  const read = () => {
    const p = body.GetPosition();
    if (!plank) return p.GetX() - anchor1[0] - kRestLength;
    const q = body.GetRotation();
    const angle = 2 * Math.atan2(q.GetZ(), q.GetW());
    const ax = p.GetX() + Math.sin(angle) * kPlankOffset, ay = p.GetY() - Math.cos(angle) * kPlankOffset;
    return Math.hypot(ax - anchor1[0], ay - anchor1[1]) - kRestLength;
  };
  const trajectory = [read()];
  for (let i = 0; i < run.steps; ++i) {
    jolt.Step(run.dt, collisionSteps);
    trajectory.push(read());
  }
  system.RemoveConstraint(constraint);
  bodies.RemoveBody(body.GetID());
  bodies.DestroyBody(body.GetID());
  J.destroy(jolt);
  return trajectory;
}
