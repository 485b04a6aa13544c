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
