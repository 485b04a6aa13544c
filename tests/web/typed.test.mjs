// web/typed.js: the preset "as typed". What a simulate answer says to type, pasted back into the scene by the
// page's own function, is accepted by the real codec and measures what the answer measured (the copy test,
// here from the page's side); a joint the scene does not have is named.
// Run: SOFTTUNE_BIN=build/softtune node --test tests/web/typed.test.mjs
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { readFileSync } from 'node:fs';
import { parseTyped, typedScene, valuesToType } from '../../web/typed.js';

const softtune = process.env.SOFTTUNE_BIN ?? 'build/softtune';
const presets = new URL('../../presets/', import.meta.url);
const run = (input) => JSON.parse(execFileSync(softtune, ['simulate', '--request', '-'], { input: JSON.stringify(input), encoding: 'utf8', cwd: new URL('../..', import.meta.url) }));

test('the vehicle typed back as the page pastes it measures its heave as the answer did', () => {
  const scene = JSON.parse(readFileSync(new URL('vehicle.json', presets), 'utf8'));
  const answer = run({ preset: 'vehicle' });
  const values = valuesToType(answer);
  assert.deepEqual(Object.keys(values), ['rear_suspension', 'front_suspension']);
  assert.equal(values.rear_suspension['b2WheelJointDef::stiffness'], answer.modal_tuning.groups[0].stiffness);
  const typed = typedScene(scene, parseTyped(JSON.stringify(values)));
  assert.equal(typed.modal_tuning, undefined);
  assert.equal(scene.modal_tuning.groups.length, 1, 'the preset itself is left alone');
  const again = run({ scene: typed });
  assert.ok(again.joints.every((j) => j.typed && !j.tuned));
  const heave = (doc) => doc.probes.find((p) => p.id === 'heave').measured;
  assert.ok(Math.abs(heave(again).frequency_hz / heave(answer).frequency_hz - 1) < 0.01);
  assert.ok(Math.abs(heave(again).damping_ratio - heave(answer).damping_ratio) < 0.01);
});

test('a joint the scene does not have, or text that is not an object, is refused by name', () => {
  const scene = JSON.parse(readFileSync(new URL('mouse.json', presets), 'utf8'));
  assert.throws(() => typedScene(scene, { no_such_joint: {} }), /"no_such_joint" is not a joint of mouse/);
  assert.throws(() => parseTyped('[1, 2]'), /give an object/);
  assert.throws(() => parseTyped('{'), /not JSON/);
  // The stiff preset's oscillators copy its joint's tuning: typed, they go with their probes.
  const stiff = JSON.parse(readFileSync(new URL('stiff.json', presets), 'utf8'));
  const typed = typedScene(stiff, { spring: { 'b2DistanceJointDef::stiffness': 100, 'b2DistanceJointDef::damping': 1 } });
  assert.ok(typed.oscillators.every((o) => o.joint !== 'spring'));
  assert.ok(typed.probes.every((p) => p.kind !== 'oscillator' || typed.oscillators.some((o) => o.id === p.oscillator)));
  assert.ok(run({ scene: typed }).joints[0].typed);
});
