// The Jolt scene module (engines/jolt/jolt_scene.mjs) in the real engine (npm jolt-physics 1.1.0): the
// shared acceptance of a scene backend measured straight on the module, as the node worker calls it.
// Run by ctest as `node --test`.
import assert from 'node:assert/strict';
import { readdirSync } from 'node:fs';
import { test } from 'node:test';

import * as jolt from '../../../engines/jolt/jolt_scene.mjs';
import { fitResponse, fromPoles } from '../js/prony.mjs';
import { bodyMass, frameCount, kPresetsDir, readPreset, sceneRequest } from './scene_request.mjs';

const J = await jolt.init();

// Jolt's soft row on one body (core/src/engines/jolt.cpp, SpringPart.h / AxisConstraintPart.h): each step is
// implicit Euler on (m, k, c), v1 = (m v0 - h k x0) / (m + h c + h^2 k), x1 = x0 + h v1 (a constant force
// only moves the equilibrium). Its discrete poles as frequency and damping ratio.
function joltStepModel(m, k, c, h) {
  const D = m + h * c + h * h * k;
  const trace = 1 - (h * h * k) / D + m / D, det = m / D;
  return fromPoles(trace, -det, h);
}

function continuous(m, k, c) {
  const w = Math.sqrt(k / m);
  return { frequencyHz: w / (2 * Math.PI), dampingRatio: c / (2 * Math.sqrt(k * m)) };
}

function box(id, width, height, position, extra = {}) {
  return { id, shape: { type: 'box', width, height }, position, ...extra };
}

// Runs `frames` frames, returning the states after each (frame 0's start first).
function run(request, frames) {
  const world = jolt.build(request);
  try {
    const states = [world.bodies()];
    for (let f = 0; f < frames; ++f) {
      world.step(f);
      states.push(world.bodies());
    }
    return states;
  } finally {
    world.destroy();
  }
}

const kFps = 60;
const kH = 1 / kFps;

test('a box hanging from a static box on a distance spring oscillates as Jolt\'s soft step on k, c, m', () => {
  const m = 2, f = 1.5, zeta = 0.1, w = 2 * Math.PI * f, k = m * w * w, c = 2 * m * zeta * w;
  // The spring hangs from the ceiling's underside to the box's top centre: the line runs through the centre
  // of mass, so the box does not swing. It starts at rest at the rest length; gravity stretches it m g / k.
  const scene = {
    world: { fps: kFps, gravity: [0, -10] },
    bodies: [box('ceiling', 4, 0.5, [0, 3.25], { static: true }), box('weight', 0.5, 0.5, [0, 1.75], { mass: m })],
    joints: [{ id: 'spring', type: 'distance', body_a: 'ceiling', body_b: 'weight', anchor_a: [0, 3], anchor_b: [0, 2],
               frequency_hz: f, damping_ratio: zeta }],
  };
  const request = sceneRequest(scene, { spring: () => ({ stiffness: k, damping: c }) });
  const states = run(request, 300);
  const y = states.map((s) => s[1][3]);
  const fitted = fitResponse(y, kH);
  const model = joltStepModel(m, k, c, kH), exact = continuous(m, k, c);
  console.log(`  distance spring: f ${fitted.frequencyHz.toFixed(4)} Hz (Jolt's step ${model.frequencyHz.toFixed(4)}, ` +
              `continuous ${exact.frequencyHz}), zeta ${fitted.dampingRatio.toFixed(4)} (step ` +
              `${model.dampingRatio.toFixed(4)}, continuous ${exact.dampingRatio})`);
  assert.ok(Math.abs(fitted.frequencyHz / model.frequencyHz - 1) < 2e-3, JSON.stringify(fitted));
  assert.ok(Math.abs(fitted.dampingRatio - model.dampingRatio) < 3e-3, JSON.stringify(fitted));
  // The implicit step's error against the continuous answer at h w = 0.16: frequency within 2 %, and the
  // numerical damping it adds (~ h w / 2) within 0.1 of the asked ratio.
  assert.ok(Math.abs(fitted.frequencyHz / exact.frequencyHz - 1) < 0.02);
  assert.ok(Math.abs(fitted.dampingRatio - exact.dampingRatio) < 0.1);
  // It settles where gravity stretches the spring by m g / k, and never turns.
  assert.ok(Math.abs(y[y.length - 1] - (1.75 - (m * 10) / k)) < 2e-3 * (m * 10) / k + 1e-5);
  assert.ok(states.every((s) => Math.abs(s[1][4]) < 1e-4 && Math.abs(s[1][2]) < 1e-4));
});

