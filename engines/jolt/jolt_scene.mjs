// A scene built and stepped in Jolt Physics (npm jolt-physics 1.1.0, WebAssembly, single precision): the
// engine module the node worker (engines/node_worker/scene_worker.mjs) loads for `"engine": "jolt"`.
//
// Exports (the worker's module contract): name, version, async init(), build(request) -> world, or throws
// {field, message} for a scene feature Jolt cannot represent; world.step(frame), world.bodies() ->
// [[ox, oy, cx, cy, angle, vx, vy, w], ...] (indexed like request.bodies), world.contacts() -> [[px, py, nx,
// ny], ...], world.destroy(). The request is the worker's build message: bodies with mass, inertia (about the
// centre of mass) and local_centre from the scene's engine-neutral mass data, joints with body indices
// (body_a -1: the world), length already resolved, spring {stiffness, damping} in N/m, N s/m (weld: N m/rad,
// N m s/rad) or null for a rigid joint.
//
// The mapping (read in the JoltPhysics repository's Jolt/Physics, a recent snapshot of the v5 line jolt-physics
// 1.1.0 builds: SixDOFConstraint.cpp UpdateFixedFreeAxis / CacheHasSpringLimits / SetupVelocityConstraint,
// Body/MotionProperties.cpp SetMassProperties, ConstraintPart/RotationEulerConstraintPart.h
// CalculateConstraintProperties, Constraints/ContactConstraintManager.h mCombineFriction / mCombineRestitution;
// each behaviour below is also measured by tests/engines/jolt/jolt_scene.test.mjs in the npm build):
//   plane     Jolt is y-up: the scene's x-y plane is Jolt's x-y plane, z out of it, so scene angles
//             (counter-clockwise) are rotations about +z. Every dynamic body has
//             BodyCreationSettings::mAllowedDOFs = EAllowedDOFs::Plane2D (TranslationX | TranslationY when
//             fixed_rotation), mass and inertia given (EOverrideMassProperties::MassAndInertiaProvided, the
//             inertia diag(I, I, I) about the centre of mass: only z matters, the other axes are locked by
//             MotionProperties::SetMassProperties / GetInverseInertiaForRotation).
//   shapes    box -> BoxShape of depth kDepth; circle -> CylinderShape (axis y in Jolt) inside a
//             RotatedTranslatedShape turned 90 degrees about x so its axis is z: every body lies in the same
//             slab, so cylinders meet boxes and each other on their round sides; polygon -> ConvexHullShape of
//             the prism (vertices at z = +-kDepth/2), whose centre of mass is the polygon's centroid as the
//             mass data's local_centre. Convex radius: Jolt's default 0.05 m, less on thin shapes (it must not
//             exceed the half extent; BoxShape rounds inside the box's outline, so the outline is kept).
//   contact   Jolt's own defaults are Box2D's mix: ContactConstraintManager's mCombineFriction is
//             sqrt(f1 f2) (b2MixFriction), mCombineRestitution max(r1, r2) (b2MixRestitution).
//             collide_connected false: a GroupFilterTable with one subgroup per body, the pair disabled.
//   damping   mLinearDamping = mAngularDamping = 0 (Jolt's default is 0.05 /s; the scene's bodies, as Box2D's
//             b2BodyDef, have none). Sleeping off (the scene's allow_sleeping default: a sleeping body would
//             freeze a measurement). mMaxAngularVelocity = Box2D's cap, b2_maxRotation (0.5 pi) per step:
//             94 rad/s at 60 Hz (Jolt's default 0.25 pi 60 = 47 rad/s would clip a fast wheel Box2D runs);
//             mMaxLinearVelocity stays Jolt's 500 m/s (over Box2D's b2_maxTranslation, 2 m per step).
//   step      each frame is world.substeps calls of JoltInterface::Step(h, 1), h = 1 / (fps substeps): one
//             collision step per substep. PhysicsSettings::mNumVelocitySteps / mNumPositionSteps from
//             request.settings under exactly those names (Jolt's defaults 10 and 2 when absent).
//   joints    (each soft row a SpringSettings in ESpringMode::StiffnessAndDamping with the given k, c:
//             AxisConstraintPart::CalculateConstraintPropertiesWithSettingsForLimit / ...ForMotor, soft rows
//             skipped by the position steps)
//     distance  DistanceConstraint, mMinDistance = mMaxDistance = length, mLimitsSpringSettings = (k, c) when
//               sprung (DistanceConstraint::CalculateConstraintProperties: min == max is one unclamped row,
//               Box2D's soft distance joint with minLength 0, maxLength inf); no spring: a rigid rod.
//     wheel     SixDOFConstraint at anchor_b on both bodies (b2WheelJointDef::Initialize), constraint X = the
//               axis, Y = across it in the plane: TranslationX limited to [0, 0] with mLimitsSpringSettings
//               (k, c) (SixDOFConstraint::SetupVelocityConstraint: a fixed axis with spring limits is one soft
//               row at d - 0, Box2D's spring on the translation with no rest offset) or free without a spring
//               (Box2D's wheel with stiffness 0), TranslationY fixed, TranslationZ and every rotation free (the
//               bodies' DOFs keep them in the plane), so body B turns freely. The motor: RotationZ in
//               EMotorState::Velocity, SetTargetAngularVelocityCS(0, 0, motor_speed) (w_B - w_A, as
//               b2WheelJoint), MotorSettings torque limits +-max_motor_torque, switched on the first frame with
//               frame / fps >= motor_start_s.
//     weld      rigid: FixedConstraint at anchor_a (RotationEulerConstraintPart sets the locked axes' columns
//               to identity, so Plane2D bodies are fine). Sprung: SixDOFConstraint with every translation
//               fixed (one PointConstraintPart) and RotationZ a position motor with mSpringSettings (k, c) to
//               the starting relative rotation (Jolt has no soft rotation limits: SixDOFConstraint.h). Jolt's
//               rotation error is 2 sin(theta / 2) ~ theta, so the spring is Box2D's to small angles.
//     mouse     SixDOFConstraint from Body::sFixedToWorld at `target` to body B at anchor_b, X along the pull,
//               TranslationX and Y position motors with mSpringSettings (k, c) towards 0 and force limits
//               +-max_force: each axis is capped on its own, where b2MouseJoint caps the force's length (the
//               same along the pull line).
//     revolute  PointConstraint at anchor_a: with both bodies in the plane the only rotation left is about z,
//               so a point is a pin (a HingeConstraint's two extra rotation rows would act on locked axes).
//   refused   (thrown as {field, message} naming the feature and jolt): an unknown shape or joint type, a
//             spring with stiffness <= 0 (Jolt's SpringSettings::HasStiffness false turns the row rigid: no
//             damper-only row) or damping + h stiffness <= 0 (SpringPart: softness 1 / (h (c + h k)) is
//             infinite or negative), a distance joint of length 0 (DistanceConstraint's row has no direction).
import initJolt from 'jolt-physics';

