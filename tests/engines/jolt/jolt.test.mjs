// Jolt conformance (npm jolt-physics 1.1.0): softtune's `jolt` report run in the real engine.
// Run by ctest as `node --test` with SOFTTUNE_BIN set to the softtune binary.
import assert from 'node:assert/strict';
import { test } from 'node:test';

import { conform, fit, grid, identify, refusedGrid, tune } from '../js/conformance.mjs';
import { initJoltModule, runJolt } from './jolt_run.mjs';

const J = await initJoltModule();

// Report settings (name -> number or choice) as the runner reads them, under the engine's own names.
function runnerSettings(report) {
  const s = report.settings;
  return {
    'PhysicsSettings::mNumVelocitySteps': s.numVelocitySteps,
    'PhysicsSettings::mNumPositionSteps': s.numPositionSteps,
    'PhysicsSystem::Update inCollisionSteps': s.collisionSteps,
    'BodyCreationSettings::mLinearDamping': s.linearDamping,
  };
}

function run(c, report, parameters, dt, steps) {
  return runJolt(J, {
    body: c.body,
    effectiveMass: c.request.effective_mass,
    settings: runnerSettings(report),
    parameters,
    dt,
    steps,
    // Large against float's resolution, small enough that the plank's turn stays linear (0.04 rad).
    x0: c.body === 'rotating_plank' ? 0.02 : 0.05,
  });
}

// Engine settings cycle through the defaults and the changes a user makes: collision steps, the three
// spring modes, velocity/position steps, no or more linear damping.
const modes = ['FrequencyAndDamping', 'StiffnessAndDamping', 'MassNormalizedStiffnessAndDamping'];
const cases = grid(72, (i) => {
  const settings = { springMode: modes[i % 3] };
  if (i % 4 === 1) settings.collisionSteps = 2;
  if (i % 8 === 3) settings.collisionSteps = 3;
  if (i % 5 === 2) settings.linearDamping = 0;
  if (i % 7 === 4) settings.linearDamping = 0.5;
  if (i % 9 === 5) { settings.numVelocitySteps = 2; settings.numPositionSteps = 0; }
  const body = i % 3 === 1 ? 'rotating_plank' : 'point';
  return { body, label: `${body} ${JSON.stringify(settings)}`, settings };
}).map((c) => ({ ...c, request: { ...c.request, engine_settings: { jolt: c.settings } } }));

test('Jolt runs what softtune predicts, and exact runs what was asked', () => {
  const started = Date.now();
  const { failures, table } = conform('jolt', cases, run);
  console.log(table);
  console.log(`  ${((Date.now() - started) / 1000).toFixed(1)} s`);
  assert.deepEqual(failures, []);
});

// Refused plain exports (exact mode's c' + h k' at or below 0 at the collision step) run in Jolt: each
// does what its `predicted` says -- an undamped spring where the float sum leaves a few ulp, NaN where it
// rounds to 0, a growing one below -- and `exact` keeps damping + h stiffness clear of zero.
const refusedCases = refusedGrid(36, (i) => {
  const settings = { springMode: modes[i % 3], collisionSteps: 1 + ((i * 5) % 4), linearDamping: i % 4 === 2 ? 0.05 : 0 };
  const body = i % 5 === 3 ? 'rotating_plank' : 'point';
  return { body, label: `${body} ${JSON.stringify(settings)}`, settings };
}).map((c) => ({ ...c, request: { ...c.request, engine_settings: { jolt: c.settings } } }));

test('a refused export runs in Jolt as predicted, and is never exported as exact', () => {
  const { rows, failures, table } = conform('jolt', refusedCases, run);
  console.log(table);
  assert.deepEqual(failures, []);
  assert.ok(rows.filter((r) => r.refused).length >= 24);
  for (const r of rows.filter((row) => row.report.exact !== null)) {
    const s = r.report.settings, h = 1 / (r.case.request.fps * r.case.request.substeps * s.collisionSteps);
    const m = r.case.request.effective_mass, e = r.report.exact;
    const scale = s.springMode === 'MassNormalizedStiffnessAndDamping' ? m : 1;
    if (s.springMode === 'FrequencyAndDamping') {
      const w = 2 * Math.PI * e['SpringSettings::mFrequency'];
      assert.ok(2 * e['SpringSettings::mDamping'] * w + h * w * w >= 1e-4 * h * w * w);
    } else {
      const k = scale * e['SpringSettings::mStiffness'], c = scale * e['SpringSettings::mDamping'];
      assert.ok(c + h * k >= 1e-4 * h * k);
    }
  }
});

