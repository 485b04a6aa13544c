// web/identify.js: the query of a CSV identify request, the overlay of a recording on the response plot
// (normalised like it: x0 = 1 about the fitted equilibrium) and the engine-table row, from a fixed answer of
// POST /api/v1/identify.
// Run: node --test tests/web/identify.test.mjs
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { identifiedRow, identifyQuery, overlayCurves } from '../../web/identify.js';

const answer = {
  frequency_hz: 4.3, damping_ratio: 0.61, equilibrium: { x: 0.5 },
  error: { frequency: -0.14, damping_ratio: 0.11 },
  verdicts: [],
  plot: { time_s: [1, 1.5, 2], recorded: { x: [0.6, 0.45, 0.5] }, fit_time_s: [1, 1.5], fitted: { x: [0.6, 0.45] } },
  correction: { method: 'scaled', next: { frequency_hz: 5.814, damping_ratio: 0.39, k: 2668.9, c: 57 }, parameters: null },
  exact: null,
};

test('the query carries the scalar tune fields and the engine, not nested objects', () => {
  const q = identifyQuery({ frequency_hz: 5, oscillation: 'some', constraint: { axis: [1, 0] } }, 'godot');
  assert.equal(q.get('frequency_hz'), '5');
  assert.equal(q.get('oscillation'), 'some');
  assert.equal(q.get('engine'), 'godot');
  assert.equal(q.has('constraint'), false);
  assert.equal(identifyQuery({}, '').has('engine'), false);
});

test('the overlay starts at x = 1, t = 0 and decays about the equilibrium', () => {
  const [rec, fit] = overlayCurves(answer);
  assert.deepEqual(rec.points.map(([t]) => t), [0, 0.5, 1]);
  assert.ok(Math.abs(rec.points[0][1] - 1) < 1e-12);
  assert.ok(Math.abs(rec.points[1][1] + 0.5) < 1e-12);
  assert.ok(Math.abs(rec.points[2][1]) < 1e-12);
  assert.equal(fit.points.length, 2);
  assert.deepEqual(overlayCurves({ ...answer, equilibrium: { x: 0.6 } }), []);  // no deviation to scale by
});

test('the row says what the engine did and what to type instead', () => {
  const row = identifiedRow(answer, 'godot');
  assert.match(row.did, /^4\.3 Hz, zeta 0\.61 \(-14\.0 %, zeta \+0\.11\)$/);
  assert.equal(row.quality, 'ok');
  assert.deepEqual(row.instead, ['frequency 5.814 Hz, damping ratio 0.39', 'k = 2668.9, c = 57']);
  assert.equal(row.method, 'scaled correction');
  const unreachable = identifiedRow({ ...answer, correction: { ...answer.correction, method: 'secant', verdict: 'beyond_reach' } }, 'bullet');
  assert.equal(unreachable.method, 'secant correction: beyond reach');
  assert.equal(identifiedRow({ ...answer, correction: { ...answer.correction, verdict: 'converging' } }, '').method, 'scaled correction');
  const modelled = identifiedRow({ ...answer, exact: { 'b2DistanceJointDef::stiffness': 2535.585 }, verdicts: [{ code: 'too_noisy' }] }, 'box2d_v2_4');
  assert.deepEqual(modelled.instead, ['b2DistanceJointDef::stiffness = 2535.59']);
  assert.equal(modelled.quality, 'too_noisy');
});