test('a wheel joint on a slider: soft along its tilted axis, rigid across it, the wheel body turns freely', () => {
  const m = 3, f = 2, zeta = 0.3, w = 2 * Math.PI * f, k = m * w * w, c = 2 * m * zeta * w;
  const axis = [0.6, 0.8], spin = 4;  // rad/s: the wheel body spins while it slides
  const scene = {
    world: { fps: kFps, gravity: [0, 0] },
    bodies: [box('frame', 1, 1, [0, 0], { static: true }),
             { id: 'wheel', shape: { type: 'circle', radius: 0.3 }, position: [2, 0], mass: m,
               linear_velocity: [0.5 * axis[0], 0.5 * axis[1]], angular_velocity: spin }],
    joints: [{ id: 'suspension', type: 'wheel', body_a: 'frame', body_b: 'wheel', anchor_b: [2, 0], axis,
               frequency_hz: f, damping_ratio: zeta }],
  };
  const states = run(sceneRequest(scene, { spring: () => ({ stiffness: k, damping: c }) }), 240);
  const along = states.map((s) => (s[1][2] - 2) * axis[0] + s[1][3] * axis[1]);
  const across = states.map((s) => Math.abs(-(s[1][2] - 2) * axis[1] + s[1][3] * axis[0]));
  const fitted = fitResponse(along, kH);
  const model = joltStepModel(m, k, c, kH), exact = continuous(m, k, c);
  console.log(`  wheel: f ${fitted.frequencyHz.toFixed(4)} Hz (Jolt's step ${model.frequencyHz.toFixed(4)}, continuous ` +
              `${exact.frequencyHz}), zeta ${fitted.dampingRatio.toFixed(4)} (step ${model.dampingRatio.toFixed(4)}, ` +
              `continuous ${exact.dampingRatio}), max drift across ${Math.max(...across).toExponential(2)} m`);
  assert.ok(Math.abs(fitted.frequencyHz / model.frequencyHz - 1) < 2e-3, JSON.stringify(fitted));
  assert.ok(Math.abs(fitted.dampingRatio - model.dampingRatio) < 3e-3, JSON.stringify(fitted));
  // Implicit Euler at h w = 0.21 runs 3.7 % slow and adds about h w / 2 of damping.
  assert.ok(Math.abs(fitted.frequencyHz / exact.frequencyHz - 1) < 0.05);
  assert.ok(Math.abs(fitted.dampingRatio - exact.dampingRatio) < 0.12);
  assert.ok(Math.max(...across) < 1e-4);
  // Free rotation: nothing brakes the spin (no body damping, no rotation row).
  const last = states[states.length - 1][1];
  assert.ok(Math.abs(last[7] - spin) < 1e-3 * spin, `w ${last[7]}`);
  assert.ok(Math.abs(last[4] - spin * 240 * kH) < 1e-2, `angle ${last[4]} (unwrapped through the turns)`);
});

test('a mouse joint pulls the crate to its target as one soft row on the crate\'s mass', () => {
  const scene = readPreset('mouse');
  const crate = bodyMass(scene.bodies[0]);
  const f = 2, zeta = 0.2, w = 2 * Math.PI * f, k = crate.mass * w * w, c = 2 * crate.mass * zeta * w;
  const states = run(sceneRequest(scene, { spring: () => ({ stiffness: k, damping: c }) }), frameCount(scene));
  const x = states.map((s) => s[0][2]);
  const fitted = fitResponse(x, kH);
  const model = joltStepModel(crate.mass, k, c, kH);
  console.log(`  mouse: f ${fitted.frequencyHz.toFixed(4)} Hz (Jolt's step ${model.frequencyHz.toFixed(4)}), zeta ` +
              `${fitted.dampingRatio.toFixed(4)} (step ${model.dampingRatio.toFixed(4)})`);
  assert.ok(Math.abs(fitted.frequencyHz / model.frequencyHz - 1) < 2e-3);
  assert.ok(Math.abs(fitted.dampingRatio - model.dampingRatio) < 3e-3);
  // The grab point (0.5 m right of the centre) ends on the target (2.5, 0).
  assert.ok(Math.abs(x[x.length - 1] + 0.5 - 2.5) < 1e-3);
});

