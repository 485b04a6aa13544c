// A scene in the real Rapier 2-D (npm @dimforge/rapier2d-compat 0.21.0, WebAssembly; true 2-D, no plane
// mapping), built from the node worker's build request (engines/node_worker/scene_worker.mjs). What maps to
// what (docs/scene-backends.md):
//   bodies     RigidBodyDesc.fixed() / dynamic(), never sleeping; the mass, the inertia about the centre of
//              mass and the local centre from the request (Box2D 2.4.1's mass data) through
//              setAdditionalMassProperties, the colliders at density 0 (cuboid, ball, convexHull).
//   friction   Rapier mixes with Average, Min, Multiply or Max, not Box2D's sqrt(fa fb): each collider gets
//              sqrt(f) with CoefficientCombineRule.Multiply, so the pair mixes to sqrt(fa) sqrt(fb) =
//              sqrt(fa fb), Box2D's b2MixFriction exactly. restitution: CoefficientCombineRule.Max (b2MixRestitution).
//   distance   spring: JointData.spring(length, stiffness, damping) (a coupled linear motor, ForceBased);
//              rigid rod: JointData.rope with both LinX limits at the length.
//   wheel      Rapier 2-D has no joint that is soft along one axis and free in rotation, so a massive hub:
//              a prismatic joint from body A to the hub along the axis (locked rotation relative to A), its
//              motor ForceBased configureMotorPosition(start, stiffness, damping) as the suspension, and a
//              revolute joint from the hub to body B with the wheel motor (configureMotorVelocity, its max
//              force the max motor torque). Body B's mass is split half to the hub, half to B (B keeps its whole
//              inertia), so the suspension carries B's mass; the hub sits at the joint anchor (the wheel centre
//              in the presets).
//   weld       rigid: JointData.fixed; soft in rotation: a revolute joint whose AngX motor holds the
//              starting relative angle with ForceBased configureMotorPosition(angle, stiffness, damping).
//   mouse      a spring joint of rest length 0 from a fixed body at the target to body B's anchor, its
//              motor force capped at max_force.
//   revolute   JointData.revolute.
// collide_connected false: setContactsEnabled(false) on the joint (and on the hub's joints).
// Step: each frame is world.substeps World.step calls of dt = 1 / (fps substeps).
import RAPIER from '@dimforge/rapier2d-compat';

export const name = 'rapier';
export const version = 'Rapier 0.21.0 (@dimforge/rapier2d-compat)';

export async function init() {
  await RAPIER.init();
}

const R = RAPIER;
const kSettings = {
  'IntegrationParameters::numSolverIterations': (p, v) => { p.numSolverIterations = v; },
  'IntegrationParameters::numInternalPgsIterations': (p, v) => { p.numInternalPgsIterations = v; },
};
// The wheel motor: a velocity motor this stiff is rigid until its force cap (Box2D's motor is a rigid
// velocity row capped at maxMotorTorque); N m s per rad/s.
const kMotorFactor = 1.0e6;
// The hub's inertia, per body B's: the hub turns with body A, so this adds to A's inertia (0.65 % of the
// vehicle chassis's pitch inertia per wheel). A hub much lighter in rotation than the wheel leaves the
// prismatic joint's angular row too weak to carry the motor's reaction (measured: the vehicle reached 15 m
// at 6 s with 1e-2, 17.4 m with 0.5 and 1).
const kHubInertia = 0.5;
// Colliders' interaction groups: 16 membership bits (InteractionGroups, membership << 16 | filter).
const kGroupBits = 16;

function refuse(field, why) {
  throw { field, message: `rapier ${why}` };
}

function rotate(angle, [x, y]) {
  const c = Math.cos(angle), s = Math.sin(angle);
  return [c * x - s * y, s * x + c * y];
}
function localPoint(body, world) {
  if (!body) return { x: world[0], y: world[1] };
  const [x, y] = rotate(-body.angle, [world[0] - body.position[0], world[1] - body.position[1]]);
  return { x, y };
}
function localVector(body, world) {
  const [x, y] = body ? rotate(-body.angle, world) : world;
  return { x, y };
}

function colliderOf(body, i) {
  const s = body.shape;
  let desc = null;
  if (s.type === 'box') desc = R.ColliderDesc.cuboid(s.width / 2, s.height / 2);
  else if (s.type === 'circle') desc = R.ColliderDesc.ball(s.radius);
  else if (s.type === 'polygon') desc = R.ColliderDesc.convexHull(new Float32Array(s.vertices.flat()));
  if (!desc) refuse(`bodies.${i}.shape.type`, `cannot build the shape "${s.type}"`);
  return desc.setDensity(0)
    .setFriction(Math.sqrt(body.friction))
    .setFrictionCombineRule(R.CoefficientCombineRule.Multiply)
    .setRestitution(body.restitution)
    .setRestitutionCombineRule(R.CoefficientCombineRule.Max);
}

