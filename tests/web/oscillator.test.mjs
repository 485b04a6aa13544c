// web/oscillator.js against the physics: the exact motion of a real answer solves the ODE, the replayed step maps of a real
// `softtune tune` response obey the talk's identity (soft constraint == implicit Euler) and exact mode's
// discrete poles exp(s h), and a blow-up never reaches a plot as NaN.
// Run: SOFTTUNE_BIN=build/softtune node --test tests/web/oscillator.test.mjs
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { replay, responseSeries, METHODS, MAX_SAMPLES } from '../../web/oscillator.js';

const softtune = process.env.SOFTTUNE_BIN ?? 'build/softtune';
const tune = (...args) => JSON.parse(execFileSync(softtune, ['tune', ...args], { encoding: 'utf8' }));

test('the exact motion of a tune answer solves m x\'\' + c x\' + k x = 0 from x0 = 1, v0 = 0 in every damping case', () => {
  // The page keeps no copy of the closed form: it replays the answer's one-step flow and draws its samples.
  for (const osc of ['--oscillation free', '--damping-ratio 0.2', '--oscillation some', '--oscillation none', '--damping-ratio 2.5']) {
    const r = tune('--frames', '20', ...osc.split(' '), '--mass', '1', '--fps', '600');
    const s = responseSeries(r);
    const omega = r.omega, zeta = r.damping_ratio, h = r.h;
    assert.ok(Math.abs(s.exact[0] - 1) < 1e-15, `x(0) at ${osc}`);
    // Three periods of the request, as the answer says.
    assert.ok(Math.abs(r.exact_motion.duration_s - 3 / r.requested.frequency_hz) < 1e-12);
    // The step-grid motion: central differences of x satisfy the ODE to O(h^2).
    for (let n = 1; n + 1 < s.exact.length; n += 7) {
      const acc = (s.exact[n + 1] - 2 * s.exact[n] + s.exact[n - 1]) / (h * h);
      const vel = (s.exact[n + 1] - s.exact[n - 1]) / (2 * h);
      const residual = acc + 2 * zeta * omega * vel + omega * omega * s.exact[n];
      assert.ok(Math.abs(residual) < 2e-3 * omega * omega, `residual ${residual} at ${osc}, step ${n}`);
    }
  }
  // Undamped: a cosine on the fine grid, back at 1 after the three periods.
  const r = tune('--frames', '12', '--oscillation', 'free', '--mass', '1');
  r.exact_motion.smooth.x.forEach((x, i) => assert.ok(Math.abs(x - Math.cos(r.omega * i * r.exact_motion.smooth.dt_s)) < 1e-12, `i = ${i}`));
});

test('replay iterates the step map: a rotation by theta gives cos(n theta)', () => {
  const th = 0.3;
  const xs = replay([[Math.cos(th), Math.sin(th)], [-Math.sin(th), Math.cos(th)]], 1, 0, 50);
  xs.forEach((x, n) => assert.ok(Math.abs(x - Math.cos(n * th)) < 1e-12, `n = ${n}`));
  const every3 = replay([[Math.cos(th), Math.sin(th)], [-Math.sin(th), Math.cos(th)]], 1, 0, 20, 3);
  every3.forEach((x, n) => assert.ok(Math.abs(x - Math.cos(3 * n * th)) < 1e-12, `stride 3, n = ${n}`));
});

test('a long run at a small step is replayed in full and drawn in at most MAX_SAMPLES points', () => {
  // 120 frames at 60 fps basis (0.5 Hz), 1000 substeps at 1000 fps: 6 s of h = 1 us, six million steps.
  const r = tune('--frames', '120', '--oscillation', 'some', '--mass', '1', '--fps', '1000', '--substeps', '1000');
  const s = responseSeries(r);
  assert.ok(s.t.length <= MAX_SAMPLES + 1 && s.stride > 1);
  assert.ok(Math.abs(s.t.at(-1) - 6) < s.stride * r.h + 1e-12, `covers 3 periods: ${s.t.at(-1)} s`);
  // At omega h = 3e-6 every method, first order or not, stays within 1e-4 of the closed form all along.
  for (const name of METHODS) {
    const worst = Math.max(...s.error[name].filter((e) => e !== null));
    assert.ok(worst < 1e-4, `${name}: worst error ${worst}`);
  }
});