test('a sprung weld turns about its anchor as one soft rotation row on the inertia; a rigid weld holds', () => {
  // The weld sits 0.5 m left of the plate's centre: the plate turns about the anchor (held rigid), on the
  // inertia about it, I + m d^2 (the rotation row and the point rows solved together).
  const m = 4, d = 0.5, inertia = bodyMass(box('', 1, 0.5, [0, 0], { mass: m })).inertia + m * d * d;
  const f = 1, zeta = 0.05, w = 2 * Math.PI * f, k = inertia * w * w, c = 2 * inertia * zeta * w;
  const scene = {
    world: { fps: kFps, gravity: [0, 0] },
    bodies: [box('post', 0.2, 2, [-2, 0], { static: true }),
             box('plate', 1, 0.5, [0, 0], { mass: m, angular_velocity: 0.3 })],
    joints: [{ id: 'weld', type: 'weld', body_a: 'post', body_b: 'plate', anchor_a: [-d, 0], frequency_hz: f,
               damping_ratio: zeta }],
  };
  const states = run(sceneRequest(scene, { spring: () => ({ stiffness: k, damping: c }) }), 240);
  const fitted = fitResponse(states.map((s) => s[1][4]), kH);
  const model = joltStepModel(inertia, k, c, kH);
  const gap = Math.max(...states.map((s) => Math.hypot(s[1][0] - d * Math.cos(s[1][4]) + d, s[1][1] - d * Math.sin(s[1][4]))));
  console.log(`  weld: f ${fitted.frequencyHz.toFixed(4)} Hz (Jolt's step on I + m d^2 ${model.frequencyHz.toFixed(4)}), zeta ` +
              `${fitted.dampingRatio.toFixed(4)} (step ${model.dampingRatio.toFixed(4)}), anchor gap ${gap.toExponential(1)} m`);
  assert.ok(Math.abs(fitted.frequencyHz / model.frequencyHz - 1) < 2e-3);
  assert.ok(Math.abs(fitted.dampingRatio - model.dampingRatio) < 3e-3);
  assert.ok(gap < 1e-4, 'the weld keeps its translation rigid');

  // Rigid: a plate welded 1 m out from the post under gravity hangs on (rotation and translation both held).
  scene.world.gravity = [0, -10];
  scene.bodies[1].angular_velocity = 0;
  scene.joints[0].anchor_a = [-1.9, 0];
  delete scene.joints[0].frequency_hz;
  const rigid = run(sceneRequest(scene), 120);
  const last = rigid[rigid.length - 1][1];
  console.log(`  rigid weld 1.9 m out under gravity after 2 s: turned ${last[4].toExponential(1)} rad, dropped ${last[3].toExponential(1)} m`);
  assert.ok(Math.abs(last[4]) < 0.02 && Math.abs(last[3]) < 0.02, `rigid weld sagged: ${last}`);
});

// The wheel's off-axis drift: body B's centre against the anchor fixed in body A, across the axis fixed in A.
function wheelDrift(joint, start, now) {
  const a0 = start[joint.body_a], a = now[joint.body_a], b = now[joint.body_b];
  const rot = (v, t) => [Math.cos(t) * v[0] - Math.sin(t) * v[1], Math.sin(t) * v[0] + Math.cos(t) * v[1]];
  const local = rot([joint.anchor_b[0] - a0[0], joint.anchor_b[1] - a0[1]], -a0[4]);
  const anchor = rot(local, a[4]), axis = rot(joint.axis, a[4] - a0[4]);
  const dx = b[2] - (a[0] + anchor[0]), dy = b[3] - (a[1] + anchor[1]);
  return Math.abs(-axis[1] * dx + axis[0] * dy);
}

const kVehicleSpring = { stiffness: 24842.07, damping: 914.753 };  // N/m, N s/m: Box2D 2.4's 3 Hz, zeta 0.5 heave

