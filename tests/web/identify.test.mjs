// web/identify.js: the query of a CSV identify request, the overlay of a recording on the response plot
// (normalised like it: x0 = 1 about the fitted equilibrium) and the engine-table row, from a fixed answer of
// POST /api/v1/identify.
// Run: node --test tests/web/identify.test.mjs
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { identifiedRow, identifyQuery, overlayCurves, roundBody, roundOf } from '../../web/identify.js';

const softtune = process.env.SOFTTUNE_BIN ?? 'build/softtune';
const identify = (body) => JSON.parse(execFileSync(softtune, ['identify', '--request', '-'], { input: JSON.stringify(body), encoding: 'utf8' }));

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

test('later recordings go with the earlier rounds, and the service iterates on them', () => {
  const request = { fps: 60, response_frames: 12, basis_fps: 60, oscillation: 'some', effective_mass: 1 };
  // A black box that runs 20 % slow: 4 Hz measured where 5 was typed, sampled at 60 Hz.
  const csv = (f, zeta) => ['t,x', ...Array.from({ length: 181 }, (_, n) => {
    const t = n / 60, w = 2 * Math.PI * f;
    return `${t},${Math.exp(-zeta * w * t) * Math.cos(w * Math.sqrt(1 - zeta * zeta) * t)}`;
  })].join('\n');
  const first = identify(roundBody(csv(4, 0.5), request, '', [], null));
  assert.equal(first.correction.rounds, 1);
  const r1 = roundOf(first);
  assert.deepEqual(r1.typed, { frequency_hz: 5, damping_ratio: 0.5 });  // the request as typed
  assert.ok(Math.abs(r1.measured.frequency_hz - 4) < 0.02, `${r1.measured.frequency_hz}`);
  // The designer typed `next` (6.25 Hz: 5 x 5 / 4) and recorded 5 Hz: the second answer counts both rounds.
  const body = roundBody(csv(5, 0.5), request, 'godot', [r1], first.correction.next);
  assert.deepEqual(body.typed, { frequency_hz: first.correction.next.frequency_hz, damping_ratio: first.correction.next.damping_ratio });
  assert.equal(body.engine, 'godot');
  const second = identify(body);
  assert.equal(second.correction.rounds, 2);
  assert.equal(second.correction.verdict, 'met');
  // At most four earlier rounds (the service's kIdentifyMaxPrevious): the newest.
  const many = Array.from({ length: 6 }, (_, i) => ({ typed: { frequency_hz: i + 1, damping_ratio: 0.5 }, measured: { frequency_hz: i + 1, damping_ratio: 0.5 } }));
  assert.deepEqual(roundBody('t,x', request, '', many, null).previous.map((r) => r.typed.frequency_hz), [3, 4, 5, 6]);
  // A recording that measured no frequency adds no round; a negative fitted ratio is sent as 0 (measured >= 0).
  assert.equal(roundOf({ ...first, frequency_hz: null }), null);
  assert.equal(roundOf({ ...first, damping_ratio: -0.01 }).measured.damping_ratio, 0);
});
