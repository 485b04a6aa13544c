// planck.js conformance (npm planck 1.4.2): softtune's `planck_js` report run in the real engine. Run by
// ctest as `node --test` with SOFTTUNE_BIN set to the softtune binary.
import assert from 'node:assert/strict';
import { test } from 'node:test';

import { conform, grid, tune } from '../js/conformance.mjs';
import { fitResponse } from '../js/prony.mjs';
import { runPlanck } from './planck_js_run.mjs';

function run(c, report, parameters, dt, steps) {
  return runPlanck({ body: c.body, effectiveMass: c.request.effective_mass, settings: report.settings, parameters,
                     dt, steps, x0: c.body === 'rotating_plank' ? 1e-4 : 0.05 });
}

// The three joints on a point body, the distance joint on the plank (every third case), the velocity
// iterations 8 (the default), 1, 3 and 20.
const joints = ['distance', 'wheel', 'mouse'];
const iterations = [8, 1, 3, 20];
const cases = grid(72, (i) => {
  const body = i % 3 === 1 ? 'rotating_plank' : 'point';
  const settings = { joint: body === 'point' ? joints[(i >> 1) % 3] : 'distance', velocityIterations: iterations[i % 4] };
  return { body, label: `${body} ${JSON.stringify(settings)}`, settings };
}).map((c) => ({ ...c, request: { ...c.request, engine_settings: { planck_js: c.settings } } }));

test('planck.js runs what softtune predicts, and exact runs what was asked', () => {
  const started = Date.now();
  // Doubles: the fit reads the trajectory down to 1e-9 of its swing. A known gap: a refused export (exact
  // mode at zeta 0, d + h k = 0) on the turning plank. planck computes m_gamma = h (d + h k) in doubles, where
  // the sum is a few ulp whose sign and size set the motion (#40 ran at 9.46 Hz, zeta 1.08; #64 could not be
  // fitted), not Box2D 2.4.1's float rounding that the shared model predicts; on a point body it is.
  const runRefused = (c) => c.body !== 'rotating_plank';
  const { failures, table } = conform('planck_js', cases, run, { fitFloor: () => 1e-9, runRefused });
  console.log(table);
  console.log(`  ${((Date.now() - started) / 1000).toFixed(1)} s`);
  assert.deepEqual(failures, []);
});

test('the issue: frequencyHz 10, dampingRatio 0.1 at 60 fps run at 8.25 Hz, 0.48; exact types what gives 10, 0.1', () => {
  const report = tune({ fps: 60, frequency_hz: 10, damping_ratio: 0.1, mode: 'standard', effective_mass: 1 }).engines.planck_js;
  assert.equal(report.parameters['DistanceJointDef.frequencyHz'], 10);
  const measure = (parameters) => fitResponse(runPlanck({ body: 'point', effectiveMass: 1, settings: report.settings,
                                                         parameters, dt: 1 / 60, steps: 600, x0: 0.05 }), 1 / 60, 1e-9);
  const plain = measure(report.parameters), exact = measure(report.exact);
  console.log(`planck_js 10 Hz / 0.1 at 60 fps: typed as asked -> ${plain.frequencyHz.toFixed(3)} Hz / ` +
              `${plain.dampingRatio.toFixed(3)}; exact ${report.exact['DistanceJointDef.frequencyHz'].toFixed(4)} Hz / ` +
              `${report.exact['DistanceJointDef.dampingRatio'].toFixed(4)} -> ${exact.frequencyHz.toFixed(3)} Hz / ${exact.dampingRatio.toFixed(3)}`);
  assert.ok(Math.abs(plain.frequencyHz - 8.25) < 0.05 && Math.abs(plain.dampingRatio - 0.48) < 0.01);
  assert.ok(Math.abs(exact.frequencyHz / 10 - 1) < 0.01 && Math.abs(exact.dampingRatio - 0.1) < 0.02);
});
