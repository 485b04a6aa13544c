// web/modes.js: the scene built from a picked mode is accepted by the real codec and its solve lands the mode on
// the sliders' request (the linear model's prediction, `softtune simulate`); the drawing has an arrow per moving
// coordinate. Run: SOFTTUNE_BIN=build/softtune node --test tests/web/modes.test.mjs
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { readFileSync } from 'node:fs';
import {
  SPRINGS, modalScene, modeArrows, modesOfAnswer, modeTarget, parseTarget, sceneTarget, showModes, solvedAnswer, targetKey, targetedScene,
} from '../../web/modes.js';

const softtune = process.env.SOFTTUNE_BIN ?? 'build/softtune';
const presets = new URL('../../presets/', import.meta.url);
const run = (args, input) => JSON.parse(execFileSync(softtune, args, { input: JSON.stringify(input), encoding: 'utf8', cwd: new URL('../..', import.meta.url) }));

test('a picked mode becomes the modal tuning target the solve lands on', () => {
  const scene = JSON.parse(readFileSync(new URL('vehicle_per_spring.json', presets), 'utf8'));
  const modes = run(['modes', '--request', '-'], scene);
  const heave = modes.modes.find((m) => m.name === 'chassis heave');
  assert.deepEqual(modeTarget(heave), { body: 'chassis', mode: 'heave' });
  const tuned = modalScene(scene, { response_frames: 24, basis_fps: 60, oscillation: 'some', mode: 'exact' }, modeTarget(heave));
  assert.equal(tuned.modal_tuning.groups[0].joints.length, 2);
  const out = run(['simulate', '--request', '-'], tuned);
  const target = out.modal_tuning.targets[0];
  assert.equal(target.mode, 'chassis heave');
  assert.ok(Math.abs(target.predicted.frequency_hz - 2.5) < 1e-6);  // 24 frames at 60 fps, exact at the step
  assert.ok(Math.abs(target.predicted.damping_ratio - 0.5) < 1e-6);
  assert.equal(modalScene(scene, {}, null), scene);  // no pick: the scene as given
});

test('the drawing has an arrow for each translation and an arc for a rotation', () => {
  const created = [];
  const doc = {
    createElementNS: (_ns, name) => {
      const e = { name, attrs: {}, children: [], setAttribute(k, v) { this.attrs[k] = v; }, appendChild(c) { this.children.push(c); } };
      created.push(e);
      return e;
    },
  };
  modeArrows({ components: [{ body: 'chassis', coordinate: 'y', amplitude: 1 }, { body: 'chassis', coordinate: 'angle', amplitude: 0.5 },
    { body: 'wheel', coordinate: 'x', amplitude: 0.3 }] }, doc);
  const arrows = created.filter((e) => (e.attrs.class ?? '').includes('mode-arrow'));
  assert.equal(arrows.length, 3);
  assert.equal(created.filter((e) => e.name === 'rect').length, 2);
});

test('a pick is a control value that names the body and its motion, and picks the scene to run', () => {
  assert.equal(targetKey({ body: 'chassis', mode: 'heave' }), 'chassis.heave');
  assert.equal(targetKey(null), SPRINGS);
  assert.deepEqual(parseTarget('deck.plank_5.heave'), { body: 'deck.plank_5', mode: 'heave' });  // a dotted body id
  assert.equal(parseTarget(SPRINGS), null);
  assert.equal(parseTarget('heave'), null);
  const scene = JSON.parse(readFileSync(new URL('vehicle.json', presets), 'utf8'));
  assert.deepEqual(sceneTarget(scene), { body: 'chassis', mode: 'heave' });
  assert.equal(targetedScene(scene, {}, 'chassis.heave'), scene);  // the scene's own target: as given
  assert.equal(targetedScene(scene, {}, SPRINGS).modal_tuning, undefined);
  assert.ok(scene.modal_tuning, 'the preset itself is left alone');
  const pitch = targetedScene(scene, { response_frames: 30, oscillation: 'none' }, 'chassis.pitch').modal_tuning;
  assert.deepEqual(pitch.targets, [{ response_frames: 30, oscillation: 'none', body: 'chassis', mode: 'pitch' }]);
});

// The modes list follows every answer (a modal tuning carries the solved system's modes), and a simulate
// answer's solved joint is what the page's numbers show; a pick's label is the target it makes.
test('the modes follow the simulate answer, its solved joint answers, and a label names its pick', () => {
  const vehicle = run(['simulate', '--request', '-'], { preset: 'vehicle' });
  const listing = modesOfAnswer(vehicle);
  assert.equal(listing.modes, vehicle.modal_tuning.modes);
  assert.equal(listing.at_s, vehicle.modal_tuning.at_s);
  assert.equal(modesOfAnswer(run(['simulate', '--request', '-'], { preset: 'vehicle_per_spring' })), null);
  const answer = solvedAnswer(vehicle, 'front_suspension');
  assert.equal(answer.joint, 'front_suspension');
  assert.equal(answer.k, vehicle.modal_tuning.groups[0].stiffness);
  assert.equal(answer.requested.mode, 'chassis heave');
  assert.equal(solvedAnswer(vehicle, 'no_such_joint').joint, 'rear_suspension');  // the first solved joint
  // A mode named for one body by its energy, led in amplitude by another: the radio's label names the pick.
  const created = [];
  const node = (name) => {
    const e = { name, attrs: {}, children: [], textContent: '', dataset: {}, className: '' };
    e.setAttribute = (k, v) => { e.attrs[k] = v; };
    e.appendChild = (c) => { e.children.push(c); return c; };
    e.append = (...cs) => { e.children.push(...cs); };
    e.replaceChildren = () => { e.children = []; };
    created.push(e);
    return e;
  };
  const doc = { createElement: node, createElementNS: (_, name) => node(name) };
  const panel = node('div');
  showModes(panel, { at_s: 1, settled: true, modes: [{ name: 'plank_2 heave', discrete: { frequency_hz: 2, damping_ratio: 0.5 },
    components: [{ body: 'plank_1', coordinate: 'y', motion: 'heave', amplitude: 1 }] }] }, 'plank_1.heave', doc);
  const labels = created.filter((e) => e.name === 'label').map((e) => e.children.filter((c) => typeof c === 'string').join(''));
  assert.ok(labels.some((l) => l.startsWith(' plank_1 heave: 2.000 Hz')), labels.join(' | '));
  assert.ok(!labels.some((l) => l.includes('plank_2')), labels.join(' | '));
});