export const name = 'jolt';
export const version = 'Jolt Physics 5 (npm jolt-physics 1.1.0, WebAssembly)';

const kDepth = 1.0;            // m, the slab every body lies in (mass and inertia are given, so it does not matter)
const kConvexRadius = 0.05;    // m, Jolt's cDefaultConvexRadius
const kSamePoint = 1e-4;       // m, contact points closer than this in the plane are one point
// A world's share of the module's fixed 128 MiB heap: 10.4 MiB measured for the vehicle, and room for larger scenes.
const kWorldHeapBytes = 16 * 2 ** 20;
const kMaxRotation = 0.5 * Math.PI;  // rad per step, Box2D 2.4's b2_maxRotation (b2_common.h)
const kLayerStatic = 0;
const kLayerMoving = 1;
const kVelocitySteps = 'PhysicsSettings::mNumVelocitySteps';
const kPositionSteps = 'PhysicsSettings::mNumPositionSteps';

let J = null;
/** Loads the WebAssembly module once. */
export async function init() {
  if (!J) J = await initJolt();
  return J;
}

// A refusal as the worker passes it on: {field, message} (an Error, for its stack in a test's failure).
function refuse(field, message) {
  throw Object.assign(new Error(message), { field });
}

// One world's Jolt, sized to the scene: with JoltSettings' defaults (10240 bodies, 65536 body pairs, 10240
// contact constraints) a vehicle world took 19.7 MiB of the module's fixed 128 MiB heap, sized 10.4 MiB (the
// rest is JoltInterface's fixed 10 MiB temp allocator), measured; a heap out of memory aborts the whole module
// (every world of the worker). Past these sizes Jolt drops pairs or contacts (EPhysicsUpdateError), it does
// not fail.
function makeInterface(bodyCount) {
  const settings = new J.JoltSettings();
  const pairs = Math.min(65536, Math.max(64, (bodyCount * (bodyCount - 1)) / 2));
  settings.mMaxBodies = bodyCount + 1;
  settings.mMaxBodyPairs = pairs;
  settings.mMaxContactConstraints = Math.min(10240, 2 * pairs);
  const objectFilter = new J.ObjectLayerPairFilterTable(2);
  objectFilter.EnableCollision(kLayerStatic, kLayerMoving);
  objectFilter.EnableCollision(kLayerMoving, kLayerMoving);
  const bpInterface = new J.BroadPhaseLayerInterfaceTable(2, 2);
  const bpStatic = new J.BroadPhaseLayer(kLayerStatic), bpMoving = new J.BroadPhaseLayer(kLayerMoving);
  bpInterface.MapObjectToBroadPhaseLayer(kLayerStatic, bpStatic);
  bpInterface.MapObjectToBroadPhaseLayer(kLayerMoving, bpMoving);
  J.destroy(bpStatic);
  J.destroy(bpMoving);
  settings.mObjectLayerPairFilter = objectFilter;
  settings.mBroadPhaseLayerInterface = bpInterface;
  settings.mObjectVsBroadPhaseLayerFilter = new J.ObjectVsBroadPhaseLayerFilterTable(
    settings.mBroadPhaseLayerInterface, 2, settings.mObjectLayerPairFilter, 2);
  const jolt = new J.JoltInterface(settings);  // owns the filters from here on
  J.destroy(settings);
  return jolt;
}