function bodyDesc(b) {
  const desc = b.static ? R.RigidBodyDesc.fixed() : R.RigidBodyDesc.dynamic();
  desc.setTranslation(b.position[0], b.position[1]).setRotation(b.angle).setCanSleep(false);
  if (!b.static) {
    desc.setLinvel(b.linear_velocity[0], b.linear_velocity[1]).setAngvel(b.angular_velocity);
    if (b.fixed_rotation) desc.lockRotations();
  }
  return desc;
}

class RapierScene {
  constructor(request) {
    const { world: w, bodies, joints } = request;
    this.fps = w.fps;
    this.substeps = w.substeps;
    this.world = new R.World({ x: w.gravity[0], y: w.gravity[1] });
    const p = this.world.integrationParameters;
    p.dt = 1 / (w.fps * w.substeps);
    for (const [key, value] of Object.entries(request.settings ?? {})) {
      if (!kSettings[key]) refuse('engine_settings', `has no setting ${key}`);
      kSettings[key](p, value);
    }
    this.world.integrationParameters = p;
    this.world.timestep = p.dt;
    this.bodies = [];
    this.colliders = [];
    this.apart = [];  // body index pairs that must not collide and share no joint (a wheel's bodies A and B)
    this.masses = [];  // [mass, inertia, local centre] each body ends up with (the wheel hubs take some)
    bodies.forEach((b, i) => {
      const body = this.world.createRigidBody(bodyDesc(b));
      this.colliders.push(this.world.createCollider(colliderOf(b, i), body));
      this.bodies.push(body);
      this.masses.push({ mass: b.mass, inertia: b.inertia, centre: b.local_centre });
    });
    this.motors = [];  // wheel motors waiting for their start time
    this.joints = joints.map((j, i) => this.joint(j, i, bodies));
    this.keepApart();
    bodies.forEach((b, i) => {
      if (b.static) return;
      const m = this.masses[i];
      this.bodies[i].setAdditionalMassProperties(m.mass, { x: m.centre[0], y: m.centre[1] }, b.fixed_rotation ? 0 : m.inertia, true);
    });
  }

  // A wheel's bodies A and B are joined through the hub, not by one joint whose setContactsEnabled(false)
  // could switch their contacts off. Interaction groups keep them apart at no cost per step: one body of
  // each pair is a member of its own bit only, and its partner's filter drops that bit (Rapier collides a
  // pair when each one's membership meets the other's filter). Beyond 16 such bodies, a contact filter
  // (PhysicsHooks.filterContactPair, a JS call per pair and step: the vehicle ran 6x slower with it).
  keepApart() {
    if (this.apart.length === 0) return;
    const bit = new Map(), filter = new Map();
    for (const [a, b] of this.apart) {
      let member = bit.has(b) || !bit.has(a) ? b : a;
      if (!bit.has(member)) bit.set(member, bit.size);
      const other = member === b ? a : b;
      filter.set(other, (filter.get(other) ?? 0xffff) & ~(1 << bit.get(member)));
    }
    if (bit.size <= kGroupBits) {
      for (const i of new Set([...bit.keys(), ...filter.keys()])) {
        const membership = bit.has(i) ? 1 << bit.get(i) : 0xffff;
        this.colliders[i].setCollisionGroups(((membership << 16) | (filter.get(i) ?? 0xffff)) >>> 0);
      }
      return;
    }
    const apart = new Set(this.apart.map(([a, b]) => {
      const h1 = this.bodies[a].handle, h2 = this.bodies[b].handle;
      return h1 < h2 ? `${h1}:${h2}` : `${h2}:${h1}`;
    }));
    for (const [a, b] of this.apart) {
      this.colliders[a].setActiveHooks(R.ActiveHooks.FILTER_CONTACT_PAIRS);
      this.colliders[b].setActiveHooks(R.ActiveHooks.FILTER_CONTACT_PAIRS);
    }
    this.hooks = {
      filterContactPair: (c1, c2, b1, b2) => (apart.has(b1 < b2 ? `${b1}:${b2}` : `${b2}:${b1}`) ? null : R.SolverFlags.COMPUTE_IMPULSE),
      filterIntersectionPair: () => true,
    };
    // World.step calls the hooks only with an event queue (PhysicsPipeline.step: stepWithEvents); no collider
    // asks for events, so it stays empty.
    this.events = new R.EventQueue(false);
  }

  impulse(data, a, b, collide) {
    const joint = this.world.createImpulseJoint(data, a, b, true);
    joint.setContactsEnabled(collide);
    return joint;
  }

