// Jolt conformance (npm jolt-physics 1.1.0): softtune's `jolt` report run in the real engine.
// Run by ctest as `node --test` with SOFTTUNE_BIN set to the softtune binary.
import assert from 'node:assert/strict';
import { test } from 'node:test';

import { conform, grid, tune } from '../js/conformance.mjs';
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

test('a refused export is never exported as exact', () => {
  // Exact mode at zeta 0: softtune's k', c' have c' + h k' = 0; the plain export is refused and `exact`
  // (if any) keeps damping + h stiffness clear of zero.
  const r = tune({ fps: 60, substeps: 1, frequency_hz: 5, damping_ratio: 0, mode: 'exact', effective_mass: 1,
                   engine_settings: { jolt: { springMode: 'StiffnessAndDamping', linearDamping: 0 } } }).engines.jolt;
  assert.equal(r.predicted.frequency_hz, null);
  assert.ok(r.warnings.some((w) => w.code === 'engine_refuses'));
  assert.ok(r.exact);
  const h = 1 / 60;
  const k = r.exact['SpringSettings::mStiffness'], c = r.exact['SpringSettings::mDamping'];
  assert.ok(c + h * k >= 1e-4 * h * k);
});