// Temporaries of the wasm heap made while building, destroyed together.
class Scratch {
  constructor() { this.items = []; }
  keep(o) { this.items.push(o); return o; }
  vec3(x, y, z) { return this.keep(new J.Vec3(x, y, z)); }
  rvec3(x, y, z) { return this.keep(new J.RVec3(x, y, z)); }
  free() { for (const o of this.items) J.destroy(o); this.items = []; }
}

// A rotation of `angle` about a unit axis, as a Quat of the scratch heap (x, y, z, w).
function quatAboutAxis(s, axis, angle) {
  const h = Math.sin(angle / 2);
  return s.keep(new J.Quat(axis[0] * h, axis[1] * h, axis[2] * h, Math.cos(angle / 2)));
}

function finite(v) { return typeof v === 'number' && Number.isFinite(v); }

function number(value, field, fallback) {
  if (value === undefined || value === null) {
    if (fallback !== undefined) return fallback;
    refuse(field, `jolt: ${field} is missing`);
  }
  if (!finite(value)) refuse(field, `jolt: ${field} must be a finite number`);
  return value;
}

function point(value, field, fallback) {
  if (value === undefined || value === null) {
    if (fallback !== undefined) return fallback;
    refuse(field, `jolt: ${field} is missing`);
  }
  if (!Array.isArray(value) || value.length !== 2 || !value.every(finite)) {
    refuse(field, `jolt: ${field} must be [x, y] in metres`);
  }
  return value;
}

// A shape's settings (ref counted: the caller releases it once the body holds the shape).
function shapeSettings(shape, field, s) {
  const type = shape && shape.type;
  let settings;
  if (type === 'box') {
    const hw = number(shape.width, `${field}.width`) / 2, hh = number(shape.height, `${field}.height`) / 2;
    const radius = Math.min(kConvexRadius, 0.5 * Math.min(hw, hh));
    settings = new J.BoxShapeSettings(s.vec3(hw, hh, kDepth / 2), radius);
  } else if (type === 'circle') {
    const r = number(shape.radius, `${field}.radius`);
    const cylinder = new J.CylinderShapeSettings(kDepth / 2, r, Math.min(kConvexRadius, 0.5 * r));
    settings = new J.RotatedTranslatedShapeSettings(s.vec3(0, 0, 0), quatAboutAxis(s, [1, 0, 0], Math.PI / 2), cylinder);
  } else if (type === 'polygon') {
    const vertices = shape.vertices;
    if (!Array.isArray(vertices) || vertices.length < 3) refuse(`${field}.vertices`, 'jolt: a polygon needs 3 or more vertices');
    const hull = new J.ConvexHullShapeSettings();
    let shortest = Infinity;
    vertices.forEach((v, i) => {
      point(v, `${field}.vertices.${i}`);
      const next = vertices[(i + 1) % vertices.length];
      shortest = Math.min(shortest, Math.hypot(next[0] - v[0], next[1] - v[1]));
      for (const z of [-kDepth / 2, kDepth / 2]) hull.mPoints.push_back(s.vec3(v[0], v[1], z));
    });
    hull.mMaxConvexRadius = Math.min(kConvexRadius, 0.25 * shortest);
    settings = hull;
  } else {
    refuse(`${field}.type`, `jolt has no shape type ${JSON.stringify(type)} in this backend (box, circle, polygon)`);
  }
  settings.AddRef();
  return settings;
}