test('the vehicle settles on its wheels, heaves near 3 Hz, and drives into the boxes after 2 s', () => {
  const scene = readPreset('vehicle');
  const request = sceneRequest(scene, { spring: () => kVehicleSpring });
  const frames = frameCount(scene), fps = scene.world.fps;
  const index = (id) => scene.bodies.findIndex((b) => b.id === id);
  const chassis = index('chassis'), box00 = index('box_0_0');
  const states = run(request, frames);
  assert.ok(states.every((s) => s.every((b) => b.every(Number.isFinite))), 'every state finite');

  const motorFrame = Math.round(2 * fps);
  const y = states.slice(0, motorFrame + 1).map((s) => s[chassis][3]);
  const heave = fitResponse(y, 1 / fps);
  // The tyres start 5 mm up (where Box2D's 1 cm polygon skin leaves them; Jolt's shapes have none) and land
  // within 2 frames; from there on the car is linear: each spring carries half the chassis on tyres that hold,
  // so the heave is Jolt's step on (60 kg, k, c) -- the 3 Hz, 0.5 these k, c are tuned to.
  const landed = states.findIndex((s) => ['rear_wheel', 'front_wheel'].every((w) => s[index(w)][3] <= 0.4 + 1e-4));
  const afterLanding = fitResponse(y.slice(landed), 1 / fps);
  const model = joltStepModel(bodyMass(scene.bodies[chassis]).mass / 2, kVehicleSpring.stiffness,
                              kVehicleSpring.damping, 1 / fps);
  console.log(`  vehicle heave in Jolt over 0-2 s: f ${heave.frequencyHz.toFixed(4)} Hz, zeta ` +
              `${heave.dampingRatio.toFixed(4)}; from the tyres' landing (frame ${landed}): f ` +
              `${afterLanding.frequencyHz.toFixed(4)} Hz, zeta ${afterLanding.dampingRatio.toFixed(4)} (Jolt's step on ` +
              `half the chassis ${model.frequencyHz.toFixed(4)} Hz, ${model.dampingRatio.toFixed(4)}; Box2D 2.4 with ` +
              'the same k, c: 3.0032 Hz, zeta 0.4993 -- softtune simulate --preset vehicle)');
  assert.ok(landed > 0 && landed <= 4, `landed at frame ${landed}`);
  assert.ok(Math.abs(heave.frequencyHz / 3 - 1) < 0.1, JSON.stringify(heave));
  assert.ok(Math.abs(heave.dampingRatio - 0.5) < 0.05, JSON.stringify(heave));
  assert.ok(Math.abs(afterLanding.frequencyHz / model.frequencyHz - 1) < 5e-3, JSON.stringify(afterLanding));
  assert.ok(Math.abs(afterLanding.dampingRatio - model.dampingRatio) < 5e-3, JSON.stringify(afterLanding));
  // Settled by 2 s: on its wheels (tyres on the road), the heave and pitch died out; the free wheels let the
  // car roll a little from its pitch kick (-2 cm/s).
  const settled = states[motorFrame];
  assert.ok(Math.abs(settled[chassis][6]) < 1e-3 && Math.abs(settled[chassis][7]) < 1e-3, `${settled[chassis]}`);
  assert.ok(Math.abs(settled[chassis][5]) < 0.05, `${settled[chassis]}`);
  for (const wheel of ['rear_wheel', 'front_wheel']) assert.ok(Math.abs(settled[index(wheel)][3] - 0.4) < 0.01);
  // Drives right after the motor starts, and pushes into the stack.
  const x = states.map((s) => s[chassis][2]);
  assert.ok(Math.abs(x[motorFrame] - x[0]) < 0.05, 'no drive before the motor');
  assert.ok(x[frames] - x[0] > 5, `chassis x ${x[frames]}`);
  assert.ok(states[frames][box00][2] - 9.0 > 0.5, `the stack's bottom box at x ${states[frames][box00][2]}`);
  const drift = Math.max(...request.joints.map((j) => Math.max(...states.map((s) => wheelDrift(j, states[0], s)))));
  assert.ok(drift < 0.05, `off-axis drift ${drift} m`);
  console.log(`  vehicle: chassis x ${x[frames].toFixed(2)} m at 6 s (Box2D 20.51), wheels' off-axis drift ` +
              `${drift.toExponential(2)} m`);

  // ms per vehicle run (6 s at 60 fps: build, 360 frames, the states read each frame), warm, without and with
  // the contacts read each frame.
  const timed = (withContacts) => {
    const started = performance.now();
    const world = jolt.build(request);
    for (let f = 0; f < frames; ++f) {
      world.step(f);
      world.bodies();
      if (withContacts) world.contacts();
    }
    world.destroy();
    return performance.now() - started;
  };
  timed(false);
  const plain = Math.min(timed(false), timed(false)), contacts = Math.min(timed(true), timed(true));
  console.log(`  vehicle run (6 s at 60 fps) in node: ${plain.toFixed(1)} ms, ${contacts.toFixed(1)} ms reading contacts`);
});

