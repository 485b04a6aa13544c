// cannon-es conformance (npm cannon-es 0.20.0): softtune's `cannon_es` report run in the real engine. Run by
// ctest as `node --test` with SOFTTUNE_BIN set to the softtune binary.
import assert from 'node:assert/strict';
import { test } from 'node:test';

import { conform, grid, tune } from '../js/conformance.mjs';
import { fitResponse } from '../js/prony.mjs';
import { runCannon } from './cannon_es_run.mjs';

// A run the model predicts to grow starts small and is read until the stretch passes 1 cm, while the geometry
// stays linear (cannon-es computes in doubles); the plank starts at 1e-4, where its turn is linear to 1e-8.
function run(c, report, parameters, dt, steps) {
  const predicted = parameters === report.parameters ? report.predicted : report.exact_predicted;
  const x0 = !predicted.stable ? 1e-6 : c.body === 'rotating_plank' ? 1e-4 : 0.05;
  const x = runCannon({ body: c.body, effectiveMass: c.request.effective_mass, settings: report.settings,
                        parameters, dt, steps, x0 });
  const end = x.findIndex((v) => !(Math.abs(v) <= 1e-2));
  return predicted.stable || end < 0 ? x : x.slice(0, end + 1);
}

// Settings cycle through the defaults (the Spring, linearDamping 0.01, SPOOK baked at the world's step, 10
// iterations) and the changes a user makes: the DistanceConstraint, no damping, heavy damping, SPOOK baked at
// the Equation constructor's 1 / 60 whatever the step, 1 or 3 solver iterations; every third case the
// Spring on the plank.
const cases = grid(72, (i) => {
  const body = i % 3 === 1 ? 'rotating_plank' : 'point';
  const settings = { joint: body === 'point' && i % 2 === 0 ? 'distance' : 'spring', iterations: [10, 1, 3][i % 3] };
  if (i % 4 === 1) settings.linearDamping = 0;
  if (i % 7 === 3) settings.linearDamping = 0.3;
  if (i % 5 === 2) settings.spookTimeStep = 1 / 60;
  return { body, label: `${body} ${JSON.stringify(settings)}`, settings };
}).map((c) => ({ ...c, request: { ...c.request, engine_settings: { cannon_es: c.settings } } }));

test('cannon-es runs what softtune predicts, and exact runs what was asked', () => {
  const started = Date.now();
  const { failures, table } = conform('cannon_es', cases, run, { fitFloor: () => 1e-9 });
  console.log(table);
  console.log(`  ${((Date.now() - started) / 1000).toFixed(1)} s`);
  assert.deepEqual(failures, []);
});

// What a designer gets from the textbook values (the plain export: Spring stiffness k = m omega^2, damping
// c = 2 m zeta omega; SPOOK stiffness k, relaxation c / (k h)) against exact, in the real engine.
test('the designer table: the textbook values against exact, at 60 fps and the defaults', () => {
  const rows = [];
  const measure = (report, parameters, dt) => {
    const x = runCannon({ body: 'point', effectiveMass: 1, settings: report.settings, parameters, dt, steps: 600, x0: 0.05 });
    if (x.some((v) => !(Math.abs(v) <= 0.5))) return 'blows up';
    const fit = fitResponse(x, dt, 1e-9);
    return fit ? `${fit.frequencyHz.toFixed(3)} Hz / ${fit.dampingRatio.toFixed(3)}` : 'no fit';
  };
  for (const joint of ['spring', 'distance']) {
    for (const [hz, zeta] of [[2, 0], [2, 0.1], [5, 0.3], [10, 0.5], [10, 1]]) {
      const request = { fps: 60, frequency_hz: hz, damping_ratio: zeta, mode: 'standard', effective_mass: 1,
                        engine_settings: { cannon_es: { joint } } };
      const report = tune(request).engines.cannon_es;
      const [p0, p1] = Object.keys(report.parameters).sort().reverse();  // stiffness, then damping or relaxation
      rows.push(`  ${joint} ${hz} Hz / ${zeta}: typed ${report.parameters[p0].toPrecision(4)} / ${report.parameters[p1].toPrecision(3)} ` +
                `-> ${measure(report, report.parameters, 1 / 60)}; ` +
                (report.exact ? `exact ${report.exact[p0].toPrecision(5)} / ${report.exact[p1].toPrecision(4)} -> ` +
                                `${measure(report, report.exact, 1 / 60)}` : 'exact null'));
    }
  }
  // SPOOK baked with 1 / 60 and stepped at 120 fps: the frequency moves (the issue measured 1.98 -> 2.73 Hz).
  const baked = tune({ fps: 60, frequency_hz: 2, damping_ratio: 0.1, mode: 'standard', effective_mass: 1,
                       engine_settings: { cannon_es: { joint: 'distance' } } }).engines.cannon_es;
  const at60 = fitResponse(runCannon({ body: 'point', effectiveMass: 1, settings: { ...baked.settings, spookTimeStep: 1 / 60 },
                                       parameters: baked.parameters, dt: 1 / 60, steps: 600, x0: 0.05 }), 1 / 60, 1e-9);
  const at120 = fitResponse(runCannon({ body: 'point', effectiveMass: 1, settings: { ...baked.settings, spookTimeStep: 1 / 60 },
                                        parameters: baked.parameters, dt: 1 / 120, steps: 1200, x0: 0.05 }), 1 / 120, 1e-9);
  rows.push(`  distance 2 Hz / 0.1 typed at 60 fps, baked 1/60, stepped at 120 fps: ${at60.frequencyHz.toFixed(3)} Hz -> ` +
            `${at120.frequencyHz.toFixed(3)} Hz`);
  assert.ok(at120.frequencyHz / at60.frequencyHz > 1.3);
  // A typed damping 0 becomes 1 (damping || 1): the 2 Hz / 0 Spring damps.
  const undamped = tune({ fps: 60, frequency_hz: 2, damping_ratio: 0, mode: 'standard', effective_mass: 1,
                          engine_settings: { cannon_es: { linearDamping: 0 } } }).engines.cannon_es;
  const fit0 = fitResponse(runCannon({ body: 'point', effectiveMass: 1, settings: undamped.settings,
                                       parameters: undamped.parameters, dt: 1 / 60, steps: 600, x0: 0.05 }), 1 / 60, 1e-9);
  assert.equal(undamped.parameters['Spring.damping'], 0);
  assert.ok(fit0.dampingRatio > 0.03, `damping 0 ran at zeta ${fit0.dampingRatio}`);
  console.log(['cannon_es, 60 fps, linearDamping 0.01 (asked: typed -> measured):', ...rows].join('\n'));
});