function springSettings(target, k, c) {
  target.mMode = J.ESpringMode_StiffnessAndDamping;
  target.mStiffness = k;
  target.mDamping = c;
}

// The joint's spring, checked against what Jolt's SpringSettings can represent at step h; null when rigid.
function springOf(joint, field, h) {
  const spring = joint.spring;
  if (spring === undefined || spring === null) return null;
  const k = number(spring.stiffness, `${field}.spring.stiffness`);
  const c = number(spring.damping, `${field}.spring.damping`);
  if (!(k > 0)) {
    refuse(`${field}.spring.stiffness`, `jolt has no damper-only row: SpringSettings with mStiffness ${k} <= 0 ` +
           'makes the constraint rigid (SpringSettings::HasStiffness)');
  }
  if (!(c + h * k > 0)) {
    refuse(`${field}.spring.damping`, `jolt's soft row needs damping + h stiffness > 0 (SpringPart: softness ` +
           `1 / (h (c + h k))); here ${c} + ${h} * ${k} <= 0`);
  }
  return { k, c };
}

const kAxis = () => ({
  TX: J.SixDOFConstraintSettings_EAxis_TranslationX, TY: J.SixDOFConstraintSettings_EAxis_TranslationY,
  TZ: J.SixDOFConstraintSettings_EAxis_TranslationZ, RX: J.SixDOFConstraintSettings_EAxis_RotationX,
  RY: J.SixDOFConstraintSettings_EAxis_RotationY, RZ: J.SixDOFConstraintSettings_EAxis_RotationZ,
});

function sixDof(s, position1, position2, axisX) {
  const d = s.keep(new J.SixDOFConstraintSettings());
  d.mSpace = J.EConstraintSpace_WorldSpace;
  d.mPosition1 = s.rvec3(position1[0], position1[1], 0);
  d.mPosition2 = s.rvec3(position2[0], position2[1], 0);
  d.mAxisX1 = d.mAxisX2 = s.vec3(axisX[0], axisX[1], 0);
  d.mAxisY1 = d.mAxisY2 = s.vec3(-axisX[1], axisX[0], 0);
  return d;
}

// A SixDOF axis's motor settings, edited in place and written back.
function editMotor(d, axis, edit) {
  const m = d.get_mMotorSettings(axis);
  edit(m);
  d.set_mMotorSettings(axis, m);
}

class JoltSceneWorld {
  constructor(request) {
    this.jolt = null;
    this.listener = null;
    this.bodyIds = [];
    this.bodyObjects = [];
    this.constraints = [];
    this.motors = [];      // {constraint, speed, start, on}: the wheel motors, switched on once
    this.contactList = [];
    try {
      this.#build(request);
    } catch (e) {
      this.destroy();
      throw e;
    }
  }

  #build(request) {
    const world = request.world || {};
    this.fps = number(world.fps, 'world.fps');
    this.substeps = number(world.substeps, 'world.substeps', 1);
    if (!(this.fps > 0)) refuse('world.fps', 'jolt: world.fps must be > 0');
    if (!(Number.isInteger(this.substeps) && this.substeps >= 1)) refuse('world.substeps', 'jolt: world.substeps must be an integer >= 1');
    this.h = 1 / (this.fps * this.substeps);
    const gravity = point(world.gravity, 'world.gravity', [0, -10]);
    const settings = request.settings || {};
    const velocitySteps = number(settings[kVelocitySteps], `settings.${kVelocitySteps}`, 10);
    const positionSteps = number(settings[kPositionSteps], `settings.${kPositionSteps}`, 2);
    if (!(Number.isInteger(velocitySteps) && velocitySteps >= 1 && velocitySteps <= 255)) {
      refuse(`settings.${kVelocitySteps}`, `jolt: ${kVelocitySteps} must be an integer in [1, 255]`);
    }
    if (!(Number.isInteger(positionSteps) && positionSteps >= 0 && positionSteps <= 255)) {
      refuse(`settings.${kPositionSteps}`, `jolt: ${kPositionSteps} must be an integer in [0, 255]`);
    }
    const bodiesIn = request.bodies || [], jointsIn = request.joints || [];

