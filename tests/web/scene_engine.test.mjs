// web/scene_engine.js: the picked engine goes as `engine` with a scene request, the real codec accepts the
// request so built (`softtune simulate --request -`) and the answer names the engine that ran; no pick leaves
// the request as it was. Run: SOFTTUNE_BIN=build/softtune node --test tests/web/scene_engine.test.mjs
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import {
  DEFAULT_SCENE_ENGINE, sceneEngineLabel, sceneJointValues, sceneValuesText, withSceneEngine,
} from '../../web/scene_engine.js';

const softtune = process.env.SOFTTUNE_BIN ?? 'build/softtune';
const simulate = (request) => JSON.parse(execFileSync(softtune, ['simulate', '--request', '-'], {
  input: JSON.stringify(request), encoding: 'utf8', cwd: new URL('../..', import.meta.url),
}));

test('the picked engine rides on the scene request and the answer names it', () => {
  const request = withSceneEngine({ preset: 'buddhas' }, { engine: DEFAULT_SCENE_ENGINE, fps: '60' });
  assert.deepEqual(request, { preset: 'buddhas', engine: 'box2d_v2_4' });
  const answer = simulate(request);
  assert.equal(answer.engine.name, 'box2d_v2_4');
  assert.match(answer.engine.version, /2\.4/);
  const tuned = answer.joints.filter((j) => j.tuned);
  assert.ok(tuned.length > 0);
  for (const j of tuned) assert.equal(j.parameters.engine, 'box2d_v2_4');
});

test('no pick leaves the request unchanged, and an unknown engine is refused naming engine', () => {
  const bare = { preset: 'buddhas' };
  assert.equal(withSceneEngine(bare, { engine: '' }), bare);
  assert.equal(withSceneEngine(bare, {}), bare);
  assert.throws(() => execFileSync(softtune, ['simulate', '--request', '-'], {
    input: JSON.stringify(withSceneEngine(bare, { engine: 'havok' })), encoding: 'utf8', stdio: 'pipe',
    cwd: new URL('../..', import.meta.url),
  }), (e) => e.status === 2 && JSON.parse(e.stderr).field === 'engine');
});

test('an engine is labelled with the version it runs', () => {
  assert.equal(sceneEngineLabel({ name: 'mujoco', version: 'MuJoCo 2.2.2' }), 'mujoco (MuJoCo 2.2.2)');
  assert.equal(sceneEngineLabel({ name: 'box2d_v2_4' }), 'box2d_v2_4');
});

test("Copy's values are the answer's parameters of the picked joint, in the engine that ran", () => {
  const answer = simulate(withSceneEngine({ preset: 'vehicle_per_spring' }, { engine: 'box2d_v2_4' }));
  const withSpring = answer.joints.filter((j) => j.parameters);
  assert.ok(withSpring.length >= 2);
  const picked = withSpring[1];
  const v = sceneJointValues(answer, picked.id);
  assert.deepEqual(v, { engine: 'box2d_v2_4', joint: picked.id, values: picked.parameters.values });
  assert.equal(sceneJointValues(answer, 'no_such_joint').joint, withSpring[0].id);
  const lines = sceneValuesText(v).split('\n');
  assert.equal(lines.length, Object.keys(picked.parameters.values).length);
  for (const [name, value] of Object.entries(picked.parameters.values)) assert.ok(lines.includes(`${name} = ${value}`));
  assert.equal(sceneJointValues({ joints: [{ id: 'pin', tuned: false }] }, ''), null);
});