test('soft constraint replay equals implicit Euler stepped from k, c (Catto GDC 2011) to round-off', () => {
  const r = tune('--frames', '9', '--oscillation', 'some', '--mass', '3', '--fps', '60', '--substeps', '2');
  const s = responseSeries(r);
  const m = r.effective_mass, k = r.standard.k, c = r.standard.c, h = r.h;
  let x = 1, v = 0;
  for (let n = 0; n < s.t.length; ++n) {
    assert.ok(Math.abs(s.methods.soft[n] - x) < 1e-12, `step ${n}: ${s.methods.soft[n]} vs ${x}`);
    v = (m * v - h * k * x) / (m + h * c + h * h * k);
    x += h * v;
  }
});

test('exact mode replay has the continuous poles: x[n+2] = S x[n+1] - P x[n]', () => {
  const r = tune('--frames', '6', '--oscillation', 'some', '--mass', '2', '--fps', '60', '--mode', 'exact');
  const s = responseSeries(r);
  const h = r.h, w = r.omega, z = r.damping_ratio;
  const P = Math.exp(-2 * z * w * h);
  const S = 2 * Math.exp(-z * w * h) * Math.cos(w * Math.sqrt(1 - z * z) * h);
  const xs = s.methods.soft_exact;
  for (let n = 0; n + 2 < xs.length; ++n) {
    assert.ok(Math.abs(xs[n + 2] - (S * xs[n + 1] - P * xs[n])) < 1e-12, `n = ${n}`);
  }
  // The standard soft constraint does not: it is slower and more damped (docs/math.md).
  const std = s.methods.soft;
  const worst = Math.max(...std.slice(0, -2).map((x, n) => Math.abs(std[n + 2] - (S * std[n + 1] - P * x))));
  assert.ok(worst > 1e-3, `standard mode should miss the continuous poles, worst ${worst}`);
});

test('a blow-up ends in nulls, never NaN or infinity', () => {
  const xs = replay([[10, 0], [0, 10]], 1, 0, 20);
  assert.deepEqual(xs.slice(0, 7), [1, 10, 100, 1e3, 1e4, 1e5, 1e6]);
  assert.ok(xs.slice(7).every((x) => x === null));
  assert.ok(replay([[NaN, 0], [0, 1]], 1, 0, 3).slice(1).every((x) => x === null));
});

test('past the stability limit the replay grows while the exact motion stays bounded', () => {
  // 2 frames per period at 60 fps undamped: omega h = pi, past explicit and semi-implicit Euler's limits.
  const r = tune('--frames', '2', '--oscillation', 'free', '--mass', '1', '--fps', '60');
  const s = responseSeries(r);
  for (const name of METHODS) assert.ok(s.methods[name], `${name} replayed`);
  // Two steps per period: the exact motion is drawn on its own fine grid over the same time span.
  assert.ok(s.smooth.t.length > 25 * s.t.length && Math.abs(s.smooth.t.at(-1) - s.t.at(-1)) < 1e-12);
  s.smooth.t.forEach((t, i) => assert.ok(Math.abs(s.smooth.x[i] - Math.cos(r.omega * t)) < 1e-12, `smooth ${i}`));
  const ee = s.methods.explicit_euler.filter((x) => x !== null);
  assert.ok(Math.abs(ee.at(-1)) > 50, `explicit Euler grows: ${ee.at(-1)}`);
  assert.ok(s.exact.every((x) => Math.abs(x) <= 1 + 1e-12));
  for (const series of [s.exact, ...Object.values(s.methods), ...Object.values(s.error)]) {
    for (const x of series) assert.ok(x === null || Number.isFinite(x));
  }
});
