// web/chain.js: the chain field of the tune request from the mass-ratio box, and the rows the page shows
// from a tune answer's chain (the shape of POST /api/v1/tune's `chain`, checked against a real
// `softtune tune` when SOFTTUNE_BIN is set).
// Run: node --test tests/web/chain.test.mjs
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { chainField, chainRows } from '../../web/chain.js';

test('the mass-ratio box: empty is no chain, a number in [1, 1e9] is one, anything else an error', () => {
  assert.equal(chainField(''), undefined);
  assert.equal(chainField('  '), undefined);
  assert.deepEqual(chainField('1000'), { mass_ratio: 1000 });
  assert.deepEqual(chainField('1e6'), { mass_ratio: 1e6 });
  for (const bad of ['0.5', 'abc', '2e9', 'Infinity']) assert.ok(chainField(bad) instanceof Error, bad);
});

test('rows from a real tune answer: one per solver, the verdict against the asked frequency', () => {
  const bin = process.env.SOFTTUNE_BIN;
  if (!bin) return;
  // 20 Hz at 60 fps on a 1e3 mass ratio: Box2D 2.4 with one velocity iteration blows up (above ~13.5 Hz).
  const request = JSON.stringify({ frequency_hz: 20, damping_ratio: 0, effective_mass: 1,
    chain: { mass_ratio: 1000, solvers: ['box2d_v2_4', 'rapier'] },
    engine_settings: { box2d_v2_4: { velocityIterations: 1 } } });
  const tune = JSON.parse(execFileSync(bin, ['tune', '--request', '-'], { input: request }).toString());
  const rows = chainRows(tune);
  assert.equal(rows.length, 2);
  const [box2d, rapier] = rows;
  assert.equal(box2d[0], 'box2d_v2_4');
  assert.equal(box2d[1], 'velocityIterations = 1, warm start');
  assert.equal(box2d[3], 'blows up');
  assert.match(box2d[4], /^\d+$/);
  assert.ok(Number(box2d[4]) > 1);
  assert.equal(rapier[3], 'stable with margin');  // joints not warm-started: no limit
  assert.match(rapier[2], /^none up to/);
  for (const row of rows) for (const cell of row) assert.doesNotMatch(cell, /NaN|undefined/);
});

test('no chain in the answer: no rows', () => {
  assert.deepEqual(chainRows({}), []);
  assert.deepEqual(chainRows({ chain: null }), []);
});
