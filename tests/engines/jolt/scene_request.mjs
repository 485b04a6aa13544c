// The node worker's build request (engines/node_worker/scene_worker.mjs, "op": "build") for a scene document
// (a preset under presets/), made in JavaScript for the Jolt scene module's tests: the C++ backend makes the
// same request from the decoded scene with scene::body_mass() and the tuned springs.
//
// bodyMass is a port of scene::body_mass (scene/src/scene_geometry.cpp): Box2D 2.4.1's mass data of the body's
// one fixture (b2PolygonShape::ComputeMass's triangle fan from the first vertex, b2CircleShape::ComputeMass),
// scaled to the body's `mass` when it gives one. Defaults are scene.h's (BodySettings, JointSettings).
import { readFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';

export const kPresetsDir = join(dirname(fileURLToPath(import.meta.url)), '..', '..', '..', 'presets');

export function readPreset(name) {
  return JSON.parse(readFileSync(join(kPresetsDir, `${name}.json`), 'utf8'));
}

function outline(shape) {
  if (shape.type === 'box') {
    const w = shape.width / 2, h = shape.height / 2;
    return [[-w, -h], [w, -h], [w, h], [-w, h]];
  }
  return shape.vertices;
}

/** {mass, inertia (about the centre of mass), local_centre} as scene::body_mass gives them. */
export function bodyMass(body) {
  if (body.static) return { mass: 0, inertia: 0, local_centre: [0, 0] };
  const density = body.density ?? 1;
  let m;
  if (body.shape.type === 'circle') {
    const r = body.shape.radius;
    const mass = density * Math.PI * r * r;
    m = { mass, inertia: mass * 0.5 * r * r, local_centre: [0, 0] };
  } else {
    const v = outline(body.shape), s = v[0];
    let area = 0, inertia = 0, cx = 0, cy = 0;
    for (let i = 0; i < v.length; ++i) {
      const e1 = [v[i][0] - s[0], v[i][1] - s[1]];
      const n = v[(i + 1) % v.length], e2 = [n[0] - s[0], n[1] - s[1]];
      const d = e1[0] * e2[1] - e1[1] * e2[0];
      area += 0.5 * d;
      cx += 0.5 * d * (e1[0] + e2[0]) / 3;
      cy += 0.5 * d * (e1[1] + e2[1]) / 3;
      const intx2 = e1[0] * e1[0] + e2[0] * e1[0] + e2[0] * e2[0];
      const inty2 = e1[1] * e1[1] + e2[1] * e1[1] + e2[1] * e2[1];
      inertia += (0.25 / 3) * d * (intx2 + inty2);
    }
    const mass = density * area;
    cx /= area; cy /= area;
    const lc = [cx + s[0], cy + s[1]];
    let I = density * inertia + mass * (lc[0] * lc[0] + lc[1] * lc[1] - (cx * cx + cy * cy));
    I -= mass * (lc[0] * lc[0] + lc[1] * lc[1]);
    m = { mass, inertia: I, local_centre: lc };
  }
  if (body.mass !== undefined && m.mass > 0) {
    const scale = body.mass / m.mass;
    m.mass *= scale;
    m.inertia *= scale;
  }
  if (body.fixed_rotation) m.inertia = 0;
  return m;
}

const kOscillation = { free: 0, some: 0.5, none: 1 };  // core/src/designer.cpp damping_ratio()

/** Whether a scene joint carries a spring (a tuning or typed values); a revolute pin never does. */
export function isSoft(joint) {
  if (joint.type === 'revolute') return false;
  return joint.response_frames !== undefined || joint.frequency_hz !== undefined || joint.typed !== undefined;
}

/**
 * A plain spring for a soft joint, enough to run a preset in an engine (not softtune's tuning): typed values
 * as typed, else k = m w^2, c = 2 m zeta w on Box2D's reduced mass of the two bodies (b2LinearStiffness;
 * the weld's rotation on the reduced inertia), w from frequency_hz or basis_fps / response_frames.
 */
export function plainSpring(joint, bodies) {
  if (joint.typed) {
    return { stiffness: joint.typed['b2' + joint.type[0].toUpperCase() + joint.type.slice(1) + 'JointDef::stiffness'],
             damping: joint.typed['b2' + joint.type[0].toUpperCase() + joint.type.slice(1) + 'JointDef::damping'] };
  }
  const f = joint.frequency_hz ?? (joint.basis_fps ?? 60) / joint.response_frames;
  const zeta = joint.damping_ratio ?? kOscillation[joint.oscillation];
  const w = 2 * Math.PI * f;
  const of = (id) => {
    const b = bodies.find((x) => x.id === id);
    if (!b || b.static) return 0;
    const m = bodyMass(b);
    return joint.type === 'weld' ? m.inertia : m.mass;
  };
  const ma = joint.type === 'mouse' ? 0 : of(joint.body_a), mb = of(joint.body_b);
  const m = ma > 0 && mb > 0 ? ma * mb / (ma + mb) : Math.max(ma, mb);
  return { stiffness: m * w * w, damping: 2 * m * zeta * w };
}

/**
 * The build request for scene document `scene`. `spring(joint, index)` gives a soft joint's
 * {stiffness, damping} (default plainSpring); `settings` the engine settings by name.
 */
export function sceneRequest(scene, { spring, settings = {} } = {}) {
  const bodies = scene.bodies || [];
  const index = (id) => bodies.findIndex((b) => b.id === id);
  const world = scene.world || {};
  return {
    op: 'build',
    engine: 'jolt',
    settings,
    world: { gravity: world.gravity ?? [0, -10], fps: world.fps ?? 60, substeps: world.substeps ?? 1 },
    bodies: bodies.map((b) => {
      const m = bodyMass(b);
      return {
        id: b.id, static: !!b.static, shape: b.shape, position: b.position ?? [0, 0], angle: b.angle ?? 0,
        linear_velocity: b.linear_velocity ?? [0, 0], angular_velocity: b.angular_velocity ?? 0,
        friction: b.friction ?? 0.6, restitution: b.restitution ?? 0, fixed_rotation: !!b.fixed_rotation,
        mass: m.mass, inertia: m.inertia, local_centre: m.local_centre,
      };
    }),
    joints: (scene.joints || []).map((j, i) => {
      const anchorA = j.anchor_a ?? [0, 0], anchorB = j.anchor_b ?? [0, 0];
      return {
        id: j.id, type: j.type, body_a: j.type === 'mouse' ? -1 : index(j.body_a), body_b: index(j.body_b),
        anchor_a: anchorA, anchor_b: anchorB, axis: j.axis ?? [0, 1],
        length: j.length ?? Math.hypot(anchorB[0] - anchorA[0], anchorB[1] - anchorA[1]),
        target: j.target ?? [0, 0], max_force: j.max_force ?? 1e9, motor_speed: j.motor_speed ?? 0,
        max_motor_torque: j.max_motor_torque ?? 0, motor_start_s: j.motor_start_s ?? 0,
        collide_connected: !!j.collide_connected,
        spring: isSoft(j) ? (spring ? spring(j, i) : plainSpring(j, bodies)) : null,
      };
    }),
  };
}

/** Frames a scene runs: round(duration_s fps) (scene::frame_count; duration default 5 s). */
export function frameCount(scene) {
  const w = scene.world || {};
  return Math.round((w.duration_s ?? 5) * (w.fps ?? 60));
}
