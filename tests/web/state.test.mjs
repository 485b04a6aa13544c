// web/state.js: the URL round trip, the requests it builds (accepted by the real codec, with the effective
// mass of a 2-D constraint equal to the hand-computed 1 / (J M^-1 J^T)), and presets tuned from the page.
// Run: SOFTTUNE_BIN=build/softtune node --test tests/web/state.test.mjs
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { fromQuery, stateFromScene, toQuery, tuneRequest, tunedScene } from '../../web/state.js';

const softtune = process.env.SOFTTUNE_BIN ?? 'build/softtune';
const tune = (request) => JSON.parse(execFileSync(softtune, ['tune', '--request', '-'], { input: JSON.stringify(request), encoding: 'utf8' }));

// The page's defaults, as index.html writes them (readForm needs a DOM; these are its values).
const DEFAULTS = {
  preset: '', body: 'mass', mass: '1', ctype: 'linear', a_static: '1', a_mass: '1', a_inertia: '', a_x: '0', a_y: '0',
  a_angle: '0', b_static: '', b_mass: '2', b_inertia: '0.5', b_x: '1', b_y: '0', b_angle: '0', anchor_a_x: '0',
  anchor_a_y: '0', anchor_b_x: '1', anchor_b_y: '0.5', axis_x: '1', axis_y: '0', frames: '12', basis: '60', osc: 'some',
  zeta: '0.5', fps: '60', substeps: '1', mode: 'standard',
};

test('a query holds only what differs from the defaults and restores it', () => {
  const state = { ...DEFAULTS, frames: '24', osc: '', zeta: '0.25', mode: 'exact' };
  const query = toQuery(state, DEFAULTS);
  assert.equal(query, 'frames=24&osc=&zeta=0.25&mode=exact');
  assert.deepEqual(fromQuery(query, DEFAULTS), state);
  assert.equal(toQuery(DEFAULTS, DEFAULTS), '');
  // An oscillation word sets the fine slider; unknown keys are ignored.
  assert.equal(fromQuery('osc=none&zeta=0.3&bogus=1', DEFAULTS).zeta, '1');
  assert.ok(!('bogus' in fromQuery('bogus=1', DEFAULTS)));
});

test('the tune request of the default state is what docs/api.md documents, and the codec accepts it', () => {
  assert.deepEqual(tuneRequest(DEFAULTS), { fps: 60, substeps: 1, response_frames: 12, basis_fps: 60, mode: 'standard',
    oscillation: 'some', effective_mass: 1 });
  const r = tune(tuneRequest(DEFAULTS));
  assert.equal(r.frequency_hz, 5);  // f = basis / frames
  assert.equal(r.damping_ratio, 0.5);
});

test('a 2-D constraint request gives the effective mass of J M^-1 J^T', () => {
  // Body B: 3 kg, I = 0.4 kg m^2 at (1, 0); anchor B at (1, 0.5), axis x, body A static.
  // J = [n, r x n] with r = (0, 0.5): r x n = 0 * 0 - 0.5 * 1 = -0.5, so J M^-1 J^T = 1/3 + 0.25 / 0.4.
  const state = fromQuery('body=constraint&b_mass=3&b_inertia=0.4', DEFAULTS);
  const r = tune(tuneRequest(state));
  assert.ok(Math.abs(r.effective_mass - 1 / (1 / 3 + 0.25 / 0.4)) < 1e-12, `${r.effective_mass}`);
  // An empty inertia locks rotation: the anchor offset no longer matters.
  const locked = tune(tuneRequest(fromQuery('body=constraint&b_mass=3&b_inertia=', DEFAULTS)));
  assert.ok(Math.abs(locked.effective_mass - 3) < 1e-12);
});

test('non-numeric text reaches the server, which names the field', () => {
  const request = tuneRequest({ ...DEFAULTS, fps: 'fast' });
  assert.equal(request.fps, 'fast');
  assert.throws(() => execFileSync(softtune, ['tune', '--request', '-'], { input: JSON.stringify(request), stdio: 'pipe' }),
    (e) => e.status === 2 && JSON.parse(e.stderr.toString()).field === 'fps');
});

test('a preset takes the page step and tuning, keeping a mode an item names itself', () => {
  const scene = {
    name: 'two', world: { fps: 60, duration_s: 3 },
    oscillators: [
      { id: 'a', effective_mass: 2, response_frames: 30, oscillation: 'some' },
      { id: 'b', effective_mass: 2, frequency_hz: 2, damping_ratio: 0.2, mode: 'exact' },
      { id: 'c', effective_mass: 1 },
    ],
  };
  const seeded = stateFromScene(scene);
  assert.deepEqual(seeded, { fps: '60', substeps: '1', basis: '60', frames: '30', osc: 'some', zeta: '0.5', mode: 'standard', body: 'mass', mass: '2' });
  const out = tunedScene(scene, { ...DEFAULTS, frames: '20', osc: '', zeta: '0.3', fps: '120', substeps: '2' });
  assert.deepEqual(out.world, { fps: 120, duration_s: 3, substeps: 2 });
  assert.deepEqual(out.oscillators[0], { id: 'a', effective_mass: 2, response_frames: 20, basis_fps: 60, damping_ratio: 0.3, mode: 'standard' });
  assert.equal(out.oscillators[1].mode, 'exact');
  assert.equal(out.oscillators[1].response_frames, 20);
  assert.ok(!('frequency_hz' in out.oscillators[1]));
  assert.deepEqual(out.oscillators[2], { id: 'c', effective_mass: 1 });
  assert.equal(scene.oscillators[0].response_frames, 30, 'the preset itself is untouched');
});