    const s = new Scratch();
    try {
      // Check what Jolt cannot represent before creating anything.
      const springs = jointsIn.map((j, i) => this.#checkJoint(j, i, bodiesIn.length));

      // JoltInterface's temp allocator alone takes 10 MB: a heap without room for another world answers an
      // error here rather than abort the module (and every other world) on the allocation.
      const free = J.JoltInterface.prototype.sGetFreeMemory();
      if (free < kWorldHeapBytes) {
        throw new Error(`jolt: the WebAssembly heap has ${(free / 2 ** 20).toFixed(1)} MiB free, a world needs ` +
                        `${kWorldHeapBytes / 2 ** 20} MiB: too many worlds at once`);
      }
      this.jolt = makeInterface(bodiesIn.length);
      const system = this.jolt.GetPhysicsSystem();
      this.bodyInterface = system.GetBodyInterface();
      system.SetGravity(s.vec3(gravity[0], gravity[1], 0));
      const ps = system.GetPhysicsSettings();
      ps.mNumVelocitySteps = velocitySteps;
      ps.mNumPositionSteps = positionSteps;
      ps.mAllowSleeping = false;
      system.SetPhysicsSettings(ps);

      // collide_connected false: the pair's subgroups never collide (GroupFilterTable::CanCollide).
      // Ref counted: the bodies' CollisionGroups hold it, and the last one destroyed frees it.
      const filter = new J.GroupFilterTable(Math.max(1, bodiesIn.length));
      filter.AddRef();
      try {
        for (const j of jointsIn) {
          if (!j.collide_connected && j.body_a >= 0 && j.body_a !== j.body_b) filter.DisableCollision(j.body_a, j.body_b);
        }
        bodiesIn.forEach((b, i) => this.#createBody(b, i, filter, s));
      } finally {
        filter.Release();
      }
      this.angles = bodiesIn.map((b) => b.angle ?? 0);
      jointsIn.forEach((j, i) => this.#createJoint(j, i, springs[i], s));
      this.state = bodiesIn.map(() => new Array(8).fill(0));
      this.#read();
    } finally {
      s.free();
    }
  }

  #checkJoint(j, i, bodyCount) {
    const field = `joints.${i}`;
    const types = ['distance', 'wheel', 'weld', 'mouse', 'revolute'];
    if (!types.includes(j.type)) refuse(`${field}.type`, `jolt has no joint type ${JSON.stringify(j.type)} in this backend (${types.join(', ')})`);
    const inRange = (v) => Number.isInteger(v) && v >= 0 && v < bodyCount;
    if (!inRange(j.body_b)) refuse(`${field}.body_b`, `jolt: ${field}.body_b must be a body index`);
    if (j.type !== 'mouse' && !inRange(j.body_a)) refuse(`${field}.body_a`, `jolt: ${field}.body_a must be a body index`);
    const spring = springOf(j, field, this.h);
    if (j.type === 'distance' && !(number(j.length, `${field}.length`) > 0)) {
      refuse(`${field}.length`, 'jolt has no distance constraint of length 0: DistanceConstraint\'s row has no direction');
    }
    if (j.type === 'mouse' && !spring) refuse(`${field}.spring`, 'jolt: a mouse joint needs a spring (its pull)');
    if (j.type === 'revolute' && spring) refuse(`${field}.spring`, 'jolt: a revolute pin has no spring in this backend');
    return spring;
  }

  #createBody(b, i, filter, s) {
    const field = `bodies.${i}`;
    const position = point(b.position, `${field}.position`, [0, 0]);
    const angle = number(b.angle, `${field}.angle`, 0);
    const isStatic = !!b.static;
    const settings = shapeSettings(b.shape, `${field}.shape`, s);
    try {
      const result = settings.Create();
      if (!result.IsValid()) refuse(`${field}.shape`, `jolt cannot build this shape: ${result.GetError().c_str()}`);
      const q = quatAboutAxis(s, [0, 0, 1], angle);
      const cs = s.keep(new J.BodyCreationSettings(result.Get(), s.rvec3(position[0], position[1], 0), q,
                                                   isStatic ? J.EMotionType_Static : J.EMotionType_Dynamic,
                                                   isStatic ? kLayerStatic : kLayerMoving));
      cs.mFriction = number(b.friction, `${field}.friction`, 0.6);
      cs.mRestitution = number(b.restitution, `${field}.restitution`, 0);
      const group = s.keep(new J.CollisionGroup(filter, 0, i));
      cs.mCollisionGroup = group;
      if (!isStatic) {
        const mass = number(b.mass, `${field}.mass`);
        if (!(mass > 0)) refuse(`${field}.mass`, 'jolt: a dynamic body needs a mass > 0');
        const inertia = number(b.inertia, `${field}.inertia`, 0);
        const rotates = !b.fixed_rotation && inertia > 0;
        cs.mOverrideMassProperties = J.EOverrideMassProperties_MassAndInertiaProvided;
        cs.mMassPropertiesOverride.mMass = mass;
        // Only the inertia about z acts; the locked axes get the same positive value.
        // (Mat44::sScale returns the binding's static temporary: copied by the setter, never destroyed.)
        cs.mMassPropertiesOverride.mInertia = J.Mat44.prototype.sScale(rotates ? inertia : mass);
        cs.mAllowedDOFs = rotates ? J.EAllowedDOFs_Plane2D : (J.EAllowedDOFs_TranslationX | J.EAllowedDOFs_TranslationY);
        const v = point(b.linear_velocity, `${field}.linear_velocity`, [0, 0]);
        cs.mLinearVelocity = s.vec3(v[0], v[1], 0);
        cs.mAngularVelocity = s.vec3(0, 0, rotates ? number(b.angular_velocity, `${field}.angular_velocity`, 0) : 0);
        cs.mLinearDamping = 0;
        cs.mAngularDamping = 0;
        cs.mAllowSleeping = false;
        cs.mMaxAngularVelocity = kMaxRotation / this.h;
      }
      const body = this.bodyInterface.CreateBody(cs);
      const id = body.GetID();
      this.bodyInterface.AddBody(id, isStatic ? J.EActivation_DontActivate : J.EActivation_Activate);
      this.bodyObjects.push(body);
      this.bodyIds.push(id);
    } finally {
      settings.Release();
    }
  }

