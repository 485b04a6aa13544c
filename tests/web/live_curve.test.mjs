// web/live_curve.js: the curve drawn at the slider, before any answer, is the server's own step: its step
// matrix equals the tune answer's `stability[soft|soft_exact].step_matrix` for the same controls (the real
// `softtune tune`), its poles are the continuous motion's in exact mode, e^(hA) meets the analytic flow,
// and the plain words (bounce, settle) match the damped oscillator's known overshoot.
// Run: SOFTTUNE_BIN=build/softtune node --test tests/web/live_curve.test.mjs
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { askedResponse, expm2, feel, feelWords, liveCurve, liveStepMatrix } from '../../web/live_curve.js';
import { responseSeries } from '../../web/oscillator.js';
import { tuneRequest } from '../../web/state.js';

const softtune = process.env.SOFTTUNE_BIN ?? 'build/softtune';
const tune = (request) => JSON.parse(execFileSync(softtune, ['tune', '--request', '-'], { input: JSON.stringify(request), encoding: 'utf8' }));
const WORDS = { free: 0, some: 0.5, none: 1 };
const BASE = { frames: '12', basis: '60', osc: 'some', zeta: '0.5', fps: '60', substeps: '1', mode: 'standard', body: 'mass', mass: '1' };

const close = (a, b, tol, what) => assert.ok(Math.abs(a - b) <= tol * Math.max(1, Math.abs(b)), `${what}: ${a} against ${b}`);

test('the step at the slider is the tune answer\'s step, standard and exact, over the designer\'s range', () => {
  const cases = [
    {}, { frames: '4' }, { frames: '120' }, { osc: 'free', zeta: '0' }, { osc: 'none', zeta: '1' }, { osc: '', zeta: '1.7' },
    { osc: '', zeta: '0.05', fps: '30' }, { substeps: '4', frames: '3' }, { basis: '30', fps: '144', mass: '7' },
  ];
  for (const c of cases) {
    for (const mode of ['standard', 'exact']) {
      const state = { ...BASE, ...c, mode };
      const answer = tune(tuneRequest(state));
      const server = answer.stability[mode === 'exact' ? 'soft_exact' : 'soft'].step_matrix;
      const ask = askedResponse(state, WORDS);
      close(ask.h, answer.h, 1e-15, 'h');
      const mine = liveStepMatrix(ask);
      for (let i = 0; i < 2; ++i) for (let j = 0; j < 2; ++j) close(mine[i][j], server[i][j], 1e-9, `${JSON.stringify(c)} ${mode} M[${i}][${j}]`);
      // The whole curve drawn at the slider is the one the answer's replay then draws.
      const curve = liveCurve(ask);
      const replayed = responseSeries(answer).methods[mode === 'exact' ? 'soft_exact' : 'soft'];
      const stride = Math.round((curve.t[1] - curve.t[0]) / ask.h);
      for (let n = 0; n < curve.x.length; ++n) {
        const m = (n * stride) / responseSeries(answer).stride;
        if (!Number.isInteger(m) || m >= replayed.length) continue;
        close(curve.x[n], replayed[m], 1e-9, `${JSON.stringify(c)} ${mode} x at step ${n * stride}`);
      }
    }
  }
});

test('e^(hA) is the damped oscillator\'s flow; the exact step has its poles', () => {
  // Underdamped, x0 = 1, v0 = 0: x(t) = e^(-zeta w t) (cos wd t + zeta w / wd sin wd t).
  const w = 2 * Math.PI * 5, zeta = 0.3, h = 1 / 60, wd = w * Math.sqrt(1 - zeta * zeta);
  const e = expm2([[0, h], [-w * w * h, -2 * zeta * w * h]]);
  close(e[0][0], Math.exp(-zeta * w * h) * (Math.cos(wd * h) + (zeta * w / wd) * Math.sin(wd * h)), 1e-13, 'x(h)');
  close(e[0][1], Math.exp(-zeta * w * h) * Math.sin(wd * h) / wd, 1e-13, 'x(h) from v0 = 1');
  const m = liveStepMatrix({ omega: w, zeta, h, mode: 'exact' });
  close(m[0][0] + m[1][1], 2 * Math.exp(-zeta * w * h) * Math.cos(wd * h), 1e-12, 'trace = 2 e^(-zeta w h) cos(wd h)');
  close(m[0][0] * m[1][1] - m[0][1] * m[1][0], Math.exp(-2 * zeta * w * h), 1e-12, 'det = e^(-2 zeta w h)');
  // A large step (w h = 20): scaling and squaring keeps it exact; critical damping: x(h) = e^(-w h)(1 + w h).
  const big = expm2([[0, 2], [-100 * 2, -2 * 10 * 2]]);
  close(big[0][0], Math.exp(-20) * 21, 1e-9, 'critically damped x(h) at w h = 20');
});

test('the words: a damped oscillator bounces e^(-pi zeta / sqrt(1 - zeta^2)) of its start, and settles', () => {
  const ask = askedResponse({ ...BASE, mode: 'exact', fps: '600', basis: '600', frames: '120' }, WORDS);  // 5 Hz, fine steps
  const f = feel(liveCurve(ask), 60);
  const zeta = 0.5;
  close(f.bouncePercent, 100 * Math.exp(-Math.PI * zeta / Math.sqrt(1 - zeta * zeta)), 5e-3, 'overshoot %');
  // The envelope e^(-zeta w t) falls under 2 % by t = ln(50) / (zeta w): it settles no later (in 60 fps frames).
  assert.ok(f.settleFrames !== null && f.settleFrames <= Math.ceil(60 * Math.log(50) / (zeta * 2 * Math.PI * 5)), `${f.settleFrames}`);
  assert.equal(feelWords(f), `bounces 16 %, settles in ${f.settleFrames} frames`);
  const none = feel(liveCurve(askedResponse({ ...BASE, osc: 'none', zeta: '1' }, WORDS)), 60);
  assert.ok(none.bouncePercent < 0.5, `${none.bouncePercent}`);
  assert.match(feelWords(none), /^no bounce, settles in \d+ frames$/);
  // Free oscillation: exact mode keeps it swinging; standard (implicit Euler) damps it by itself, as the
  // discrete analysis says (its poles inside the unit circle), so even "free" settles there.
  assert.match(feelWords(feel(liveCurve(askedResponse({ ...BASE, osc: 'free', zeta: '0', mode: 'exact' }, WORDS)), 60)), /still moving/);
  const damped = feel(liveCurve(askedResponse({ ...BASE, osc: 'free', zeta: '0' }, WORDS)), 60);
  assert.ok(damped.bouncePercent < 100 && damped.settleFrames !== null, JSON.stringify(damped));
});

test('a field the page refuses draws no curve', () => {
  for (const c of [{ fps: '' }, { frames: '' }, { substeps: '0' }, { basis: 'x' }, { osc: '', zeta: '' }]) {
    assert.equal(askedResponse({ ...BASE, ...c }, WORDS), null, JSON.stringify(c));
  }
});