  joint(j, i, bodies) {
    const A = j.body_a >= 0 ? bodies[j.body_a] : null, B = bodies[j.body_b];
    const a = j.body_a >= 0 ? this.bodies[j.body_a] : null, b = this.bodies[j.body_b];
    const la = localPoint(A, j.anchor_a), lb = localPoint(B, j.anchor_b);
    const raw = this.world.impulseJoints.raw;
    switch (j.type) {
      case 'revolute':
        return this.impulse(R.JointData.revolute(la, lb), a, b, j.collide_connected);
      case 'distance': {
        if (j.spring) {
          return this.impulse(R.JointData.spring(j.length, j.spring.stiffness, j.spring.damping, la, lb), a, b, j.collide_connected);
        }
        const rod = this.impulse(R.JointData.rope(j.length, la, lb), a, b, j.collide_connected);
        raw.jointSetLimits(rod.handle, R.JointAxis.LinX, j.length, j.length);
        return rod;
      }
      case 'weld': {
        const relative = B.angle - A.angle;
        if (!j.spring) return this.impulse(R.JointData.fixed(la, 0, lb, -relative), a, b, j.collide_connected);
        const weld = this.impulse(R.JointData.revolute(la, lb), a, b, j.collide_connected);
        weld.configureMotorModel(R.MotorModel.ForceBased);
        weld.configureMotorPosition(relative, j.spring.stiffness, j.spring.damping);
        return weld;
      }
      case 'mouse': {
        if (!j.spring) refuse(`joints.${i}`, 'has no rigid mouse joint (a mouse joint needs a spring)');
        const anchor = this.world.createRigidBody(R.RigidBodyDesc.fixed().setTranslation(j.target[0], j.target[1]));
        const pull = this.impulse(R.JointData.spring(0, j.spring.stiffness, j.spring.damping, { x: 0, y: 0 }, lb), anchor, b, true);
        raw.jointSetMotorMaxForce(pull.handle, R.JointAxis.LinX, j.max_force);
        return pull;
      }
      case 'wheel': {
        if (!j.spring) refuse(`joints.${i}.spring`, 'builds a wheel joint only with a suspension spring');
        const m = this.masses[j.body_b];
        const hubMass = m.mass / 2;
        m.mass -= hubMass;
        const hub = this.world.createRigidBody(R.RigidBodyDesc.dynamic()
          .setTranslation(j.anchor_b[0], j.anchor_b[1]).setRotation(A.angle).setCanSleep(false)
          .setLinvel(B.linear_velocity[0], B.linear_velocity[1])
          .setAdditionalMassProperties(hubMass, { x: 0, y: 0 }, kHubInertia * Math.max(m.inertia, 1.0e-6)));
        const axis = localVector(A, j.axis);
        const start = (j.anchor_b[0] - j.anchor_a[0]) * j.axis[0] + (j.anchor_b[1] - j.anchor_a[1]) * j.axis[1];
        const slider = this.impulse(R.JointData.prismatic(la, { x: 0, y: 0 }, axis), a, hub, j.collide_connected);
        slider.configureMotorModel(R.MotorModel.ForceBased);
        slider.configureMotorPosition(start, j.spring.stiffness, j.spring.damping);
        const axle = this.impulse(R.JointData.revolute({ x: 0, y: 0 }, lb), hub, b, j.collide_connected);
        if (!j.collide_connected) this.apart.push([j.body_a, j.body_b]);
        if (j.max_motor_torque > 0) {
          axle.configureMotorModel(R.MotorModel.ForceBased);
          raw.jointSetMotorMaxForce(axle.handle, R.JointAxis.AngX, j.max_motor_torque);
          this.motors.push({ axle, speed: j.motor_speed, start_s: j.motor_start_s, on: false });
        }
        return slider;
      }
      default:
        return refuse(`joints.${i}.type`, `has no joint type "${j.type}"`);
    }
  }

  step(frame) {
    const t = frame / this.fps;
    for (const m of this.motors) {
      if (!m.on && t >= m.start_s) {
        m.axle.configureMotorVelocity(m.speed, kMotorFactor);
        m.on = true;
      }
    }
    for (let s = 0; s < this.substeps; ++s) this.world.step(this.events, this.hooks);
  }

  bodies_() {
    return this.bodies.map((body) => {
      const t = body.translation(), c = body.worldCom(), v = body.linvel();
      return [t.x, t.y, c.x, c.y, body.rotation(), v.x, v.y, body.angvel()];
    });
  }

  contacts() {
    const out = [];
    const np = this.world.narrowPhase;
    this.world.colliders.forEach((collider) => {
      const h1 = collider.handle;
      np.contactPairsWith(h1, (h2) => {
        if (h2 <= h1) return;  // each pair once
        np.contactPair(h1, h2, this.world.bodies, (manifold, flipped) => {
          const n = manifold.normal();
          const sign = flipped ? -1 : 1;
          for (let k = 0; k < manifold.numSolverContacts(); ++k) {
            const p = manifold.solverContactPoint(k);
            out.push([p.x, p.y, sign * n.x, sign * n.y]);
          }
        });
      });
    });
    return out;
  }

  destroy() {
    this.events?.free();
    this.world.free();
    this.world = null;
  }
}

/** Builds the scene of a build request; throws {field, message} for a feature Rapier cannot represent. */
export function build(request) {
  const scene = new RapierScene(request);
  return {
    step: (frame) => scene.step(frame),
    bodies: () => scene.bodies_(),
    contacts: () => scene.contacts(),
    destroy: () => scene.destroy(),
  };
}
