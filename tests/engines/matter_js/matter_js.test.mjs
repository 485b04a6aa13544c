// matter.js conformance (npm matter-js 0.20.0): softtune's `matter_js` report run in the real engine. Run by
// ctest as `node --test` with SOFTTUNE_BIN set to the softtune binary.
import assert from 'node:assert/strict';
import { test } from 'node:test';

import { conform, grid, tune } from '../js/conformance.mjs';
import { fitBestOrder } from '../js/prony_order.mjs';
import { kPlankLeverage, runMatter } from './matter_js_run.mjs';

// A run the model predicts to grow starts at 1e-9 and is read until the stretch passes 1 cm, while the
// geometry stays linear (matter computes in doubles: the growth is a clean recurrence down there); the
// plank starts at 1e-6, where its turn's geometry is linear to 1e-8.
function run(c, report, parameters, dt, steps) {
  const predicted = parameters === report.parameters ? report.predicted : report.exact_predicted;
  const x0 = !predicted.stable ? 1e-9 : c.body === 'rotating_plank' ? 1e-6 : 0.05;
  const x = runMatter({ body: c.body, effectiveMass: c.request.effective_mass, settings: report.settings,
                        parameters, dt, steps, x0 });
  const end = x.findIndex((v) => !(Math.abs(v) <= 1e-2));
  return predicted.stable || end < 0 ? x : x.slice(0, end + 1);
}

// Settings cycle through the defaults (2 constraintIterations, frictionAir 0.01) and the changes a user
// makes: other iteration counts, no air friction, more of it; every third case the plank, whose request
// names its anchorLeverage.
const iterations = [2, 1, 2, 4, 8];
const cases = grid(72, (i) => {
  const settings = { constraintIterations: iterations[i % iterations.length] };
  if (i % 4 === 1) settings.frictionAir = 0;
  if (i % 7 === 3) settings.frictionAir = 0.05;
  const body = i % 3 === 1 ? 'rotating_plank' : 'point';
  if (body === 'rotating_plank') settings.anchorLeverage = kPlankLeverage;
  return { body, label: `${body} ${JSON.stringify(settings)}`, settings };
}).map((c) => ({ ...c, request: { ...c.request, engine_settings: { matter_js: c.settings } } }));

test('matter.js runs what softtune predicts, and exact runs what was asked', () => {
  const started = Date.now();
  // The point's motion is third order (stretch, previous stretch, carried impulse), the plank's up to five
  // (its turn adds two, less the free motion that leaves the stretch at zero): each run is fitted with the
  // order up to that which reads it best. Doubles: the fit reads the trajectory down to 1e-10 of its swing.
  const fit = (c) => (x, dt, floor) => fitBestOrder(x, dt, c.body === 'point' ? 3 : 5, floor);
  const { failures, table } = conform('matter_js', cases, run, { fit, fitFloor: () => 1e-10 });
  console.log(table);
  console.log(`  ${((Date.now() - started) / 1000).toFixed(1)} s`);
  assert.deepEqual(failures, []);
});

// What a designer gets from the continuous formulas (stiffness = k h^2 / m, damping = c h / m, the plain
// export) against exact, in the real engine: the note table.
test('the designer table: the continuous formulas against exact, at 60 fps and the defaults', () => {
  const rows = [];
  for (const [hz, zeta] of [[1, 0.1], [2, 0.1], [2, 0.5], [5, 0.3], [10, 0.5], [10, 1]]) {
    const request = { fps: 60, frequency_hz: hz, damping_ratio: zeta, mode: 'standard', effective_mass: 1 };
    const report = tune(request).engines.matter_js;
    const measure = (parameters) => {
      const x = runMatter({ body: 'point', effectiveMass: 1, settings: report.settings, parameters, dt: 1 / 60,
                            steps: 600, x0: 0.05 });
      if (x.some((v) => !(Math.abs(v) <= 0.5))) return 'blows up';
      const fit = fitBestOrder(x, 1 / 60, 3, 1e-10);
      return fit ? `${fit.frequencyHz.toFixed(3)} Hz / ${fit.dampingRatio.toFixed(3)}` : 'no fit';
    };
    rows.push(`  ${hz} Hz / ${zeta}: typed stiffness ${report.parameters['Constraint.stiffness'].toPrecision(3)} ` +
              `damping ${report.parameters['Constraint.damping'].toPrecision(3)} -> ${measure(report.parameters)}; ` +
              (report.exact ? `exact ${report.exact['Constraint.stiffness'].toPrecision(4)} / ` +
                              `${report.exact['Constraint.damping'].toPrecision(4)} -> ${measure(report.exact)}`
                            : 'exact null'));
    if (hz === 2 && zeta === 0.1) {
      // The continuous formulas miss by far more than the tolerance: the fractions act 2 passes x 2 iterations.
      const x = runMatter({ body: 'point', effectiveMass: 1, settings: report.settings, parameters: report.parameters,
                            dt: 1 / 60, steps: 600, x0: 0.05 });
      assert.ok(fitBestOrder(x, 1 / 60, 3, 1e-10).frequencyHz / hz - 1 > 0.5);
    }
  }
  console.log(['matter_js, 60 fps, constraintIterations 2, frictionAir 0.01 (asked: typed -> measured):', ...rows].join('\n'));
});
