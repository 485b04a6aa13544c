// The Jolt scene module (engines/jolt/jolt_scene.mjs) in node: ms per vehicle run (6 s at 60 fps, k =
// 24842.07 N/m, c = 914.753 N s/m on both suspensions: build, 360 frames, the states read each frame), without
// and with the contacts read each frame, against one baseline in the same run: the same world stepped with
// nothing read back (world.step: the motors, JoltInterface::Step and the module's own state cache).
// With --softtune BIN, Box2D 2.4's run of the same preset in the same run as well: `softtune simulate --preset
// vehicle` (its modal solve finds these k, c), less `softtune --version` (the process start): an upper bound on
// Box2D's run, which also decodes, tunes, probes and fits.
// By hand: node bench/jolt_scene_bench.mjs [--runs 20] [--softtune build/softtune]
import { spawnSync } from 'node:child_process';

import * as jolt from '../engines/jolt/jolt_scene.mjs';
import { frameCount, kPresetsDir, readPreset, sceneRequest } from '../tests/engines/jolt/scene_request.mjs';

const runsAt = process.argv.indexOf('--runs');
const runs = runsAt > 0 ? Number(process.argv[runsAt + 1]) : 20;
const binAt = process.argv.indexOf('--softtune');
const softtune = binAt > 0 ? process.argv[binAt + 1] : null;

await jolt.init();
const scene = readPreset('vehicle');
const request = sceneRequest(scene, { spring: () => ({ stiffness: 24842.07, damping: 914.753 }) });
const frames = frameCount(scene);

function timed(read) {
  const started = performance.now();
  const world = jolt.build(request);
  for (let f = 0; f < frames; ++f) {
    world.step(f);
    read(world);
  }
  world.destroy();
  return performance.now() - started;
}

function spawned(args) {
  const started = performance.now();
  const out = spawnSync(softtune, args, { encoding: 'utf8', env: { ...process.env, SOFTTUNE_PRESETS: kPresetsDir } });
  if (out.status !== 0) throw new Error(`${softtune} ${args.join(' ')}: ${out.stderr}`);
  return performance.now() - started;
}

const cases = {
  'world.step only (baseline)': () => {},
  'step + bodies()': (w) => w.bodies(),
  'step + bodies() + contacts()': (w) => { w.bodies(); w.contacts(); },
};
for (const read of Object.values(cases)) for (let i = 0; i < 3; ++i) timed(read);  // JIT warm-up
const median = (xs) => xs.sort((a, b) => a - b)[Math.floor(xs.length / 2)];
const results = {};
for (let r = 0; r < runs; ++r) {
  for (const [name, read] of Object.entries(cases)) (results[name] ??= []).push(timed(read));
}
if (softtune) {
  const simulate = [], start = [];
  for (let r = 0; r < runs; ++r) {
    simulate.push(spawned(['simulate', '--preset', 'vehicle']));
    start.push(spawned(['--version']));
  }
  results['Box2D 2.4: softtune simulate less its start'] = [median(simulate) - median(start)];
}
const base = median(results['world.step only (baseline)']);
for (const [name, times] of Object.entries(results)) {
  const m = median(times);
  console.log(`${name.padEnd(30)} ${m.toFixed(1).padStart(7)} ms per vehicle run (median of ${runs}), ` +
              `${(m / base).toFixed(2)}x the baseline`);
}