// Near misses: mLinearDamping damps at least about damping / (2 omega), so zeta 0 has no exact spring; where
// that floor is within 0.02 the least-damped spring is given as `exact`, flagged engine_inexact, and Jolt
// runs it as its exact_predicted says (conform holds it there, and that prediction within 1 % / 0.02).
const nearCases = [[3, 0.5, 1], [2, 0.3, 20], [5, 1.0, 0.05], [1, 0.15, 1], [4, 0.6, 2]].map(([hz, d, m], i) => ({
  index: i, body: i === 4 ? 'rotating_plank' : 'point', label: `near miss, linearDamping ${d}`,
  request: { fps: 60, substeps: 1, frequency_hz: hz, damping_ratio: 0, mode: 'standard', effective_mass: m,
             engine_settings: { jolt: { springMode: modes[i % 3], linearDamping: d } } },
}));

test('a near miss gives the nearest legal value, and Jolt runs it as predicted', () => {
  const { rows, failures, table } = conform('jolt', nearCases, run);
  console.log(table);
  assert.deepEqual(failures, []);
  assert.equal(rows.filter((r) => r.nearest).length, nearCases.length);
});

// identify's correction in Jolt (8 Hz / 0.3 at 60 fps, its collision step damps by itself): each round types
// the correction's `parameters` into Jolt, records it and sends the recording back. Where `next` has a
// negative damping ratio that Jolt takes (damping + h stiffness > 0) the parameters are given, and Jolt
// runs them as `parameters_predicted` says.
test('identify gives Jolt the negative damping it takes, and Jolt runs it as predicted', () => {
  const request = { fps: 60, frequency_hz: 8, damping_ratio: 0.3, effective_mass: 2 };
  const first = tune(request).engines.jolt;
  const dt = 1 / 60, steps = 240;
  const runWith = (parameters) => runJolt(J, { body: 'point', effectiveMass: 2, settings: runnerSettings(first),
                                               parameters, dt, steps, x0: 0.05 });
  const csv = (x) => 'time,x\n' + x.map((v, n) => `${n * dt},${v}`).join('\n') + '\n';
  let parameters = first.parameters, typed = { frequency_hz: 8, damping_ratio: 0.3 };
  const previous = [];
  let negative = 0;
  for (let round = 0; round < 4; ++round) {
    const x = runWith(parameters);
    const answer = identify({ csv: csv(x), request, engine: 'jolt', typed, previous });
    const c = answer.correction;
    previous.push({ typed, measured: { frequency_hz: answer.frequency_hz, damping_ratio: answer.damping_ratio } });
    if (c.verdict === 'met') break;
    const next = c.next, omega = 2 * Math.PI * next.frequency_hz;
    if (2 * next.damping_ratio + omega * dt > 0) {
      assert.ok(c.parameters, `round ${round}: next ${JSON.stringify(next)} has no parameters`);
    }
    if (next.damping_ratio < 0) ++negative;
    if (!c.parameters) break;
    assert.ok(Math.abs(c.parameters['SpringSettings::mDamping'] - next.damping_ratio) < 1e-9);
    // Jolt runs the correction as its prediction says.
    const p = c.parameters_predicted, m = fit(runWith(c.parameters), dt);
    assert.ok(m && Math.abs(m.frequencyHz / p.frequency_hz - 1) <= 0.01 && Math.abs(m.dampingRatio - p.damping_ratio) <= 0.02,
              `round ${round}: Jolt ran ${JSON.stringify(m)}, predicted ${JSON.stringify(p)}`);
    parameters = c.parameters;
    typed = { frequency_hz: next.frequency_hz, damping_ratio: next.damping_ratio };
  }
  console.log(`  identify in Jolt at 8 Hz / 0.3: ${previous.length} rounds, ${negative} with a negative next, each given ` +
              `in Jolt's fields; last measured ${JSON.stringify(previous[previous.length - 1].measured)}`);
  assert.ok(negative >= 1);
});