  #createJoint(j, i, spring, s) {
    const A = kAxis();
    const body1 = j.type === 'mouse' || j.body_a < 0 ? J.JoltInterface.prototype.sGetFixedToWorldBody() : this.bodyObjects[j.body_a];
    const body2 = this.bodyObjects[j.body_b];
    const field = `joints.${i}`;
    let settings;
    if (j.type === 'distance') {
      const a = point(j.anchor_a, `${field}.anchor_a`), b = point(j.anchor_b, `${field}.anchor_b`);
      const d = settings = s.keep(new J.DistanceConstraintSettings());
      d.mSpace = J.EConstraintSpace_WorldSpace;
      d.mPoint1 = s.rvec3(a[0], a[1], 0);
      d.mPoint2 = s.rvec3(b[0], b[1], 0);
      d.mMinDistance = d.mMaxDistance = j.length;
      if (spring) {
        const limits = d.mLimitsSpringSettings;
        springSettings(limits, spring.k, spring.c);
        d.mLimitsSpringSettings = limits;
      }
    } else if (j.type === 'wheel') {
      const anchor = point(j.anchor_b, `${field}.anchor_b`);
      const axis = point(j.axis, `${field}.axis`, [0, 1]);
      const n = Math.hypot(axis[0], axis[1]);
      if (!(n > 0)) refuse(`${field}.axis`, 'jolt: a wheel axis must not be zero');
      const d = settings = sixDof(s, anchor, anchor, [axis[0] / n, axis[1] / n]);
      if (spring) {
        d.SetLimitedAxis(A.TX, 0, 0);
        const limits = d.get_mLimitsSpringSettings(A.TX);
        springSettings(limits, spring.k, spring.c);
        d.set_mLimitsSpringSettings(A.TX, limits);
      } else {
        d.MakeFreeAxis(A.TX);
      }
      d.MakeFixedAxis(A.TY);
      for (const axisId of [A.TZ, A.RX, A.RY, A.RZ]) d.MakeFreeAxis(axisId);
      const torque = number(j.max_motor_torque, `${field}.max_motor_torque`, 0);
      if (torque > 0) {
        editMotor(d, A.RZ, (m) => { m.mMinTorqueLimit = -torque; m.mMaxTorqueLimit = torque; });
      }
    } else if (j.type === 'weld') {
      const anchor = point(j.anchor_a, `${field}.anchor_a`);
      if (!spring) {
        const d = settings = s.keep(new J.FixedConstraintSettings());
        d.mSpace = J.EConstraintSpace_WorldSpace;
        d.mAutoDetectPoint = false;
        d.mPoint1 = d.mPoint2 = s.rvec3(anchor[0], anchor[1], 0);
      } else {
        const d = settings = sixDof(s, anchor, anchor, [1, 0]);
        for (const axisId of [A.TX, A.TY, A.TZ]) d.MakeFixedAxis(axisId);
        for (const axisId of [A.RX, A.RY, A.RZ]) d.MakeFreeAxis(axisId);
        editMotor(d, A.RZ, (m) => springSettings(m.mSpringSettings, spring.k, spring.c));
      }
    } else if (j.type === 'mouse') {
      const anchor = point(j.anchor_b, `${field}.anchor_b`), target = point(j.target, `${field}.target`);
      const dx = target[0] - anchor[0], dy = target[1] - anchor[1], len = Math.hypot(dx, dy);
      const pull = len > 0 ? [dx / len, dy / len] : [1, 0];
      const d = settings = sixDof(s, target, anchor, pull);
      for (const axisId of [A.TX, A.TY, A.TZ, A.RX, A.RY, A.RZ]) d.MakeFreeAxis(axisId);
      const cap = number(j.max_force, `${field}.max_force`, 1e9);
      for (const axisId of [A.TX, A.TY]) {
        editMotor(d, axisId, (m) => {
          springSettings(m.mSpringSettings, spring.k, spring.c);
          m.mMinForceLimit = -cap;
          m.mMaxForceLimit = cap;
        });
      }
    } else {  // revolute
      const anchor = point(j.anchor_a, `${field}.anchor_a`);
      const d = settings = s.keep(new J.PointConstraintSettings());
      d.mSpace = J.EConstraintSpace_WorldSpace;
      d.mPoint1 = d.mPoint2 = s.rvec3(anchor[0], anchor[1], 0);
    }
    const constraint = settings.Create(body1, body2);
    this.jolt.GetPhysicsSystem().AddConstraint(constraint);
    this.constraints.push(constraint);
    if (j.type === 'mouse' || (j.type === 'weld' && spring)) {
      const six = J.castObject(constraint, J.SixDOFConstraint);
      const zero = s.vec3(0, 0, 0);
      if (j.type === 'mouse') {
        six.SetTargetPositionCS(zero);
        six.SetMotorState(A.TX, J.EMotorState_Position);
        six.SetMotorState(A.TY, J.EMotorState_Position);
      } else {
        const identity = s.keep(new J.Quat(0, 0, 0, 1));
        six.SetTargetOrientationCS(identity);
        six.SetMotorState(A.RZ, J.EMotorState_Position);
      }
    }
    if (j.type === 'wheel' && number(j.max_motor_torque, `${field}.max_motor_torque`, 0) > 0) {
      this.motors.push({ constraint: J.castObject(constraint, J.SixDOFConstraint),
                         speed: number(j.motor_speed, `${field}.motor_speed`, 0),
                         start: number(j.motor_start_s, `${field}.motor_start_s`, 0), on: false });
    }
  }

  // A ContactListenerJS costs a wasm -> JS call per manifold per step (the vehicle's 6 s: 218 ms against 94 ms
  // without one, measured), so it is attached by the first contacts() call, for the worlds whose contacts are
  // read (the previews).
  #listenToContacts() {
    const system = this.jolt.GetPhysicsSystem();
    const listener = this.listener = new J.ContactListenerJS();
    const record = (body1, body2, manifoldPtr) => {
      if (!this.recording) return;
      const m = J.wrapPointer(manifoldPtr, J.ContactManifold);
      const n = m.mWorldSpaceNormal;
      const nx = n.GetX(), ny = n.GetY();
      // A face manifold of two prisms holds each plane point twice (the slab's front and back): kept once.
      const count = m.mRelativeContactPointsOn1.size(), first = this.contactList.length;
      for (let k = 0; k < count; ++k) {
        const p = m.GetWorldSpaceContactPointOn1(k), px = p.GetX(), py = p.GetY();
        let seen = false;
        for (let e = first; e < this.contactList.length && !seen; ++e) {
          const q = this.contactList[e];
          seen = Math.abs(q[0] - px) <= kSamePoint && Math.abs(q[1] - py) <= kSamePoint;
        }
        if (!seen) this.contactList.push([px, py, nx, ny]);
      }
    };
    listener.OnContactValidate = () => J.ValidateResult_AcceptAllContactsForThisBodyPair;
    listener.OnContactAdded = record;
    listener.OnContactPersisted = record;
    listener.OnContactRemoved = () => {};
    system.SetContactListener(listener);
  }

  // Each body's angle, unwrapped from the last step's (Jolt's rotation is a quaternion; Box2D's angle keeps
  // counting turns): |w| <= mMaxAngularVelocity turns a body at most 0.5 pi per step.
  #unwrap(i) {
    const q = this.bodyObjects[i].GetRotation();
    const angle = 2 * Math.atan2(q.GetZ(), q.GetW());
    const last = this.angles[i];
    this.angles[i] = angle + 2 * Math.PI * Math.round((last - angle) / (2 * Math.PI));
    return this.angles[i];
  }

  // Reads every body into this.state.
  #read() {
    for (let i = 0; i < this.bodyObjects.length; ++i) {
      const body = this.bodyObjects[i];
      const o = body.GetPosition(), ox = o.GetX(), oy = o.GetY();
      const c = body.GetCenterOfMassPosition(), cx = c.GetX(), cy = c.GetY();
      const angle = this.#unwrap(i);
      const v = body.GetLinearVelocity(), vx = v.GetX(), vy = v.GetY();
      const w = body.GetAngularVelocity().GetZ();
      const st = this.state[i];
      st[0] = ox; st[1] = oy; st[2] = cx; st[3] = cy; st[4] = angle; st[5] = vx; st[6] = vy; st[7] = w;
    }
  }

  /** One frame: the motors due by frame / fps switch on, then world.substeps steps of h. */
  step(frame) {
    const t = frame / this.fps;
    for (const m of this.motors) {
      if (!m.on && t >= m.start) {
        const target = new J.Vec3(0, 0, m.speed);
        m.constraint.SetTargetAngularVelocityCS(target);
        J.destroy(target);
        m.constraint.SetMotorState(J.SixDOFConstraintSettings_EAxis_RotationZ, J.EMotorState_Velocity);
        m.on = true;
      }
    }
    for (let k = 0; k < this.substeps; ++k) {
      // The contacts of the frame's last step are the ones touching now.
      this.recording = k === this.substeps - 1;
      if (this.recording) this.contactList = [];
      this.jolt.Step(this.h, 1);
      if (k < this.substeps - 1) for (let i = 0; i < this.bodyObjects.length; ++i) this.#unwrap(i);
    }
    this.recording = false;
    this.#read();
  }

  /** [[ox, oy, cx, cy, angle, vx, vy, w], ...] after the last frame. */
  bodies() { return this.state.map((s) => s.slice()); }

  /** [[px, py, nx, ny], ...]: every point of every touching contact after the last frame, the normal from
   *  Jolt's body 1 to body 2 (ContactManifold::mWorldSpaceNormal). The first call starts the recording
   *  (#listenToContacts) and answers [] (the steps before it were not recorded; before the first step there
   *  are no contacts, as in Box2D); each later call answers the contacts of the frame's last step. */
  contacts() {
    if (!this.listener) {
      this.#listenToContacts();
      return [];
    }
    return this.contactList.map((c) => c.slice());
  }

  /** Frees everything this world made in the wasm heap. */
  destroy() {
    if (this.jolt) {
      const system = this.jolt.GetPhysicsSystem();
      for (const c of this.constraints) system.RemoveConstraint(c);
      for (const id of this.bodyIds) {
        this.bodyInterface.RemoveBody(id);
        this.bodyInterface.DestroyBody(id);
      }
      J.destroy(this.jolt);
    }
    if (this.listener) J.destroy(this.listener);
    this.jolt = null;
    this.listener = null;
    this.constraints = [];
    this.bodyIds = [];
    this.bodyObjects = [];
    this.motors = [];
  }
}

/** Builds the request's scene in Jolt; throws {field, message} for what Jolt cannot represent. */
export function build(request) {
  if (!J) throw new Error('jolt: init() first');
  return new JoltSceneWorld(request);
}
