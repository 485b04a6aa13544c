// web/preset_words.js: every preset the repository ships has designer words, none of them in solver
// terms, and a preset without words shows its description's first sentence.
// Run: node --test tests/web/preset_words.test.mjs
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readdirSync, readFileSync } from 'node:fs';
import { PRESET_WORDS, presetWords } from '../../web/preset_words.js';

const dir = new URL('../../presets/', import.meta.url);
const shipped = readdirSync(dir).filter((f) => f.endsWith('.json') && f !== 'schema.json').map((f) => f.replace(/\.json$/, ''));

test('each shipped preset has designer words, and no word names a preset that is not shipped', () => {
  for (const name of shipped) assert.ok(PRESET_WORDS[name], `${name} has no designer words`);
  for (const name of Object.keys(PRESET_WORDS)) assert.ok(shipped.includes(name), `${name} is not a preset`);
});

test('the words use no solver terms; the scene description stays the technical one', () => {
  const technical = /\b(gamma|beta|ERP|CFM|omega|zeta|linearis|effective mass|slop|skin|eigen|modal|implicit|h\^2|k, c|Hz)\b/i;
  for (const [name, words] of Object.entries(PRESET_WORDS)) assert.doesNotMatch(words, technical, name);
  const vehicle = JSON.parse(readFileSync(new URL('vehicle.json', dir))).description;
  assert.match(vehicle, /polygon skin/, 'the technical description keeps its physics');
});

test('a preset without words reads its description\'s first sentence', () => {
  assert.equal(presetWords('newer', 'A box on a ramp. It slides with k = 10.'), 'A box on a ramp.');
  assert.equal(presetWords('newer', 'No full stop'), 'No full stop');
  assert.equal(presetWords('vehicle', 'ignored'), PRESET_WORDS.vehicle);
});
