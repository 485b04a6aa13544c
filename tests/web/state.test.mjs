// web/state.js: the URL round trip, the requests it builds (accepted by the real codec, with the effective
// mass of a 2-D constraint equal to the hand-computed 1 / (J M^-1 J^T)), and presets tuned from the page.
// Run: SOFTTUNE_BIN=build/softtune node --test tests/web/state.test.mjs
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { readFileSync } from 'node:fs';
import { fromQuery, presetRequest, previewFrames, previewRequest, stateFromScene, toQuery, tuneRequest } from '../../web/state.js';

const softtune = process.env.SOFTTUNE_BIN ?? 'build/softtune';
const presets = new URL('../../presets', import.meta.url).pathname;
const simulate = (request) => JSON.parse(execFileSync(softtune, ['simulate', '--request', '-', '--presets', presets], { input: JSON.stringify(request), encoding: 'utf8' }));
// The oscillation words as the server documents them (the page reads the same field at start).
const WORDS = JSON.parse(readFileSync(new URL('../../server/http/openapi.json', import.meta.url))).components.schemas
  .TuneRequest.properties.oscillation['x-damping-ratio'];
const tune = (request) => JSON.parse(execFileSync(softtune, ['tune', '--request', '-'], { input: JSON.stringify(request), encoding: 'utf8' }));

// The page's defaults, as index.html writes them (readForm needs a DOM; these are its values).
const DEFAULTS = {
  preset: '', body: 'mass', mass: '1', ctype: 'linear', a_static: '1', a_mass: '1', a_inertia: '', a_x: '0', a_y: '0',
  a_angle: '0', b_static: '', b_mass: '2', b_inertia: '0.5', b_x: '1', b_y: '0', b_angle: '0', anchor_a_x: '0',
  anchor_a_y: '0', anchor_b_x: '1', anchor_b_y: '0.5', axis_x: '1', axis_y: '0', frames: '12', basis: '60', osc: 'some',
  zeta: '0.5', fps: '60', substeps: '1', mode: 'standard', joint: '', target: '',
};

test('a query holds only what differs from the defaults and restores it', () => {
  const state = { ...DEFAULTS, frames: '24', osc: '', zeta: '0.25', mode: 'exact' };
  const query = toQuery(state, DEFAULTS);
  assert.equal(query, 'frames=24&zeta=0.25&mode=exact');
  assert.deepEqual(fromQuery(query, DEFAULTS, WORDS), state);
  // A link written before this form (an empty osc) still reads the same.
  assert.deepEqual(fromQuery('frames=24&osc=&zeta=0.25&mode=exact', DEFAULTS, WORDS), state);
  assert.equal(toQuery(DEFAULTS, DEFAULTS), '');
  // An oscillation word sets the fine slider; unknown keys are ignored.
  assert.equal(fromQuery('osc=none&zeta=0.3&bogus=1', DEFAULTS, WORDS).zeta, '1');
  // The words are the core's damping ratios (docs/math.md), read from the server, not copied into the page.
  assert.deepEqual(WORDS, { free: 0, some: 0.5, none: 1 });
  assert.ok(!('bogus' in fromQuery('bogus=1', DEFAULTS)));
});

