// web/simulate_panel.js against a real simulation: the stiff preset's Euler probes read "blew up" (not a
// frequency fitted to the blow-up), damping errors are differences of ratios, each probe has its unit, and
// a preset's tuned joints carry k = m_eff omega^2 on their own effective mass.
// Run: SOFTTUNE_BIN=build/softtune node --test tests/web/simulate_panel.test.mjs
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { modalTargetCells, probeCells, probeUnit, tunedJoints } from '../../web/simulate_panel.js';

const softtune = process.env.SOFTTUNE_BIN ?? 'build/softtune';
const presets = new URL('../../presets', import.meta.url).pathname;
const simulate = (request) => JSON.parse(execFileSync(softtune, ['simulate', '--request', '-', '--presets', presets],
  { input: JSON.stringify(request), encoding: 'utf8' }));

test('the stiff preset: blow-ups say so, the soft constraint has a frequency, damping errors are Δζ', () => {
  const doc = simulate({ preset: 'stiff' });
  const rows = Object.fromEntries(doc.probes.map((p) => [p.id, probeCells(p)]));
  for (const id of ['explicit_euler', 'semi_implicit_euler']) {
    assert.equal(rows[id][2], 'blew up', id);
    assert.equal(rows[id][5], 'blew up', id);
  }
  assert.ok(Number.isFinite(Number(rows.soft[2])), rows.soft.join('|'));
  // Asked zeta 0 (free): the error is the measured ratio itself, as a signed difference, never a percent.
  const soft = doc.probes.find((p) => p.id === 'soft');
  assert.match(rows.soft[6], /^[+−]\d\.\d{3}$/);
  assert.ok(Math.abs(Number(rows.soft[6].replace('−', '-')) - (soft.measured.damping_ratio - soft.requested.damping_ratio)) < 5e-4);
  assert.equal(rows.soft[0], 'soft (m)');
  assert.equal(probeUnit('joint_angle'), 'rad');
});

test('a tuned preset lists its joints on their own effective masses with k = m omega^2', () => {
  const joints = tunedJoints(simulate({ preset: 'buddhas', tuning: { response_frames: 30, oscillation: 'some', mode: 'standard' } }));
  assert.equal(joints.length, 4);
  const omega = 2 * Math.PI * 2;  // 30 frames at 60 fps
  for (const j of joints) assert.ok(Math.abs(j.k - j.model_mass * omega * omega) < 1e-9 * j.k, `${j.id}: ${j.k}`);
});

test('the vehicle tuned by its heave: the row shows asked, predicted and measured, errors in % and Δζ', () => {
  const out = simulate({ preset: 'vehicle' });
  const t = out.modal_tuning.targets[0];
  const cells = modalTargetCells(t);
  assert.equal(cells[0], 'chassis heave');
  assert.equal(cells[1], '3 Hz, ζ 0.5');  // the preset asks 20 frames at 60 fps, some oscillation
  assert.match(cells[2], /^3 Hz, ζ 0\.5$/);  // exact mode: the linear model lands on the request at the step
  // Measured in Box2D within the preset's own bar (3 %, 0.05), and the error column is that measurement's.
  assert.ok(Math.abs(t.measured.frequency_hz / 3 - 1) < 0.03, cells[3]);
  assert.ok(Math.abs(t.measured.damping_ratio - 0.5) < 0.05, cells[3]);
  const pct = (100 * (t.measured.frequency_hz / 3 - 1)).toFixed(2);
  assert.ok(cells[4].startsWith(`${Number(pct) > 0 ? '+' : ''}${pct} %, Δζ `), cells[4]);
  assert.deepEqual(modalTargetCells({ mode: 'x', requested: { frequency_hz: 1, damping_ratio: 0 } }).slice(2), ['—', '—', '—']);
});