test('every preset builds in Jolt and runs its whole duration finite, inside its world', () => {
  const names = readdirSync(kPresetsDir).filter((f) => f.endsWith('.json')).map((f) => f.slice(0, -5));
  let ran = 0;
  for (const name of names) {
    const scene = readPreset(name);
    if (!scene.world) continue;  // schema.json: the presets' JSON schema, not a scene
    const bounds = scene.world.bounds ?? [-1000, -1000, 1000, 1000];
    const states = run(sceneRequest(scene), frameCount(scene));
    const bad = states.findIndex((s) => !s.every((b) => b.every(Number.isFinite) &&
      b[2] >= bounds[0] && b[2] <= bounds[2] && b[3] >= bounds[1] && b[3] <= bounds[3]));
    assert.equal(bad, -1, `${name}: a body is not finite or left the world at frame ${bad}`);
    ++ran;
  }
  assert.ok(ran >= 9, `${ran} presets ran`);
});

function refusal(request) {
  try {
    jolt.build(request).destroy();
  } catch (e) {
    return e;
  }
  return null;
}

test('what Jolt cannot represent is refused naming the field and jolt', () => {
  const scene = readPreset('heavy_on_light');
  const base = () => sceneRequest(scene);
  const cases = [
    ['joints.0.type', (r) => { r.joints[0].type = 'rope'; }],
    ['bodies.1.shape.type', (r) => { r.bodies[1].shape = { type: 'capsule', radius: 1 }; }],
    ['joints.1.spring.stiffness', (r) => { r.joints[1].spring = { stiffness: 0, damping: 5 }; }],
    ['joints.0.spring.damping', (r) => { r.joints[0].spring = { stiffness: 600, damping: -20 }; }],
    ['joints.0.length', (r) => { r.joints[0].length = 0; }],
    ['settings.PhysicsSettings::mNumVelocitySteps', (r) => { r.settings['PhysicsSettings::mNumVelocitySteps'] = 0; }],
  ];
  for (const [field, edit] of cases) {
    const request = base();
    edit(request);
    const e = refusal(request);
    assert.ok(e, `${field}: built`);
    assert.equal(e.field, field);
    assert.match(e.message, /jolt/);
  }
});

test('the engine settings reach Jolt: one velocity step and no position step let the chain stretch', () => {
  const scene = readPreset('chain');
  const gap = (settings) => {
    const request = sceneRequest(scene, { settings });
    const states = run(request, 120);
    // Each pin's anchor on both bodies, carried from the start: their largest gap over the run.
    const rot = (v, t) => [Math.cos(t) * v[0] - Math.sin(t) * v[1], Math.sin(t) * v[0] + Math.cos(t) * v[1]];
    let worst = 0;
    for (const j of request.joints) {
      const at = (body, s) => {
        const b0 = states[0][body], local = rot([j.anchor_a[0] - b0[0], j.anchor_a[1] - b0[1]], -b0[4]);
        const p = rot(local, s[body][4]);
        return [s[body][0] + p[0], s[body][1] + p[1]];
      };
      for (const s of states) {
        const a = at(j.body_a, s), b = at(j.body_b, s);
        worst = Math.max(worst, Math.hypot(a[0] - b[0], a[1] - b[1]));
      }
    }
    return worst;
  };
  const defaults = gap({});
  const loose = gap({ 'PhysicsSettings::mNumVelocitySteps': 1, 'PhysicsSettings::mNumPositionSteps': 0 });
  console.log(`  chain pins' largest gap: ${defaults.toExponential(2)} m at Jolt's defaults (10, 2), ` +
              `${loose.toExponential(2)} m at (1, 0)`);
  // An iterative solver lets the 100 kg weight stretch the 1 kg links (the preset's note: Box2D 1.6 cm here).
  assert.ok(defaults < 0.05);
  assert.ok(loose > 3 * defaults);
});

test('contacts: a box resting on the ground touches at its two bottom corners, normal along y', () => {
  const scene = {
    world: { fps: kFps, gravity: [0, -10] },
    bodies: [box('ground', 10, 1, [0, -0.5], { static: true }), box('crate', 1, 1, [0.3, 0.5], { mass: 1 })],
    joints: [],
  };
  const world = jolt.build(sceneRequest(scene));
  try {
    assert.deepEqual(world.contacts(), []);  // before the first step: none (and the recording starts)
    for (let f = 0; f < 30; ++f) world.step(f);
    const points = world.contacts().sort((p, q) => p[0] - q[0]);
    assert.equal(points.length, 2, JSON.stringify(points));
    points.forEach((p, i) => {
      assert.ok(Math.abs(p[0] - (0.3 + (i ? 0.5 : -0.5))) < 0.06, JSON.stringify(p));  // within the convex radius
      assert.ok(Math.abs(p[1]) < 0.03 && Math.abs(Math.abs(p[3]) - 1) < 1e-4 && Math.abs(p[2]) < 1e-4, JSON.stringify(p));
    });
  } finally {
    world.destroy();
  }
});

