// web/exchange.js and web/input_check.js: an exported preset request imports back to the same controls, a
// tune request imports too, a file without a tuning is refused; API details read in designer words.
// Run: node --test tests/web/exchange.test.mjs
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { stateFromDocument } from '../../web/exchange.js';
import { designerMessage } from '../../web/input_check.js';
import { laneValue, oscillatorLanes } from '../../web/oscillator_lanes.js';
import { presetRequest } from '../../web/state.js';

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

test('API details read in designer words', () => {
  assert.equal(designerMessage('give exactly one of effective_mass or constraint', 'Effective mass'),
    'Give exactly one of the effective mass or a 2-D constraint');
  assert.equal(designerMessage('must be > 0', 'Frame rate'), 'Frame rate must be > 0');
  assert.equal(designerMessage('fps * substeps must be <= 1e6', 'Substeps per frame'), 'The frame rate * the substeps must be <= 1e6');
});

test('an oscillator lane blows up once it passes five amplitudes, and stays blown up', () => {
  const [lane] = oscillatorLanes([{ id: 'e', kind: 'oscillator', series: { time: [0, 1, 2, 3], value: [0.1, -0.3, 0.6, 0.2] } }]);
  assert.equal(laneValue(lane, 0.5), 0.1);
  assert.equal(laneValue(lane, 1), -0.3);
  assert.equal(laneValue(lane, 2.5), null, '0.6 is six amplitudes');
  assert.equal(laneValue(lane, 3), null, 'a blow-up does not come back');
});
