// Rapier conformance (npm @dimforge/rapier2d-compat and rapier3d-compat 0.21.0): softtune's `rapier` report
// run in the real engine. Run by ctest as `node --test` with SOFTTUNE_BIN set to the softtune binary.
import assert from 'node:assert/strict';
import { test } from 'node:test';

import { conform, grid, refusedGrid, tune } from '../js/conformance.mjs';
import { initRapier, runRapier } from './rapier_run.mjs';

await initRapier();

// Report settings as the runner reads them, under the engine's own names.
function runnerSettings(report) {
  const s = report.settings;
  return {
    'IntegrationParameters::num_solver_iterations': s.numSolverIterations,
    'IntegrationParameters::num_internal_pgs_iterations': s.numInternalPgsIterations,
    'RigidBodyDesc::additionalSolverIterations': s.additionalSolverIterations,
    'RigidBodyDesc::linearDamping': s.linearDamping,
  };
}

function run(c, report, parameters, dt, steps) {
  return runRapier({
    dim: c.dim,
    body: c.body,
    effectiveMass: c.request.effective_mass,
    settings: runnerSettings(report),
    parameters,
    dt,
    steps,
    // Large against f32's resolution, small enough that the plank's turn stays linear (0.04 rad).
    x0: c.body === 'rotating_plank' ? 0.02 : 0.05,
  });
}

// Engine settings cycle through the defaults (4 solver iterations, AccelerationBased) and the changes a user
// makes: other iteration counts, ForceBased, more PGS iterations, extra body iterations, linear damping.
const iterations = [4, 1, 2, 4, 8];
const cases = grid(66, (i) => {
  const settings = { numSolverIterations: iterations[i % iterations.length] };
  if (i % 2 === 1) settings.motorModel = 'ForceBased';
  if (i % 7 === 3) settings.numInternalPgsIterations = 2;
  if (i % 9 === 4) settings.additionalSolverIterations = 1;
  if (i % 11 === 6) settings.linearDamping = 0.3;
  const body = i % 3 === 1 ? 'rotating_plank' : 'point';
  const dim = body === 'point' && i % 6 === 2 ? 3 : 2;
  return { body, dim, label: `${body} ${dim}d ${JSON.stringify(settings)}`, settings };
}).map((c) => ({ ...c, request: { ...c.request, engine_settings: { rapier: c.settings } } }));

test('Rapier runs what softtune predicts, and exact runs what was asked', () => {
  const started = Date.now();
  // A Rapier world step costs 0.1-0.2 ms under node here: runs stop at 300 steps (a part of the slowest
  // periods, which Prony's fit reads exactly off Rapier's low-noise trajectory).
  const { failures, table } = conform('rapier', cases, run, { maxSteps: 300 });
  console.log(table);
  console.log(`  ${((Date.now() - started) / 1000).toFixed(1)} s`);
  assert.deepEqual(failures, []);
});

test('the issue: the default step is softtune substeps 4, and exact at zeta 0 stays clear of the lock', () => {
  const ask = { fps: 60, frequency_hz: 10, damping_ratio: 0, mode: 'standard', effective_mass: 1 };
  const rapier = tune({ ...ask, substeps: 1 }).engines.rapier;
  const four = tune({ ...ask, substeps: 4 });
  assert.ok(Math.abs(rapier.predicted.frequency_hz / four.achieved.frequency_hz - 1) < 1e-9);
  assert.ok(Math.abs(rapier.predicted.damping_ratio - four.achieved.damping_ratio) < 1e-9);
  const exact = tune({ ...ask, substeps: 1, mode: 'exact' }).engines.rapier;
  // c' = -h k' at 1/60 is negative compliance at 1/240: refused, and `predicted` says it grows.
  assert.ok(exact.warnings.some((w) => w.code === 'engine_refuses'));
  assert.equal(exact.predicted.stable, false);
  const h = 1 / 240, k = exact.exact['JointMotor::stiffness'], c = exact.exact['JointMotor::damping'];
  assert.ok(c + h * k >= 1e-4 * h * k);
});

// Refused plain exports (exact mode's c' + h k' at or below 0 at the substep) run in Rapier: each does what
// its `predicted` says (growing with the negative damping; at one iteration, where the two f32 sums round
// to a few ulp, the motor their ratio sets, or locked where one rounds to 0).
const refusedCases = refusedGrid(30, (i) => {
  const settings = { numSolverIterations: iterations[i % iterations.length] };
  if (i % 2 === 1) settings.motorModel = 'ForceBased';
  const body = i % 5 === 3 ? 'rotating_plank' : 'point';
  const dim = body === 'point' && i % 4 === 2 ? 3 : 2;
  return { body, dim, label: `${body} ${dim}d ${JSON.stringify(settings)}`, settings };
}).map((c) => ({ ...c, request: { ...c.request, engine_settings: { rapier: c.settings } } }));

test('a refused export runs in Rapier as predicted', () => {
  const { rows, failures, table } = conform('rapier', refusedCases, run, { maxSteps: 300 });
  console.log(table);
  assert.deepEqual(failures, []);
  assert.ok(rows.filter((r) => r.refused).length >= 20);
});

// Near misses: linear damping d damps at least about d / (2 omega), so zeta 0 has no exact motor; where that
// floor is within 0.02 the nearest legal motor is given as `exact`, flagged engine_inexact, and Rapier runs
// it as its exact_predicted says.
const nearCases = [[3, 0.3, 1], [1.5, 0.3, 20], [5, 0.8, 0.05], [3, 0.6, 2]].map(([hz, d, m], i) => ({
  index: i, body: i === 3 ? 'rotating_plank' : 'point', dim: 2, label: `near miss, linearDamping ${d}`,
  request: { fps: 60, substeps: 1, frequency_hz: hz, damping_ratio: 0, mode: 'standard', effective_mass: m,
             engine_settings: { rapier: { linearDamping: d, motorModel: i % 2 ? 'ForceBased' : 'AccelerationBased' } } },
}));

test('a near miss gives the nearest legal value, and Rapier runs it as predicted', () => {
  const { rows, failures, table } = conform('rapier', nearCases, run, { maxSteps: 300 });
  console.log(table);
  assert.deepEqual(failures, []);
  assert.equal(rows.filter((r) => r.nearest).length, nearCases.length);
});