test('a world gives back the wasm heap it took: builds, runs and refusals leave the free memory as it was', () => {
  const request = sceneRequest(readPreset('vehicle'), { spring: () => kVehicleSpring });
  const cycle = () => {
    const world = jolt.build(request);
    for (let f = 0; f < 60; ++f) world.step(f);
    world.contacts();
    world.step(60);
    world.contacts();
    world.destroy();
    for (const at of [0, 3]) {  // refused before any body holds the collision filter, and after three do
      const refused = structuredClone(request);
      refused.bodies[at].shape = { type: 'capsule' };
      assert.ok(refusal(refused));
    }
    jolt.build({ ...request, bodies: [], joints: [] }).destroy();
  };
  cycle();
  const free = () => J.JoltInterface.prototype.sGetFreeMemory();
  const before = free();
  const world = jolt.build(request);
  const held = before - free();
  world.destroy();
  for (let i = 0; i < 10; ++i) cycle();
  const leaked = before - free();
  console.log(`  wasm heap: a vehicle world holds ${(held / 1024).toFixed(0)} KiB; 10 cycles later ${leaked} B not given back`);
  // The allocator's own bookkeeping moves a few bytes (+-8 B seen); a filter left behind per refusal is 2.3 kB.
  assert.ok(held > 1e6 && Math.abs(leaked) < 256, `${leaked} B of ${held} B`);
});

test('worlds past the heap answer an error (no field: not a scene feature) and the module keeps working', () => {
  const request = sceneRequest(readPreset('vehicle'), { spring: () => kVehicleSpring });
  const worlds = [];
  let full = null;
  try {
    for (let i = 0; i < 40 && !full; ++i) {
      try {
        worlds.push(jolt.build(request));
      } catch (e) {
        full = e;
      }
    }
  } finally {
    for (const w of worlds) w.destroy();
  }
  console.log(`  ${worlds.length} vehicle worlds at once, then: ${full && full.message}`);
  assert.ok(full && full.field === undefined && /jolt: the WebAssembly heap/.test(full.message));
  assert.ok(worlds.length >= 6);
  const world = jolt.build(request);
  world.step(0);
  assert.ok(world.bodies().every((b) => b.every(Number.isFinite)));
  world.destroy();
});

test('shapes: a polygon prism\'s centre of mass is the mass data\'s local centre; it and a cylinder rest on the road', () => {
  const wedge = { id: 'wedge', shape: { type: 'polygon', vertices: [[0, 0], [2, 0], [0, 1]] }, position: [0, 0.3], mass: 3 };
  const wheel = { id: 'wheel', shape: { type: 'circle', radius: 0.25 }, position: [3, 0.5], mass: 1 };
  const scene = {
    world: { fps: kFps, gravity: [0, -10] },
    bodies: [box('road', 10, 1, [0, -0.5], { static: true }), wedge, wheel],
    joints: [],
  };
  const centre = bodyMass(wedge).local_centre;  // (2/3, 1/3): the triangle's centroid
  const states = run(sceneRequest(scene), 120);
  const start = states[0][1], last = states[states.length - 1];
  assert.ok(Math.abs(start[2] - start[0] - centre[0]) < 1e-6 && Math.abs(start[3] - start[1] - centre[1]) < 1e-6,
            JSON.stringify(start));
  assert.ok(Math.abs(last[1][1]) < 1e-3 && Math.abs(last[1][4]) < 1e-3, `the wedge rests flat: ${last[1]}`);
  // Jolt's position steps leave up to PhysicsSettings::mPenetrationSlop (0.02 m) of overlap (2.8 mm here).
  assert.ok(Math.abs(last[2][3] - 0.25) < 0.02 && Math.abs(last[2][5]) < 1e-3, `the cylinder rests on its side: ${last[2]}`);
});