test('the documented short forms are read, and no key is ever written empty', () => {
  // ?zeta=0.25 alone is a fine damping ratio: no oscillation word (the default "some" must not win).
  const fine = fromQuery('zeta=0.25', DEFAULTS, WORDS);
  assert.equal(fine.osc, '');
  assert.equal(fine.zeta, '0.25');
  assert.equal(tuneRequest(fine).damping_ratio, 0.25);
  assert.equal(tuneRequest(fine).oscillation, undefined);
  // A fine ratio equal to the default word's ratio is still a fine ratio, and says so.
  assert.equal(toQuery({ ...DEFAULTS, osc: '', zeta: '0.5' }, DEFAULTS), 'zeta=0.5');
  assert.equal(fromQuery('zeta=0.5', DEFAULTS, WORDS).osc, '');
  // A word's ratio follows from the word: never written beside it.
  assert.equal(toQuery({ ...DEFAULTS, osc: 'none', zeta: '1' }, DEFAULTS), 'osc=none');
  // The request's own field names are read as the controls'.
  assert.deepEqual(fromQuery('response_frames=24&damping_ratio=0.3&basis_fps=30&effective_mass=2', DEFAULTS, WORDS),
    { ...DEFAULTS, frames: '24', osc: '', zeta: '0.3', basis: '30', mass: '2' });
  // Empty values (an inertia left empty, a box unticked) are "none", and read back as empty.
  const emptied = { ...DEFAULTS, body: 'constraint', a_static: '', b_inertia: '' };
  const query = toQuery(emptied, DEFAULTS);
  assert.equal(query, 'body=constraint&a_static=none&b_inertia=none');
  assert.deepEqual(fromQuery(query, DEFAULTS, WORDS), emptied);
  assert.equal(fromQuery('osc=none', DEFAULTS, WORDS).osc, 'none', '"none" is a word for the oscillation');
  // Keys without a default (the identify drop's engine picker) are not written: no `identify-engine=`.
  assert.equal(toQuery({ ...DEFAULTS, 'identify-engine': '', frames: '30' }, DEFAULTS), 'frames=30');
  for (const q of [query, toQuery({ ...DEFAULTS, osc: '', zeta: '0.25' }, DEFAULTS)]) {
    for (const [k, v] of new URLSearchParams(q)) assert.notEqual(v, '', `empty key ${k} in ${q}`);
  }
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

test('a preset seeds the controls from its first tuned item', () => {
  const scene = {
    name: 'two', world: { fps: 60, duration_s: 3 },
    oscillators: [
      { id: 'a', effective_mass: 2, response_frames: 30, oscillation: 'some' },
      { id: 'b', effective_mass: 2, frequency_hz: 2, damping_ratio: 0.2, mode: 'exact' },
    ],
  };
  assert.deepEqual(stateFromScene(scene, WORDS), { fps: '60', substeps: '1', target: 'springs', basis: '60', frames: '30', osc: 'some', zeta: '0.5', mode: 'standard', body: 'mass', mass: '2' });
});

test('the page tunes a preset by name: `softtune simulate --request` gives its joints the page tuning', () => {
  // 40 frames at 60 fps (1.5 Hz), some oscillation, exact mode, 120 fps with 2 substeps, on the vehicle tuned
  // spring by spring (the modal vehicle solves its springs for the heave instead).
  const state = { ...DEFAULTS, preset: 'vehicle_per_spring', frames: '40', mode: 'exact', fps: '120', substeps: '2' };
  const request = presetRequest(state);
  assert.deepEqual(request, { preset: 'vehicle_per_spring', tuning: { fps: 120, substeps: 2, response_frames: 40, basis_fps: 60, mode: 'exact', oscillation: 'some' } });
  const out = simulate(request);
  assert.equal(out.fps, 120);
  for (const j of out.joints.filter((x) => x.tuned)) {
    assert.equal(j.requested.frequency_hz, 1.5, j.id);
    assert.equal(j.requested.damping_ratio, 0.5, j.id);
  }
  // Exact mode on its own mass: the joint's k is k' of the tune answer for that mass at h = 1 / 240.
  const j = out.joints.find((x) => x.tuned);
  const t = tune({ fps: 120, substeps: 2, response_frames: 40, basis_fps: 60, mode: 'exact', oscillation: 'some', effective_mass: j.model_mass });
  assert.ok(Math.abs(j.stiffness - t.k) <= 1e-9 * t.k, `${j.stiffness} vs ${t.k}`);
});

test('the mode pick: the preset by name for its own target, without modal tuning for each spring, the picked mode solved', () => {
  const scene = JSON.parse(readFileSync(`${presets}/vehicle.json`, 'utf8'));
  const own = stateFromScene(scene, WORDS);
  assert.equal(own.target, 'chassis.heave');  // the vehicle's own modal target is what the page starts from
  // ... with that target's ask and the modal solve's mode (exact), not a spring's own fields.
  assert.equal(own.mode, scene.modal_tuning.mode);
  assert.equal(own.frames, String(scene.modal_tuning.targets[0].response_frames));
  assert.equal(own.osc, scene.modal_tuning.targets[0].oscillation);
  const state = { ...DEFAULTS, ...own, preset: 'vehicle', frames: '24', mode: 'exact' };
  assert.deepEqual(presetRequest(state, scene), presetRequest(state, null));
  assert.equal(presetRequest(state, scene).preset, 'vehicle');
  // The preview asks the same scene as the simulation, whatever the pick.
  for (const target of ['chassis.heave', 'springs', 'chassis.pitch']) {
    const picked = { ...state, target };
    const { frames, size, wait, ...asked } = previewRequest(picked, {}, scene);
    assert.deepEqual(asked, presetRequest(picked, scene), target);
  }
  // By name: the heave lands on the sliders' 2.5 Hz (24 frames at 60 fps), exact at the step.
  const heave = simulate(presetRequest(state, scene)).modal_tuning.targets[0];
  assert.equal(heave.mode, 'chassis heave');
  assert.ok(Math.abs(heave.predicted.frequency_hz - 2.5) < 1e-6, `${heave.predicted.frequency_hz}`);
  // Each spring on its own mass: no modal solve, every spring asked the sliders' 2.5 Hz on its own mass.
  const springs = simulate(presetRequest({ ...state, target: 'springs' }, scene));
  assert.equal(springs.modal_tuning, undefined);
  for (const j of springs.joints.filter((x) => x.tuned)) assert.equal(j.requested.frequency_hz, 2.5, j.id);
  // Another mode: the pitch is solved to the sliders' request instead of the heave.
  const pitch = simulate(presetRequest({ ...state, target: 'chassis.pitch' }, scene)).modal_tuning.targets[0];
  assert.equal(pitch.mode, 'chassis pitch');
  assert.ok(Math.abs(pitch.predicted.frequency_hz - 2.5) < 1e-6, `${pitch.predicted.frequency_hz}`);
  assert.ok(Math.abs(pitch.predicted.damping_ratio - 0.5) < 1e-6, `${pitch.predicted.damping_ratio}`);
});

test('a preview covers its whole duration at up to the playback rate, within the frame cap', () => {
  assert.equal(previewFrames(6, 30), 181);
  assert.equal(previewFrames(2, 30), 61);
  assert.equal(previewFrames(100, 60), 600);
  assert.equal(previewFrames(0, 30), 2);
});
