// web/exchange.js: an exported preset request imports back to the same controls, a tune request imports
// too, a file without a tuning is refused.
// Run: node --test tests/web/exchange.test.mjs
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { stateFromDocument } from '../../web/exchange.js';
import { presetRequest, stateFromScene } from '../../web/state.js';

const WORDS = JSON.parse(readFileSync(new URL('../../server/http/openapi.json', import.meta.url))).components.schemas
  .TuneRequest.properties.oscillation['x-damping-ratio'];

test('an exported preset request imports back to the controls it came from', () => {
  const state = { preset: 'vehicle', frames: '40', basis: '30', osc: '', zeta: '0.25', fps: '120', substeps: '2', mode: 'exact' };
  const back = stateFromDocument(presetRequest(state), WORDS);
  for (const key of Object.keys(state)) assert.equal(back[key], state[key], key);
  // An oscillation word sets the fine slider from the server's mapping.
  assert.equal(stateFromDocument({ preset: 'mouse', tuning: { response_frames: 15, oscillation: 'none' } }, WORDS).zeta, '1');
});

test('a tune request imports as a custom body; a file without a tuning is refused', () => {
  const s = stateFromDocument({ response_frames: 8, oscillation: 'free', effective_mass: 3, fps: 30 }, WORDS);
  assert.equal(s.preset, '');
  assert.equal(s.frames, '8');
  assert.equal(s.mass, '3');
  assert.equal(s.fps, '30');
  assert.throws(() => stateFromDocument({ hello: 1 }, WORDS), /no preset, scene or tuning/);
  assert.throws(() => stateFromDocument([1, 2], WORDS), /not a JSON object/);
});

test('a preset exported with another mode picked imports back to that preset and pick', () => {
  const scene = JSON.parse(readFileSync(new URL('../../presets/vehicle.json', import.meta.url)));
  const state = { ...stateFromScene(scene, WORDS), preset: 'vehicle', frames: '30' };
  for (const target of ['springs', 'chassis.pitch']) {
    const doc = presetRequest({ ...state, target }, scene);
    assert.ok(doc.scene, target);  // not the preset as it stands: its scene travels with the pick
    const back = stateFromDocument(doc, WORDS);
    assert.equal(back.preset, 'vehicle', target);
    assert.equal(back.target, target);
    assert.equal(back.frames, '30', target);
  }
  // The preset as it stands travels by name, and its import leaves the pick to the preset's own target.
  const own = stateFromDocument(presetRequest(state, scene), WORDS);
  assert.equal(own.preset, 'vehicle');
  assert.equal(own.target, undefined);
});