test('a fast wheel keeps its spin (Box2D\'s 0.5 pi per step cap, not Jolt\'s 47 rad/s) and its angle counts the turns', () => {
  const spin = 80;  // rad/s: over Jolt's default cap, under Box2D's 0.5 pi / h = 188 rad/s at 60 fps x 2 substeps
  const scene = {
    world: { fps: kFps, substeps: 2, gravity: [0, 0] },
    bodies: [{ id: 'wheel', shape: { type: 'circle', radius: 0.3 }, position: [0, 0], mass: 2, angular_velocity: spin }],
    joints: [],
  };
  const states = run(sceneRequest(scene), 60);
  const last = states[states.length - 1][0];
  assert.ok(Math.abs(last[7] - spin) < 1e-3 * spin, `w ${last[7]}`);
  assert.ok(Math.abs(last[4] - spin * 1.0) < 1e-2 * spin, `angle ${last[4]} after 1 s`);
});

test('contact mixing is Box2D\'s: friction sqrt(fa fb) decelerates a sliding box, restitution max(ra, rb) bounces a ball', () => {
  // Friction 0.4 on a 0.9 road: sqrt(0.36) = 0.6, so the box slides at -0.6 g until it stops.
  const slide = {
    world: { fps: kFps, gravity: [0, -10] },
    bodies: [box('road', 40, 1, [0, -0.5], { static: true, friction: 0.9 }),
             box('crate', 1, 1, [0, 0.5], { mass: 2, friction: 0.4, linear_velocity: [3, 0] })],
    joints: [],
  };
  const vx = run(sceneRequest(slide), 40).map((s) => s[1][5]);
  const decel = (vx[5] - vx[20]) / (15 * kH);
  console.log(`  sliding: ${decel.toFixed(3)} m/s^2 (sqrt(0.4 * 0.9) g = 6)`);
  assert.ok(Math.abs(decel / 6 - 1) < 0.02, `${decel}`);
  assert.ok(Math.abs(vx[39]) < 1e-3, 'stopped by 0.5 s');

  // Restitution 0.5 on a 0 road: the ball leaves at half the speed it lands with.
  const drop = {
    world: { fps: kFps, gravity: [0, -10] },
    bodies: [box('road', 4, 1, [0, -0.5], { static: true }),
             { id: 'ball', shape: { type: 'circle', radius: 0.2 }, position: [0, 1.2], mass: 1, restitution: 0.5 }],
    joints: [],
  };
  const vy = run(sceneRequest(drop), 60).map((s) => s[1][6]);
  const bounce = vy.findIndex((v, i) => i > 0 && v > 0 && vy[i - 1] < 0);
  assert.ok(bounce > 0, 'it bounces');
  const ratio = vy[bounce] / -vy[bounce - 1];
  console.log(`  bounce: leaves at ${ratio.toFixed(3)} of its landing speed (max(0.5, 0) = 0.5)`);
  assert.ok(Math.abs(ratio - 0.5) < 0.05, `${ratio}`);
});

test('collide_connected false: jointed bodies pass through each other; true, or no joint, they collide', () => {
  // Two overlapping boxes pinned at a point off both: the pin holds them, a contact would push them apart.
  const scene = (joint) => ({
    world: { fps: kFps, gravity: [0, 0] },
    bodies: [box('a', 1, 1, [0, 0], { mass: 1 }), box('b', 1, 1, [0.5, 0], { mass: 1 })],
    joints: joint ? [{ id: 'pin', type: 'revolute', body_a: 'a', body_b: 'b', anchor_a: [0.25, 2], ...joint }] : [],
  });
  const apart = (s) => s[1][2] - s[0][2];
  const pinned = run(sceneRequest(scene({ collide_connected: false })), 30);
  assert.ok(Math.abs(apart(pinned[30]) - 0.5) < 1e-4, `pinned, not colliding: ${apart(pinned[30])}`);
  const loose = run(sceneRequest(scene(null)), 30);
  assert.ok(apart(loose[30]) > 0.6, `no joint: pushed apart to ${apart(loose[30])}`);
  const colliding = run(sceneRequest(scene({ collide_connected: true })), 30);
  assert.ok(Math.abs(colliding[30][1][4] - colliding[30][0][4]) > 0.01 || Math.abs(apart(colliding[30]) - 0.5) > 0.01,
            'collide_connected: the contact moves them about the pin');
});

test('a mouse joint\'s pull is capped at max_force along the pull: the crate accelerates at max_force / m', () => {
  const scene = readPreset('mouse');
  const m = bodyMass(scene.bodies[0]).mass, cap = 10;  // N, far under the stiff spring's k * 2 m
  scene.joints[0].max_force = cap;
  const k = 1e4, c = 2 * Math.sqrt(k * m);
  const x = run(sceneRequest(scene, { spring: () => ({ stiffness: k, damping: c }) }), 30).map((s) => s[0][2]);
  // From rest under a constant force, symplectic Euler's x_n = a h^2 n (n + 1) / 2 (the grab point stays far
  // from the target, so the cap holds throughout).
  const a = (2 * (x[30] - x[0])) / (kH * kH * 30 * 31);
  console.log(`  mouse at its cap: ${a.toFixed(4)} m/s^2 (max_force / m = ${cap / m})`);
  assert.ok(Math.abs(a / (cap / m) - 1) < 0.01, `${a}`);
});

test('a distance joint without a spring is a rigid rod: a pendulum of period 2 pi sqrt(L / g)', () => {
  const L = 1, g = 10, theta = 0.1;
  // The rod holds the bob at its centre of mass, so the bob's own turning does not enter: a point pendulum.
  const bob = [L * Math.sin(theta), 2 - L * Math.cos(theta)];
  const scene = {
    world: { fps: kFps, gravity: [0, -g] },
    bodies: [box('pivot', 0.2, 0.2, [0, 2.1], { static: true }), box('bob', 0.1, 0.1, bob, { mass: 1 })],
    joints: [{ id: 'rod', type: 'distance', body_a: 'pivot', body_b: 'bob', anchor_a: [0, 2], anchor_b: bob }],
  };
  const states = run(sceneRequest(scene), 600);
  const fitted = fitResponse(states.map((s) => s[1][2]), kH);
  const period = 2 * Math.PI * Math.sqrt(L / g) * (1 + (theta * theta) / 16);  // with the amplitude's first term
  const stretch = Math.max(...states.map((s) => Math.abs(Math.hypot(s[1][2], s[1][3] - 2) - L)));
  console.log(`  rod pendulum: period ${(1 / fitted.frequencyHz).toFixed(4)} s (2 pi sqrt(L / g) (1 + theta^2 / 16) = ` +
              `${period.toFixed(4)}), zeta ${fitted.dampingRatio.toExponential(1)}, largest stretch ${stretch.toExponential(1)} m`);
  assert.ok(Math.abs(1 / fitted.frequencyHz / period - 1) < 3e-3);
  assert.ok(Math.abs(fitted.dampingRatio) < 2e-3);
  assert.ok(stretch < 1e-3);
});

test('substeps: each frame is world.substeps Jolt steps of 1 / (fps substeps); a world runs the same twice', () => {
  const m = 1.5, f = 3, zeta = 0.05, w = 2 * Math.PI * f, k = m * w * w, c = 2 * m * zeta * w;
  const fps = 30, substeps = 3;
  const scene = {
    world: { fps, substeps, gravity: [0, 0] },
    bodies: [box('wall', 0.2, 2, [-1.1, 0], { static: true }), box('slider', 0.4, 0.4, [0, 0], { mass: m, linear_velocity: [0.2, 0] })],
    joints: [{ id: 'spring', type: 'distance', body_a: 'wall', body_b: 'slider', anchor_a: [-1, 0], anchor_b: [0, 0],
               frequency_hz: f, damping_ratio: zeta }],
  };
  const request = sceneRequest(scene, { spring: () => ({ stiffness: k, damping: c }) });
  const states = run(request, 90);
  const fitted = fitResponse(states.map((s) => s[1][2]), 1 / fps);
  // Sampled once a frame, the poles are the step's cubed: the same s = ln z / h, so the step model at h / 3.
  const model = joltStepModel(m, k, c, 1 / (fps * substeps)), once = joltStepModel(m, k, c, 1 / fps);
  console.log(`  ${substeps} substeps at ${fps} fps: f ${fitted.frequencyHz.toFixed(4)} Hz, zeta ${fitted.dampingRatio.toFixed(4)} ` +
              `(Jolt's step at 1/${fps * substeps} s: ${model.frequencyHz.toFixed(4)}, ${model.dampingRatio.toFixed(4)}; ` +
              `one step a frame would be ${once.frequencyHz.toFixed(4)}, ${once.dampingRatio.toFixed(4)})`);
  assert.ok(Math.abs(fitted.frequencyHz / model.frequencyHz - 1) < 2e-3);
  assert.ok(Math.abs(fitted.dampingRatio - model.dampingRatio) < 3e-3);
  assert.deepEqual(run(request, 90), states, 'the same request runs the same states');
});
